// Strip theory (STF 1970) on a Wigley hull: long-wave limits, zero-speed
// reciprocity, forward-speed terms, heading symmetries, determinism, and the
// added-resistance spectrum integral.
#include <cmath>
#include <complex>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "seakeeping/seakeeping.hpp"
#include "seakeeping_hulls.hpp"
#include "test_support.hpp"

namespace towdb::seakeeping {
namespace {

using Complex = std::complex<double>;

double omega_for_wavelength(double wavelength_m) {
  return std::sqrt(kGravity_m_s2 * 2.0 * kPi / wavelength_m);
}

const model::Vessel& wigley() {
  static const model::Vessel v = test::wigley_vessel();
  return v;
}

// EVIDENCE-OF: EQ-STRIP-4
// EVIDENCE-OF: EQ-STRIP-9
TEST(SeakeepingStrip, LongWavesHeaveFollowsTheWaveAndPitchTheSlope) {
  // lambda = 20 L, zero speed, head seas: heave -> 1 and pitch -> k (the
  // wave slope) with O(kL) corrections (measured 0.2% and 0.4% at 20 L; the
  // pitch limit needs the z n_1 Froude-Krylov moment of EQ-STRIP-7: without
  // it pitch/k tends to BM_L/GM_L, 1.03 here).
  constexpr double kLongWaveRelTol = 0.01;
  const double l = wigley().hull.length_pp_m;
  const auto r = compute_response(wigley(), 0.0, kPi, {omega_for_wavelength(20.0 * l)});
  const double k = r[0].wavenumber_rad_m;
  EXPECT_REL_CLOSE(std::abs(r[0].rao(kHeave)), 1.0, kLongWaveRelTol);
  EXPECT_REL_CLOSE(std::abs(r[0].rao(kPitch)), k, kLongWaveRelTol);
  // Phases: heave in phase with the crest at midships; head seas (waves
  // travelling toward -x) lift the bow first, i.e. bow-up = negative pitch
  // leads the crest by 90 deg: pitch = -i k * heave.
  constexpr double kPhaseAbsTolRad = 0.05;
  EXPECT_ABS_CLOSE(std::arg(r[0].rao(kHeave)), 0.0, kPhaseAbsTolRad);
  EXPECT_ABS_CLOSE(std::arg(r[0].rao(kPitch)), -kPi / 2.0, kPhaseAbsTolRad);
  // Following seas: the slope reverses.
  const auto f = compute_response(wigley(), 0.0, 0.0, {omega_for_wavelength(20.0 * l)});
  EXPECT_ABS_CLOSE(std::arg(f[0].rao(kPitch)), kPi / 2.0, kPhaseAbsTolRad);
}

// EVIDENCE-OF: EQ-STRIP-7
TEST(SeakeepingStrip, SurgeDiffractionMakesTheLongWaveSurgeFollowTheWater) {
  // lambda = 20 L at zero speed in head seas: the water's horizontal orbit
  // has amplitude e^{kz} (per unit wave amplitude). Froude-Krylov alone gives
  // rho V du/dt against (m + A11), so the free hull surges m / (m + A11) =
  // 1 / 1.05 of it; with the diffraction force A11 du/dt (Newman 1977, sec.
  // 4.15: F = (rho V + A11) du/dt) it follows the water. The ratio of the two
  // is 1 + A11 / m up to the surge-pitch mass coupling (measured 1e-4); the
  // orbit itself is met to O(kT / 2 + (kL)^2 / 24) = 1.3 % on this hull.
  constexpr double kCouplingRelTol = 1e-3;
  constexpr double kLongWaveRelTol = 0.02;
  const double l = wigley().hull.length_pp_m;
  const double ratio = wigley().hull.surge_added_mass_ratio;
  ASSERT_GT(ratio, 0.0);
  const std::vector<double> omega{omega_for_wavelength(20.0 * l)};
  ResponseOptions without;
  without.surge_diffraction = false;
  const auto fk_only = compute_response(wigley(), 0.0, kPi, omega, without);
  ResponseOptions with;
  with.surge_diffraction = true;
  const auto both = compute_response(wigley(), 0.0, kPi, omega, with);
  EXPECT_REL_CLOSE(std::abs(both[0].rao(kSurge)) / std::abs(fk_only[0].rao(kSurge)), 1.0 + ratio, kCouplingRelTol);
  EXPECT_REL_CLOSE(std::abs(both[0].rao(kSurge)), 1.0, kLongWaveRelTol);
  EXPECT_REL_CLOSE(std::abs(fk_only[0].rao(kSurge)), 1.0 / (1.0 + ratio), kLongWaveRelTol);
  // The option touches the surge force only.
  EXPECT_EQ(both[0].exciting_force_per_m(kHeave), fk_only[0].exciting_force_per_m(kHeave));

  // With speed the added-mass part is driven at the encounter frequency:
  // F1_D = ratio (w_h / w) F1_FK, exactly (larger in head seas, smaller in
  // following seas, opposite in sign where the waves overtake).
  constexpr double kAlgebraRelTol = 1e-12;
  const double u = 0.3 * std::sqrt(kGravity_m_s2 * l);
  for (double mu : {0.0, kPi}) {
    const auto r = compute_response(wigley(), u, mu, {omega_for_wavelength(1.5 * l)}, with);
    const VesselResponse& v = r[0];
    const Complex expected = ratio * (v.omega_hydro_rad_s / v.omega_rad_s) * v.froude_krylov_per_m(kSurge);
    EXPECT_REL_CLOSE(std::abs(v.diffraction_per_m(kSurge)), std::abs(expected), kAlgebraRelTol) << mu;
    EXPECT_REL_CLOSE(std::abs(v.exciting_force_per_m(kSurge)),
                     std::abs(v.froude_krylov_per_m(kSurge) + expected), kAlgebraRelTol) << mu;
  }
}

// EVIDENCE-OF: EQ-STRIP-3
TEST(SeakeepingStrip, ZeroSpeedCoefficientsAreSymmetric) {
  // At U = 0, K_ij = -w^2 int c_i Z_ij c_j dx is symmetric whenever the
  // sectional Z is; the sections are reciprocal (a24 = a42) only to the
  // multipole residual (~1e-3 at the default tolerance), hence 5e-3 on the
  // geometric mean of the diagonal terms.
  constexpr double kReciprocityRelTol = 5e-3;
  const auto r = compute_response(wigley(), 0.0, kPi / 3.0, {4.0, 7.0});
  for (const VesselResponse& v : r) {
    for (int i = 1; i < 6; ++i) {
      for (int j = i + 1; j < 6; ++j) {
        const double scale_a = std::sqrt(std::abs(v.added_mass(i, i) * v.added_mass(j, j)));
        const double scale_b = std::sqrt(std::abs(v.damping(i, i) * v.damping(j, j)));
        EXPECT_ABS_CLOSE(v.added_mass(i, j), v.added_mass(j, i), kReciprocityRelTol * scale_a) << i << j;
        EXPECT_ABS_CLOSE(v.damping(i, j), v.damping(j, i), kReciprocityRelTol * scale_b) << i << j;
      }
    }
    // Fore-aft symmetric hull: heave-pitch coupling vanishes at zero speed.
    EXPECT_ABS_CLOSE(v.added_mass(kHeave, kPitch), 0.0,
                     1e-9 * v.added_mass(kHeave, kHeave) * wigley().hull.length_pp_m);
  }
}

// EVIDENCE-OF: EQ-STRIP-2
// EVIDENCE-OF: EQ-STRIP-3
TEST(SeakeepingStrip, ForwardSpeedTermsAreStfs) {
  // Wigley: no transom (zero end sections), so STF gives exactly
  //   B35 - B53 = 2 U A33,  A35 - A53 = -2 (U / w^2) B33,
  //   A55(U) - A55(0) = (U^2 / w^2) A33,  B55(U) - B55(0) = (U^2 / w^2) B33.
  constexpr double kAlgebraRelTol = 1e-9;
  const double l = wigley().hull.length_pp_m;
  const double u = 0.3 * std::sqrt(kGravity_m_s2 * l);
  const double w0 = omega_for_wavelength(1.25 * l);
  const auto moving = compute_response(wigley(), u, kPi, {w0});
  const VesselResponse& m = moving[0];
  const double we = m.omega_e_rad_s;
  EXPECT_REL_CLOSE(we, w0 + w0 * w0 / kGravity_m_s2 * u, 1e-14);  // w_e = w - k U cos(pi)
  EXPECT_REL_CLOSE(m.damping(kHeave, kPitch) - m.damping(kPitch, kHeave), 2.0 * u * m.added_mass(kHeave, kHeave),
                   kAlgebraRelTol);
  EXPECT_REL_CLOSE(m.added_mass(kHeave, kPitch) - m.added_mass(kPitch, kHeave),
                   -2.0 * u / (we * we) * m.damping(kHeave, kHeave), kAlgebraRelTol);
  // The same encounter frequency at zero speed gives the U = 0 coefficients.
  const auto still = compute_response(wigley(), 0.0, kPi, {we});
  const VesselResponse& s = still[0];
  EXPECT_REL_CLOSE(m.added_mass(kPitch, kPitch) - s.added_mass(kPitch, kPitch),
                   u * u / (we * we) * s.added_mass(kHeave, kHeave), kAlgebraRelTol);
  EXPECT_REL_CLOSE(m.damping(kPitch, kPitch) - s.damping(kPitch, kPitch),
                   u * u / (we * we) * s.damping(kHeave, kHeave), kAlgebraRelTol);
  // Yaw analogue (EQ-STRIP-3 for sway/yaw): B26 - B62 = -2 U A22.
  EXPECT_REL_CLOSE(m.damping(kSway, kYaw) - m.damping(kYaw, kSway), -2.0 * u * m.added_mass(kSway, kSway),
                   kAlgebraRelTol);
}

TEST(SeakeepingStrip, HeadAndFollowingSeasExciteNoLateralMotion) {
  constexpr double kVanishingRelTol = 1e-12;  // sin(0) and sin(pi) are ~1e-16
  for (double mu : {0.0, kPi}) {
    const auto r = compute_response(wigley(), 1.0, mu, {3.0, 5.0});
    for (const VesselResponse& v : r) {
      const double scale = std::abs(v.exciting_force_per_m(kHeave));
      for (int dof : {kSway, kRoll, kYaw}) {
        EXPECT_ABS_CLOSE(std::abs(v.exciting_force_per_m(dof)), 0.0, kVanishingRelTol * scale * 10.0);
      }
    }
  }
}

TEST(SeakeepingStrip, MirroredHeadingsMirrorTheMotions) {
  // mu and -mu (seas from starboard / port bow): the vertical motions are
  // equal, the lateral ones change sign (port-starboard symmetric hull).
  constexpr double kMirrorRelTol = 1e-10;
  const double mu = 2.4;
  const auto a = compute_response(wigley(), 1.2, mu, {4.5});
  const auto b = compute_response(wigley(), 1.2, -mu, {4.5});
  for (int dof : {kSurge, kHeave, kPitch}) {
    EXPECT_REL_CLOSE(a[0].rao(dof).real(), b[0].rao(dof).real(), kMirrorRelTol);
    EXPECT_REL_CLOSE(a[0].rao(dof).imag(), b[0].rao(dof).imag(), kMirrorRelTol);
  }
  for (int dof : {kSway, kRoll, kYaw}) {
    EXPECT_REL_CLOSE(a[0].rao(dof).real(), -b[0].rao(dof).real(), kMirrorRelTol);
    EXPECT_REL_CLOSE(a[0].rao(dof).imag(), -b[0].rao(dof).imag(), kMirrorRelTol);
  }
}

TEST(SeakeepingStrip, BeamSeasLongWavesSwayFollowsTheOrbit) {
  // lambda = 40 L at zero speed in beam seas: the free hull follows the
  // water's horizontal orbit (|sway| -> 1, 90 deg off heave) and heave -> 1.
  constexpr double kLongWaveRelTol = 0.05;
  const double l = wigley().hull.length_pp_m;
  const auto r = compute_response(wigley(), 0.0, kPi / 2.0, {omega_for_wavelength(40.0 * l)});
  EXPECT_REL_CLOSE(std::abs(r[0].rao(kHeave)), 1.0, kLongWaveRelTol);
  EXPECT_REL_CLOSE(std::abs(r[0].rao(kSway)), 1.0, kLongWaveRelTol);
  EXPECT_LT(std::abs(r[0].rao(kYaw)), 1e-6 * r[0].wavenumber_rad_m);  // symmetric hull: no yaw
}

TEST(SeakeepingStrip, ResultsAreIndependentOfThreadCount) {
  ResponseOptions one;
  one.num_threads = 1;
  ResponseOptions two;
  two.num_threads = 2;
  const std::vector<double> w{2.0, 3.0, 4.0, 5.0};
  const auto a = compute_response(wigley(), 1.0, 2.0, w, one);
  const auto b = compute_response(wigley(), 1.0, 2.0, w, two);
  for (std::size_t i = 0; i < w.size(); ++i) {
    for (int d = 0; d < 6; ++d) {
      EXPECT_EQ(a[i].rao(d), b[i].rao(d));
    }
    EXPECT_EQ(a[i].added_resistance_n_per_m2, b[i].added_resistance_n_per_m2);
  }
}

// EVIDENCE-OF: EQ-STRIP-10
TEST(SeakeepingStrip, FollowingSeasThroughZeroEncounterFrequency) {
  // Following seas at U: w_e = w - w^2 U / g is zero at w = g / U and
  // negative above. The floor keeps the hydrodynamics finite and the
  // response continuous across w_e = 0 (the floor frequency is used on
  // both sides, with the sign of w_e).
  const double u = 1.0;
  const double w_zero = kGravity_m_s2 / u;
  const auto r = compute_response(wigley(), u, 0.0, {0.999 * w_zero, 1.001 * w_zero, 1.3 * w_zero});
  EXPECT_GT(r[0].omega_e_rad_s, 0.0);
  EXPECT_LT(r[1].omega_e_rad_s, 0.0);
  EXPECT_LT(r[2].omega_e_rad_s, 0.0);
  const double floor = 0.1 * std::sqrt(kGravity_m_s2 / wigley().hull.length_pp_m);
  EXPECT_DOUBLE_EQ(r[0].omega_hydro_rad_s, floor);
  EXPECT_DOUBLE_EQ(r[1].omega_hydro_rad_s, -floor);
  for (const VesselResponse& v : r) {
    EXPECT_TRUE(v.rao.allFinite());
    EXPECT_TRUE(std::isfinite(v.added_resistance_n_per_m2));
  }
}

// EVIDENCE-OF: EQ-AR-1
TEST(SeakeepingAddedResistance, HeadSeasResistFollowingSeasBarely) {
  // Head seas near heave/pitch resonance: a resistance (> 0). Following
  // seas with w_e > 0: -(k cos mu / 2 w_e) < 0, slightly negative (thesis ch. 2:
  // "maximum for head seas and slightly negative for trailing seas").
  const double l = wigley().hull.length_pp_m;
  const double u = 0.2 * std::sqrt(kGravity_m_s2 * l);
  const double w = omega_for_wavelength(1.2 * l);
  const auto head = compute_response(wigley(), u, kPi, {w});
  ResponseOptions all_headings;
  all_headings.added_resistance_aft_of_beam = true;
  const auto follow = compute_response(wigley(), u, 0.0, {omega_for_wavelength(3.0 * l)}, all_headings);
  EXPECT_GT(head[0].added_resistance_n_per_m2, 0.0);
  EXPECT_LT(follow[0].added_resistance_n_per_m2, 0.0);
  EXPECT_LT(std::abs(follow[0].added_resistance_n_per_m2), 0.1 * head[0].added_resistance_n_per_m2);
}

// EVIDENCE-OF: EQ-AR-4
TEST(SeakeepingAddedResistance, ZeroAftOfBeamByDefault) {
  const double l = wigley().hull.length_pp_m;
  const double u = 0.2 * std::sqrt(kGravity_m_s2 * l);
  const double w = omega_for_wavelength(3.0 * l);
  for (double mu_deg : {0.0, 45.0, 89.0}) {
    const auto r = compute_response(wigley(), u, mu_deg * kPi / 180.0, {w});
    EXPECT_EQ(r[0].added_resistance_n_per_m2, 0.0) << mu_deg;
  }
  // Forward of beam it is the radiated-energy value, a resistance.
  const auto bow = compute_response(wigley(), u, 135.0 * kPi / 180.0, {omega_for_wavelength(1.2 * l)});
  EXPECT_GT(bow[0].added_resistance_n_per_m2, 0.0);
}

// EVIDENCE-OF: EQ-AR-2
TEST(SeakeepingAddedResistance, SpectrumIntegralIsTwiceTheWeightedArea) {
  // Manufactured operator R_aw/zeta^2 = c w and a linear spectrum S = s w on
  // [1, 3]: 2 int c s w^2 dw = 2 c s (27 - 1)/3; the trapezoid rule on 2001
  // points is accurate to (dw^2/12) * 2 c s * 2 / (26/3) relative ~ 1e-7.
  constexpr double kQuadratureRelTol = 1e-6;
  const double c = 3.5;
  const double s = 0.2;
  std::vector<VesselResponse> r(2001);
  for (std::size_t i = 0; i < r.size(); ++i) {
    r[i].omega_rad_s = 1.0 + 2.0 * static_cast<double>(i) / 2000.0;
    r[i].added_resistance_n_per_m2 = c * r[i].omega_rad_s;
  }
  const double expected = 2.0 * c * s * 26.0 / 3.0;
  EXPECT_REL_CLOSE(mean_added_resistance_n(r, [s](double w) { return s * w; }), expected, kQuadratureRelTol);
}

// EVIDENCE-OF: EQ-AR-3
TEST(SeakeepingAddedResistance, SurgeDampingIsTheOneFootPerSecondDifference) {
  // A Pierson-Moskowitz-like sea on the model-scale Wigley; the damping is
  // (R(U + 0.3048) - R(U)) / 0.3048 by definition and positive in head seas
  // below the speed of peak added resistance.
  AddedResistanceOptions o;
  o.omega_min_rad_s = 3.0;
  o.omega_max_rad_s = 9.0;
  o.omega_count = 13;
  const auto spectrum = [](double w) { return 1e-4 * std::exp(-std::pow((w - 5.5) / 1.0, 2)); };
  const double u = 0.5;
  const double r0 = mean_added_resistance_n(wigley(), u, kPi, spectrum, o);
  const double r1 = mean_added_resistance_n(wigley(), u + 0.3048, kPi, spectrum, o);
  const double damping = wave_surge_damping_n_s_m(wigley(), u, kPi, spectrum, o);
  EXPECT_REL_CLOSE(damping, (r1 - r0) / 0.3048, 1e-12);
  EXPECT_GT(r0, 0.0);
  EXPECT_GT(damping, 0.0);
}

}  // namespace
}  // namespace towdb::seakeeping
