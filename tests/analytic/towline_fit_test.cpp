// Manufactured solutions for the polynomial towline model and its fit
// (towdb::towline, towline/towline.hpp EQ-TOWLINE-11..14).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "common/units.hpp"
#include "test_support.hpp"
#include "towline/polynomial.hpp"
#include "towline/towline.hpp"
#include "towline_test_lines.hpp"

namespace towdb::towline {
namespace {

// A least-squares solve of an exactly representable target: the residual is
// roundoff in a 9-column QR of ~1800 rows scaled to O(1): 1e-9 relative.
constexpr double kExactFitRelTol = 1e-9;

PolynomialCoefficients manufactured() {
  PolynomialCoefficients p;
  p.a = {5.0e4, 1.2e4, 3.0e3, -8.0e2, 1.5e3, 2.0e2, -1.0e2, 3.0e1, -2.0e1};
  return p;
}

// Samples xi = a sin(w t), xi_dot = a w cos(w t) over the default excitation set.
std::vector<TensionSample> sinusoid_samples(const PolynomialCoefficients& p) {
  std::vector<TensionSample> out;
  for (const Excitation& e : excitation_set()) {
    for (int k = 0; k < 32; ++k) {
      const double phase = 2.0 * kPi * k / 32.0;
      TensionSample s;
      s.xi_m = e.amplitude_m * std::sin(phase);
      s.xi_dot_m_s = e.amplitude_m * e.omega_rad_s * std::cos(phase);
      s.tau_n = p.evaluate_n(s.xi_m, s.xi_dot_m_s);
      out.push_back(s);
    }
  }
  return out;
}

// EVIDENCE-OF: EQ-TOWLINE-11
// EVIDENCE-OF: EQ-TOWLINE-12
// Samples of an exact cubic are fitted exactly: every coefficient comes back.
TEST(TowlineFit, ReproducesAnExactPolynomial) {
  const PolynomialCoefficients p = manufactured();
  const PolynomialFit fit = fit_polynomial(sinusoid_samples(p), std::numeric_limits<double>::infinity());
  for (int k = 0; k < PolynomialCoefficients::kCount; ++k) {
    EXPECT_REL_CLOSE(fit.coefficients.a[static_cast<std::size_t>(k)], p.a[static_cast<std::size_t>(k)],
                     kExactFitRelTol)
        << "coefficient " << k;
  }
  EXPECT_LT(fit.rms_error_n, kExactFitRelTol * fit.rms_tension_n);
  EXPECT_EQ(fit.samples_used, 56 * 32);
  EXPECT_EQ(fit.samples_excluded, 0);
  // Named accessors follow the stated order a10, a01, a20, a11, a02, a30, a21, a12, a03.
  EXPECT_EQ(p.a10(), 5.0e4);
  EXPECT_EQ(p.a01(), 1.2e4);
  EXPECT_EQ(p.a11(), -8.0e2);
  EXPECT_EQ(p.a03(), -2.0e1);
  EXPECT_DOUBLE_EQ(p.evaluate_n(2.0, 0.0), 5.0e4 * 2 + 3.0e3 * 4 + 2.0e2 * 8);
}

// EVIDENCE-OF: EQ-TOWLINE-12
// Samples above the breaking limit are left out: corrupting exactly those
// (here: doubling them) leaves the fit exact.
TEST(TowlineFit, LeavesOutSamplesAboveBreakingStrength) {
  const PolynomialCoefficients p = manufactured();
  std::vector<TensionSample> samples = sinusoid_samples(p);
  const double limit_n = 2.0e5;
  int above = 0;
  for (auto& s : samples) {
    if (s.tau_n > limit_n) {
      s.tau_n *= 2.0;
      ++above;
    }
  }
  ASSERT_GT(above, 50);
  const PolynomialFit fit = fit_polynomial(samples, limit_n);
  EXPECT_EQ(fit.samples_excluded, above);
  for (int k = 0; k < PolynomialCoefficients::kCount; ++k) {
    EXPECT_REL_CLOSE(fit.coefficients.a[static_cast<std::size_t>(k)], p.a[static_cast<std::size_t>(k)],
                     kExactFitRelTol);
  }
}

// EVIDENCE-OF: EQ-TOWLINE-12
// One-sided slack samples: if the data are an exact polynomial clamped at a
// floor (as a slack line is), the one-sided fit recovers the polynomial
// exactly, while the thesis's two-sided fit is biased by the flat branch.
TEST(TowlineFit, OneSidedSlackSamplesRecoverTheUnclampedPolynomial) {
  const PolynomialCoefficients p = manufactured();
  std::vector<TensionSample> samples = sinusoid_samples(p);
  const double floor_n = -3.0e4;
  int slack = 0;
  for (auto& s : samples) {
    if (s.tau_n < floor_n) {
      s.tau_n = floor_n;
      s.slack = true;
      ++slack;
    }
  }
  ASSERT_GT(slack, 50);
  const double inf = std::numeric_limits<double>::infinity();
  const PolynomialFit one = fit_polynomial(samples, inf, floor_n, SlackFit::kOneSided);
  for (int k = 0; k < PolynomialCoefficients::kCount; ++k) {
    EXPECT_REL_CLOSE(one.coefficients.a[static_cast<std::size_t>(k)], p.a[static_cast<std::size_t>(k)], 1e-8);
  }
  EXPECT_LT(one.rms_error_n, 1e-8 * one.rms_tension_n);
  const PolynomialFit two = fit_polynomial(samples, inf, floor_n, SlackFit::kTwoSided);
  EXPECT_GT(two.rms_error_n, 1e-3 * two.rms_tension_n);
}

// EVIDENCE-OF: EQ-TOWLINE-14
// The default excitation set: 56 runs, 8 frequencies x 7 amplitudes, with the
// velocity amplitude capped at 3.5 m/s and the amplitude at 6 m.
TEST(TowlineFit, DefaultExcitationSetSpansTheStatedRange) {
  const std::vector<Excitation> set = excitation_set();
  ASSERT_EQ(set.size(), 56u);
  double a_max = 0.0, v_max = 0.0, w_min = 1e9, w_max = 0.0;
  for (const auto& e : set) {
    a_max = std::max(a_max, e.amplitude_m);
    v_max = std::max(v_max, e.amplitude_m * e.omega_rad_s);
    w_min = std::min(w_min, e.omega_rad_s);
    w_max = std::max(w_max, e.omega_rad_s);
  }
  EXPECT_DOUBLE_EQ(a_max, 6.0);
  EXPECT_NEAR(v_max, 3.5, 1e-12);  // [m/s]
  EXPECT_DOUBLE_EQ(w_min, 0.03);
  EXPECT_DOUBLE_EQ(w_max, 1.6);
  EXPECT_DOUBLE_EQ(set.back().amplitude_m, 3.5 / 1.6);
}

// EVIDENCE-OF: EQ-TOWLINE-13
// The straight-spring branch: beyond xi_b the tension grows at EA/L
// (= 1 / sum L_i/EA_i) and joins the polynomial continuously; below xi_b the
// two models agree; the slack limit holds in both.
TEST(TowlineFit, StraightSpringAboveBreakingStrength) {
  const model::Towline line = test::thesis_towline("wire", 1000.0);
  TowlineFitOptions o;
  o.excitation.frequencies_rad_s = {0.05, 0.5, 1.2};  // a small set keeps the test fast
  o.excitation.amplitude_fractions = {0.1, 0.5, 1.0};
  const auto fit = build_towline_fit(line, test::thesis_tow_points(), units::lbf_to_n(109000.0), o);
  const FitSummary& s = fit->summary();
  const double k_ea = 1.0 / line.axial_compliance_m_per_n();
  EXPECT_REL_CLOSE(s.straight_spring_n_m, k_ea, 1e-14);
  // xi_b: the static extension from H = 109,000 lbf to the 360,000 lbf
  // breaking strength is a little above (breaking - H) / (EA/L), since the
  // catenary is softer than the straight line.
  const double straight = (s.breaking_strength_n - s.mean_tension_n) / k_ea;
  EXPECT_GT(s.spring_onset_extension_m, straight);
  EXPECT_LT(s.spring_onset_extension_m, 1.2 * straight);
  const double xb = s.spring_onset_extension_m;
  for (double v : {-1.0, 0.0, 2.0}) {
    const double below = fit->dynamic_tension_n(xb - 1e-9, v, AboveBreakingModel::kStraightSpring);
    const double at = fit->dynamic_tension_n(xb, v, AboveBreakingModel::kStraightSpring);
    EXPECT_NEAR(below, at, 1e-3);  // [N] continuous
    const double above = fit->dynamic_tension_n(xb + 0.5, v, AboveBreakingModel::kStraightSpring);
    EXPECT_REL_CLOSE(above - at, 0.5 * k_ea, 1e-12);
    EXPECT_EQ(fit->dynamic_tension_n(0.3, v, AboveBreakingModel::kStraightSpring),
              fit->dynamic_tension_n(0.3, v, AboveBreakingModel::kPolynomial));
  }
  // EVIDENCE-OF: EQ-TOWLINE-8
  // The slack limit: max(P, -min T) at every sample of the runs, and the
  // limit is reached somewhere (large slow shortening of a taut wire).
  int limited = 0;
  for (const HarmonicRun& run : fit->runs()) {
    for (const TensionSample& x : run.samples) {
      const double p = fit->polynomial_n(x.xi_m, x.xi_dot_m_s);
      EXPECT_EQ(fit->dynamic_tension_n(x.xi_m, x.xi_dot_m_s, AboveBreakingModel::kPolynomial),
                std::max(p, s.slack_limit_n));
      limited += p < s.slack_limit_n ? 1 : 0;
    }
  }
  EXPECT_GT(limited, 0);
  EXPECT_LE(s.slack_limit_n, -s.mean_tension_n);
  EXPECT_GT(s.slack_limit_n, -1.01 * s.mean_tension_n);
}


// EVIDENCE-OF: EQ-TOWLINE-16
// a10 held: it comes back exactly as held, and when held at the true value
// the other eight coefficients of an exact cubic come back as well.
TEST(TowlineFit, HeldLinearTermIsExactAndTheRestRecovered) {
  const PolynomialCoefficients p = manufactured();
  const double inf = std::numeric_limits<double>::infinity();
  SmallMotionFit held;
  held.fixed_a10_n_m = p.a10();
  const PolynomialFit fit = fit_polynomial(sinusoid_samples(p), inf, -inf, SlackFit::kTwoSided, held);
  for (int k = 0; k < PolynomialCoefficients::kCount; ++k) {
    EXPECT_REL_CLOSE(fit.coefficients.a[static_cast<std::size_t>(k)], p.a[static_cast<std::size_t>(k)],
                     kExactFitRelTol)
        << "coefficient " << k;
  }
  held.fixed_a10_n_m = 0.5 * p.a10();
  const PolynomialFit off = fit_polynomial(sinusoid_samples(p), inf, -inf, SlackFit::kTwoSided, held);
  EXPECT_EQ(off.coefficients.a10(), 0.5 * p.a10());
  EXPECT_GT(off.rms_error_n, 1e-3 * off.rms_tension_n);  // the other terms cannot absorb a wrong slope
}

// EVIDENCE-OF: EQ-TOWLINE-16
// Weights move the fit toward the heavy rows: samples of two different
// cubics, the second weighted 1e4, give (nearly) the second cubic.
TEST(TowlineFit, WeightsShiftTheFitTowardHeavyRows) {
  const PolynomialCoefficients p = manufactured();
  PolynomialCoefficients q = p;
  q.a[0] *= 2.0;
  q.a[5] *= -3.0;
  std::vector<TensionSample> samples = sinusoid_samples(p);
  const std::vector<TensionSample> heavy = sinusoid_samples(q);
  samples.insert(samples.end(), heavy.begin(), heavy.end());
  SmallMotionFit weighted;
  weighted.weights.assign(samples.size(), 1.0);
  std::fill(weighted.weights.begin() + static_cast<std::ptrdiff_t>(heavy.size()), weighted.weights.end(), 1e4);
  const double inf = std::numeric_limits<double>::infinity();
  const PolynomialFit fit = fit_polynomial(samples, inf, -inf, SlackFit::kTwoSided, weighted);
  // The light rows pull by (1/1e4)^2 of the heavy ones: 1e-6 relative at most.
  EXPECT_REL_CLOSE(fit.coefficients.a10(), q.a10(), 1e-6);
  EXPECT_REL_CLOSE(fit.coefficients.a30(), q.a30(), 1e-6);
  const PolynomialFit plain = fit_polynomial(samples, inf);
  EXPECT_GT(std::abs(plain.coefficients.a10() - q.a10()), 0.1 * q.a10());  // unweighted: in between
}

// EVIDENCE-OF: EQ-TOWLINE-17
// The closed-form first harmonic equals the Fourier integral of
// P(A sin wt, A w cos wt) over one period (trapezoidal rule, exact for a
// trigonometric polynomial of degree 3 with more than 6 points).
TEST(TowlineFit, FirstHarmonicMatchesTheFourierIntegral) {
  const PolynomialCoefficients p = manufactured();
  for (const auto& [a, w] : {std::pair{0.3048, 0.0628}, std::pair{2.0, 0.5}, std::pair{6.0, 1.6}}) {
    constexpr int kPoints = 64;
    double b = 0.0, c = 0.0;
    for (int k = 0; k < kPoints; ++k) {
      const double phase = 2.0 * kPi * k / kPoints;
      const double tau = p.evaluate_n(a * std::sin(phase), a * w * std::cos(phase));
      b += 2.0 / kPoints * tau * std::sin(phase);
      c += 2.0 / kPoints * tau * std::cos(phase);
    }
    EXPECT_REL_CLOSE(first_harmonic_n(p, a, w), std::hypot(b, c), 1e-12) << "A " << a << " m, w " << w;
  }
  PolynomialCoefficients linear;
  linear.a[0] = 1000.0;
  EXPECT_DOUBLE_EQ(first_harmonic_n(linear, 0.5, 0.1), 500.0);  // k A alone
}

// EVIDENCE-OF: EQ-TOWLINE-18
// The Gaussian equivalent line is the least-squares linear fit of P over
// independent zero-mean Gaussian xi and xi_dot: k = E[P xi] / E[xi^2],
// c = E[P xi_dot] / E[xi_dot^2]. Both expectations by a 3-point Gauss-Hermite
// rule per variable (nodes 0 and +/- sqrt(3) standard deviations, weights
// 2/3, 1/6, 1/6: exact to degree 5, and P xi is of degree 4 in each).
TEST(TowlineFit, GaussianEquivalentLineIsTheLeastSquaresLine) {
  const PolynomialCoefficients p = manufactured();
  const double nodes[3] = {0.0, std::sqrt(3.0), -std::sqrt(3.0)};
  const double weights[3] = {2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0};
  for (const auto& [s2, v2] : {std::pair{0.01, 0.0004}, std::pair{1.0, 0.25}, std::pair{9.0, 4.0}}) {
    double px = 0.0, pv = 0.0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double x = nodes[i] * std::sqrt(s2), v = nodes[j] * std::sqrt(v2);
        const double tau = p.evaluate_n(x, v);
        px += weights[i] * weights[j] * tau * x;
        pv += weights[i] * weights[j] * tau * v;
      }
    }
    const EquivalentLinearLine eq = gaussian_equivalent_line(p, s2, v2);
    EXPECT_REL_CLOSE(eq.stiffness_n_m, px / s2, 1e-12) << "s2 " << s2 << ", v2 " << v2;
    EXPECT_REL_CLOSE(eq.damping_n_s_m, pv / v2, 1e-12) << "s2 " << s2 << ", v2 " << v2;
  }
  // Vanishing motion: the linear terms.
  const EquivalentLinearLine small = gaussian_equivalent_line(p, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(small.stiffness_n_m, p.a10());
  EXPECT_DOUBLE_EQ(small.damping_n_s_m, p.a01());
}

// EVIDENCE-OF: EQ-TOWLINE-19
// The damping of a run from the energy dissipated per cycle. The polynomial
// on a harmonic extension dissipates a01 + a21 A^2 / 4 + 3 a03 (A w)^2 / 4
// (rectangle rule on 32 uniform phases: exact for the degree-4 integrand).
// The cable is passive (it dissipates at every run), and at low frequency its
// damping is the normal drag's: a quadratic damper F = C |v| v dissipates as
// a linear one of c_eq = 8 C A w / (3 pi) (Morison), so c_eq grows in
// proportion to the amplitude.
TEST(TowlineFit, RunDampingIsTheEnergyDissipatedPerCycle) {
  // Quadratic drag holds to a few percent below about 0.1 m/s here (the
  // chord's tangential motion and the line's inertia add a little).
  constexpr double kDragScalingRelTol = 0.05;
  constexpr double kClosedFormRelTol = 1e-9;  // roundoff over 32 samples
  const model::Towline line = test::thesis_towline("wire", 2000.0);
  TowlineFitOptions o;
  o.excitation.frequencies_rad_s = {0.05, 0.15, 0.5};  // a small set keeps the test fast
  o.excitation.amplitude_fractions = {0.02, 0.05, 0.1, 0.5};
  const auto fit = build_towline_fit(line, test::thesis_tow_points(), units::lbf_to_n(79000.0), o);
  const PolynomialCoefficients& c = fit->coefficients();
  const std::vector<RunDamping> d = run_damping(*fit);
  ASSERT_EQ(d.size(), fit->runs().size());
  int closed_form_checked = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const HarmonicRun& run = fit->runs()[i];
    EXPECT_GT(d[i].cable_n_s_m, 0.0) << "run " << i;
    bool limited = false;
    for (const TensionSample& x : run.samples) limited |= fit->polynomial_n(x.xi_m, x.xi_dot_m_s) < fit->summary().slack_limit_n;
    if (limited) continue;
    const double a = d[i].amplitude_m, w = d[i].omega_rad_s;
    EXPECT_REL_CLOSE(d[i].polynomial_n_s_m, c.a01() + c.a21() * a * a / 4.0 + 0.75 * c.a03() * a * a * w * w,
                     kClosedFormRelTol)
        << "run " << i;
    ++closed_form_checked;
  }
  EXPECT_GT(closed_form_checked, 8);
  // Low frequency, velocity amplitude 0.02-0.09 m/s: c_eq / (A w) is one number.
  for (double w : {0.05, 0.15}) {
    std::vector<double> per_velocity;
    for (const RunDamping& r : d) {
      if (r.omega_rad_s == w && r.amplitude_m * w < 0.1) per_velocity.push_back(r.cable_n_s_m / (r.amplitude_m * w));
    }
    ASSERT_GE(per_velocity.size(), 2u) << w;
    for (double x : per_velocity) EXPECT_REL_CLOSE(x, per_velocity.front(), kDragScalingRelTol) << "w " << w;
  }
}

}  // namespace
}  // namespace towdb::towline
