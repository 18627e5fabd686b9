// Seakeeping against published numbers:
//   * the heaving semicircle of Ursell (1949) -- sectional added mass and
//     radiated wave amplitude -- and Vugts' (1968) experiments on it
//     (tests/data/seakeeping/ursell1949_semicircle_heave.csv);
//   * Journee's (1992) Wigley III / IV tables: forced-heave coefficients at
//     speed, wave loads on the restrained hull, heave and pitch RAOs
//     (tests/data/seakeeping/journee1992_wigley_tables.csv).
// Each data file states where its numbers come from.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "seakeeping/lewis_section.hpp"
#include "seakeeping/seakeeping.hpp"
#include "seakeeping_hulls.hpp"
#include "test_support.hpp"

namespace towdb::seakeeping {
namespace {

std::vector<std::vector<std::string>> read_csv(const std::string& name) {
  return test::read_csv_rows(test::source_dir() / "tests/data/seakeeping" / name);
}

// Ursell's expressions evaluated with 6 multipoles and read from vertices of
// the published curve (reading error < 1e-4): the verification issue asks
// for 3 %. Measured here: added mass within 0.03 %, wave amplitude ratio
// within 0.2 % up to omega sqrt(a/g) = 1.5 and 0.9 % at 2.0 (where 6
// multipoles on 10 angles are least accurate).
constexpr double kUrsellRelTol = 0.03;
// Vugts' measured wave amplitudes scatter by up to 10 % between neighbouring
// frequencies (0.466 at 0.625 and 0.480 at 0.618 lie on either side of the
// curve); 15 % on each point. Measured here: -1 % to +12.5 %.
constexpr double kVugtsRelTol = 0.15;

// EVIDENCE-OF: EQ-SECTION-4
// EVIDENCE-OF: EQ-SECTION-6
// EVIDENCE-OF: EQ-SECTION-7
TEST(SeakeepingPublished, SemicircleHeaveMatchesUrsell1949AndVugts1968) {
  const double a = 1.0;  // radius [m]
  const double rho = kRhoSeawater_kg_m3;
  int ursell = 0, vugts = 0;
  for (const auto& row : read_csv("ursell1949_semicircle_heave.csv")) {
    ASSERT_EQ(row.size(), 5u);
    if (row[4] != "1") continue;
    const double omega_nd = std::stod(row[1]);
    const double expected = std::stod(row[3]);
    const double w = omega_nd * std::sqrt(kGravity_m_s2 / a);
    // The semicircle is the Lewis form a1 = a3 = 0: B = 2a, T = a, sigma = pi/4.
    const SectionSolution s = solve_lewis_section(2.0 * a, a, kPi / 4.0, w);
    double value = 0.0;
    if (row[2] == "added_mass_coefficient") {
      value = s.coefficients.a33 / (rho * kPi * a * a / 2.0);
    } else if (row[2] == "wave_amplitude_ratio") {
      // Wave per unit heave velocity times omega: per unit heave amplitude.
      value = w * std::abs(s.wave_per_velocity_heave);
    } else {
      ADD_FAILURE() << "unknown quantity " << row[2];
    }
    const double tol = row[0] == "ursell" ? kUrsellRelTol : kVugtsRelTol;
    EXPECT_REL_CLOSE(value, expected, tol) << row[0] << " " << row[2] << " at omega sqrt(a/g) = " << omega_nd;
    (row[0] == "ursell" ? ursell : vugts) += 1;
  }
  EXPECT_EQ(ursell, 16);
  EXPECT_EQ(vugts, 12);
}

struct WigleyRow {
  std::string table, hull, quantity;
  double froude = 0.0, x = 0.0, value = 0.0;
};

std::vector<WigleyRow> wigley_rows() {
  std::vector<WigleyRow> rows;
  for (const auto& c : read_csv("journee1992_wigley_tables.csv")) {
    EXPECT_EQ(c.size(), 6u);
    rows.push_back({c[0], c[1], c[4], std::stod(c[2]), std::stod(c[3]), std::stod(c[5])});
  }
  return rows;
}

model::Vessel wigley(const std::string& hull) {
  test::WigleyParticulars p;
  p.beam_m = hull == "IV" ? 0.6 : 0.3;
  p.alpha = 0.0;  // III and IV
  return test::wigley_vessel(p);
}

double head_wave_omega(double lambda_over_l, double length_m) {
  return std::sqrt(kGravity_m_s2 * 2.0 * kPi / (lambda_over_l * length_m));
}

// Strip theory against tank measurements on a slender hull. Forced heave at
// Fn 0.3: measured here A33 14-17 % below the tank, B33 3-14 % above (the
// Lewis sections of the parabolic Wigley III frames, and no 3-D or speed
// effect on a33 in STF without a transom); Journee (MARIND 2001,
// "Discrepancies in hydrodynamic coefficients of Wigley hull forms") reports
// discrepancies of this kind for his own strip codes. 20 %.
constexpr double kWigleyCoefficientRelTol = 0.20;
// Wave loads on the restrained hull at Fn 0.3: measured here -2 % to +10 %.
constexpr double kWigleyWaveLoadRelTol = 0.15;
// Heave RAO at Fn 0, 0.2, 0.3: measured here -4 % to +10 %.
constexpr double kWigleyHeaveRaoRelTol = 0.15;
// Pitch at zero speed: measured here 8-24 % low (worst: Wigley IV at
// lambda/L = 1.5); strip theory is known to under-predict the Wigley pitch
// (pitch added inertia low, Journee 2001), 25 %.
constexpr double kWigleyPitchRaoRelTol = 0.25;

// EVIDENCE-OF: EQ-STRIP-3
// EVIDENCE-OF: EQ-STRIP-4
// EVIDENCE-OF: EQ-STRIP-9
TEST(SeakeepingPublished, WigleyHullsMatchJournee1992Tables) {
  const std::vector<WigleyRow> rows = wigley_rows();
  ASSERT_EQ(rows.size(), 37u);
  std::map<std::string, model::Vessel> vessels{{"III", wigley("III")}, {"IV", wigley("IV")}};
  int checked = 0;
  for (const WigleyRow& r : rows) {
    const model::Vessel& v = vessels.at(r.hull);
    const double l = v.hull.length_pp_m;
    const double u = r.froude * std::sqrt(kGravity_m_s2 * l);
    const double rho_volume = v.hull.displacement_kg;
    if (r.table == "2-III") {
      // Forced heave at encounter frequency w_e: beam seas keep w_e = w.
      const double w = r.x / std::sqrt(l / kGravity_m_s2);
      const VesselResponse resp = compute_response(v, u, kPi / 2.0, {w}).front();
      const double value = r.quantity == "added_mass"
                               ? resp.added_mass(kHeave, kHeave) / rho_volume
                               : resp.damping(kHeave, kHeave) / rho_volume * std::sqrt(l / kGravity_m_s2);
      EXPECT_REL_CLOSE(value, r.value, kWigleyCoefficientRelTol) << r.table << " " << r.quantity << " " << r.x;
    } else if (r.table == "6-III") {
      const double w = head_wave_omega(r.x, l);
      const VesselResponse resp = compute_response(v, u, kPi, {w}).front();
      const double value =
          r.quantity == "heave_force"
              ? std::abs(resp.exciting_force_per_m(kHeave)) / resp.restoring(kHeave, kHeave)
              : std::abs(resp.exciting_force_per_m(kPitch)) / (resp.wavenumber_rad_m * resp.restoring(kPitch, kPitch));
      EXPECT_REL_CLOSE(value, r.value, kWigleyWaveLoadRelTol) << r.table << " " << r.quantity << " " << r.x;
    } else {
      const double w = head_wave_omega(r.x, l);
      const VesselResponse resp = compute_response(v, u, kPi, {w}).front();
      if (r.quantity == "heave_rao") {
        EXPECT_REL_CLOSE(std::abs(resp.rao(kHeave)), r.value, kWigleyHeaveRaoRelTol)
            << r.table << " Fn " << r.froude << " lambda/L " << r.x;
      } else {
        EXPECT_REL_CLOSE(std::abs(resp.rao(kPitch)) * l / (2.0 * kPi), r.value, kWigleyPitchRaoRelTol)
            << r.table << " lambda/L " << r.x;
      }
    }
    ++checked;
  }
  EXPECT_EQ(checked, 37);
}

}  // namespace
}  // namespace towdb::seakeeping
