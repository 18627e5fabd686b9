// Strip theory against Journee's (1992) Wigley hull experiments in head waves
// (reference data: tests/data/seakeeping/journee1992_wigley.csv).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "seakeeping/seakeeping.hpp"
#include "seakeeping_hulls.hpp"
#include "test_support.hpp"

namespace towdb::seakeeping {
namespace {

struct Row {
  std::string hull;
  double froude = 0.0;
  std::string wavelength;
  std::string quantity;
  double measured = 0.0;
  bool asserted = false;
};

std::vector<Row> read_rows() {
  // Columns: hull, froude, wavelength, quantity, measured, asserted.
  std::vector<Row> rows;
  for (const auto& f : test::read_csv_rows(test::source_dir() / "tests/data/seakeeping/journee1992_wigley.csv")) {
    rows.push_back({f.at(0), std::stod(f.at(1)), f.at(2), f.at(3), std::stod(f.at(4)), f.at(5) == "1"});
  }
  return rows;
}

test::WigleyParticulars particulars(const std::string& hull) {
  test::WigleyParticulars p;
  p.beam_m = (hull == "II" || hull == "IV") ? 0.6 : 0.3;
  p.alpha = (hull == "I" || hull == "II") ? 1.0 : 0.0;
  return p;
}

double omega_for(double wavelength_over_length, double length_m) {
  return std::sqrt(kGravity_m_s2 * 2.0 * kPi / (wavelength_over_length * length_m));
}

// Heave near resonance: strip theory vs the tank; Journee's own strip codes
// and other STF implementations agree with this point within a few percent
// (measured agreement here: 2.46 vs 2.52, -2.4%); 10% allows for the Lewis
// approximation of the sections and the unknown KG.
constexpr double kHeaveRaoRelTol = 0.10;
// Gerritsma-Beukelman added resistance at Fn 0.2 on the slender hulls I and
// III (measured here -12% and -16%); radiated-energy methods are usually
// quoted within 20-30% of the tank near the peak.
constexpr double kAddedResistancePeakRelTol = 0.25;

TEST(SeakeepingWigley, HeadSeaHeaveAndAddedResistanceMatchJournee1992) {
  const std::vector<Row> rows = read_rows();
  ASSERT_EQ(rows.size(), 8u);
  int checked = 0;
  for (const Row& row : rows) {
    if (!row.asserted) continue;
    const model::Vessel v = test::wigley_vessel(particulars(row.hull));
    const double l = v.hull.length_pp_m;
    const double u = row.froude * std::sqrt(kGravity_m_s2 * l);
    if (row.quantity == "heave_rao") {
      const auto r = compute_response(v, u, kPi, {omega_for(std::stod(row.wavelength), l)});
      EXPECT_REL_CLOSE(std::abs(r[0].rao(kHeave)), row.measured, kHeaveRaoRelTol) << row.hull;
      ++checked;
    } else if (row.quantity == "raw_peak") {
      std::vector<double> w;
      for (double lam = 0.8; lam <= 1.3001; lam += 0.05) w.push_back(omega_for(lam, l));
      const auto r = compute_response(v, u, kPi, w);
      double peak = 0.0;
      const double scale = kRhoSeawater_kg_m3 * kGravity_m_s2 * v.hull.beam_m * v.hull.beam_m / l;
      for (const VesselResponse& x : r) peak = std::max(peak, x.added_resistance_n_per_m2 / scale);
      EXPECT_REL_CLOSE(peak, row.measured, kAddedResistancePeakRelTol) << row.hull << " Fn " << row.froude;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3);
}

}  // namespace
}  // namespace towdb::seakeeping
