// Analytic checks of the wave spectra (sea/sea.hpp EQ-SEA-1..5): closed-form
// moments against independent quadrature, the PM wave height law, the
// Bretschneider period relations derived in the header, and JONSWAP.
#include <cmath>
#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "common/units.hpp"
#include "sea/sea.hpp"
#include "test_support.hpp"

namespace towdb::sea {
namespace {

// Independent quadrature for the tests: composite Simpson in ln(w) over
// [w_lo, w_hi] (integrand w f(w) in s = ln w), fine enough that its own error
// is below 1e-9 relative for these smooth spectra.
double log_simpson(const std::function<double(double)>& f, double w_lo, double w_hi, int panels = 200000) {
  const double s0 = std::log(w_lo);
  const double h = (std::log(w_hi) - s0) / panels;
  double sum = 0.0;
  for (int i = 0; i <= panels; ++i) {
    const double w = std::exp(s0 + i * h);
    const double weight = (i == 0 || i == panels) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += weight * w * f(w);
  }
  return sum * h / 3.0;
}

// Moment by quadrature over [0.05, 1000] w_p plus the w^-5 tail above, which
// for n < 4 is A W^(n-4)/(4-n) to relative 1e-11 (exp(-B/W^4) ~ 1 there).
double quadrature_moment(const Spectrum& s, int n) {
  const double wp = s.peak_omega_rad_s();
  const double top = 1000.0 * wp;
  const double body = log_simpson([&](double w) { return std::pow(w, n) * s.density_m2_s(w); }, 0.05 * wp, top);
  const double tail = s.jonswap_normalisation() * s.base_a_m2_rad4_s4() * std::pow(top, n - 4.0) / (4.0 - n);
  return body + tail;
}

// Quadrature with Simpson panels on a 200000-point grid: relative error < 1e-9.
constexpr double kQuadratureRelTol = 1e-8;

TEST(SeaSpectrum, PiersonMoskowitzWaveHeightLaw) {
  // EVIDENCE-OF: EQ-SEA-1
  // Hs = 2 sqrt(alpha/beta) U^2/g, which docs/physics.md rounds to 0.2092 U^2/g,
  // and w_p = (4 beta/5)^(1/4) g/U = 0.877 g/U.
  constexpr double kRoundedCoefficientRelTol = 5e-4;  // 0.2092 and 0.877 are printed to 4 and 3 digits
  for (double wind_kt : {10.0, 20.0, 35.0, 50.0}) {
    const double u = units::kt_to_m_s(wind_kt);
    const Spectrum pm = Spectrum::pierson_moskowitz(u);
    const double exact = 2.0 * std::sqrt(0.0081 / 0.74) * u * u / kGravity_m_s2;
    EXPECT_REL_CLOSE(pm.significant_height_m(), exact, 1e-14);
    EXPECT_REL_CLOSE(pm.significant_height_m(), 0.2092 * u * u / kGravity_m_s2, kRoundedCoefficientRelTol);
    EXPECT_REL_CLOSE(pm.peak_omega_rad_s(), 0.877 * kGravity_m_s2 / u, kRoundedCoefficientRelTol);
  }
}

TEST(SeaSpectrum, ClosedFormMomentsMatchQuadrature) {
  // EVIDENCE-OF: EQ-SEA-4
  const Spectrum spectra[] = {Spectrum::pierson_moskowitz(units::kt_to_m_s(30.0)),
                              Spectrum::bretschneider_mean_period(4.0, 8.0),
                              Spectrum::bretschneider_peak_period(2.0, 14.0)};
  for (const Spectrum& s : spectra) {
    for (int n = 0; n <= 3; ++n) {
      EXPECT_REL_CLOSE(s.moment(n), quadrature_moment(s, n), kQuadratureRelTol) << "n = " << n;
    }
    // The cumulative form: energy below + above any frequency is m0.
    const double w = 1.3 * s.peak_omega_rad_s();
    EXPECT_REL_CLOSE(s.energy_between_m2(0.0, w) + s.energy_between_m2(w, std::numeric_limits<double>::infinity()),
                     s.variance_m2(), 1e-14);
    EXPECT_REL_CLOSE(s.energy_between_m2(0.7 * s.peak_omega_rad_s(), w),
                     log_simpson([&](double x) { return s.density_m2_s(x); }, 0.7 * s.peak_omega_rad_s(), w),
                     kQuadratureRelTol);
  }
}

TEST(SeaSpectrum, BretschneiderMeanPeriodForm) {
  // EVIDENCE-OF: EQ-SEA-2
  const double hs = 5.0;
  const double t1 = 9.0;
  const Spectrum s = Spectrum::bretschneider_mean_period(hs, t1);
  EXPECT_REL_CLOSE(s.significant_height_m(), hs, 1e-14);
  // T1 = 2 pi m0/m1 from independent quadrature returns the input period.
  EXPECT_REL_CLOSE(2.0 * kPi * quadrature_moment(s, 0) / quadrature_moment(s, 1), t1, kQuadratureRelTol);
  // The ITTC constants of thesis eq. 6.2-6.3 are the derived ones rounded to 3 digits.
  const double b_coefficient = s.base_b_rad4_s4() * std::pow(t1, 4);
  const double a_coefficient = s.base_a_m2_rad4_s4() * std::pow(t1, 4) / (hs * hs);
  EXPECT_NEAR(b_coefficient, 691.0, 0.5);  // 691.17
  EXPECT_NEAR(a_coefficient, 173.0, 0.5);  // 172.79
  // Peak: w_p T1 = (4 B T1^4 / 5)^(1/4) = (4 * 691.17 / 5)^(1/4) = 4.849, i.e. T1 = 0.7718 Tp.
  EXPECT_REL_CLOSE(t1 / (2.0 * kPi / s.peak_omega_rad_s()), 0.7718, 1e-4);
}

TEST(SeaSpectrum, BretschneiderPeakPeriodRelations) {
  // EVIDENCE-OF: EQ-SEA-2
  const double tp = 12.0;
  const Spectrum s = Spectrum::bretschneider_peak_period(3.0, tp);
  // dS/dw changes sign at w_p = 2 pi / Tp.
  const double wp = 2.0 * kPi / tp;
  EXPECT_REL_CLOSE(s.peak_omega_rad_s(), wp, 1e-14);
  EXPECT_GT(s.density_m2_s(wp), s.density_m2_s(wp * (1.0 - 1e-4)));
  EXPECT_GT(s.density_m2_s(wp), s.density_m2_s(wp * (1.0 + 1e-4)));
  // T1 = Tp / ((5/4)^(1/4) Gamma(3/4)) = 0.77177 Tp; T2 = Tp / (5 pi/4)^(1/4) = 0.71041 Tp.
  constexpr double kPrintedRatioRelTol = 1e-4;  // ratios quoted to 5 digits
  EXPECT_REL_CLOSE(s.mean_period_s() / tp, 0.77177, kPrintedRatioRelTol);
  EXPECT_REL_CLOSE(s.zero_crossing_period_s() / tp, 0.71041, kPrintedRatioRelTol);
  EXPECT_REL_CLOSE(2.0 * kPi * std::sqrt(quadrature_moment(s, 0) / quadrature_moment(s, 2)),
                   s.zero_crossing_period_s(), kQuadratureRelTol);
}

TEST(SeaSpectrum, JonswapNormalisationAndLimits) {
  // EVIDENCE-OF: EQ-SEA-3
  const double hs = 6.0;
  const double tp = 11.0;
  // gamma = 1 is Bretschneider by peak period, point by point.
  const Spectrum j1 = Spectrum::jonswap(hs, tp, 1.0);
  const Spectrum b = Spectrum::bretschneider_peak_period(hs, tp);
  for (double w : {0.3, 0.5, 0.571, 0.8, 1.5}) EXPECT_REL_CLOSE(j1.density_m2_s(w), b.density_m2_s(w), 1e-15);
  for (double gamma : {2.0, 3.3, 5.0, 7.0}) {
    const Spectrum j = Spectrum::jonswap(hs, tp, gamma);
    // m0 = Hs^2/16 by independent quadrature of the normalised spectrum.
    EXPECT_REL_CLOSE(quadrature_moment(j, 0), hs * hs / 16.0, kQuadratureRelTol) << "gamma " << gamma;
    // Peak enhancement: S_J(w_p) / S0(w_p) = C(gamma) gamma.
    EXPECT_REL_CLOSE(j.density_m2_s(j.peak_omega_rad_s()) / b.density_m2_s(j.peak_omega_rad_s()),
                     j.jonswap_normalisation() * gamma, 1e-14);
    // DNV-RP-C205 3.5.5.2: C(gamma) ~= 1 - 0.287 ln(gamma), an approximation
    // that DNV does not bound; 2% separates it from C = 1 (a 20-40% error here).
    constexpr double kDnvApproximationRelTol = 0.02;
    EXPECT_REL_CLOSE(j.jonswap_normalisation(), 1.0 - 0.287 * std::log(gamma), kDnvApproximationRelTol);
    // Moments of order 1..3 by the module's quadrature against the test's.
    for (int n = 1; n <= 3; ++n) EXPECT_REL_CLOSE(j.moment(n), quadrature_moment(j, n), 1e-7) << "n " << n;
    // Energy in an interval through the enhanced band.
    const double lo = 0.8 * j.peak_omega_rad_s();
    const double hi = 2.5 * j.peak_omega_rad_s();
    EXPECT_REL_CLOSE(j.energy_between_m2(lo, hi), log_simpson([&](double w) { return j.density_m2_s(w); }, lo, hi),
                     kQuadratureRelTol);
  }
}

TEST(SeaSpectrum, TailFrequencyHoldsTheAskedFraction) {
  // EVIDENCE-OF: EQ-SEA-4
  const Spectrum spectra[] = {Spectrum::pierson_moskowitz(15.0), Spectrum::jonswap(4.0, 10.0, 3.3)};
  for (const Spectrum& s : spectra) {
    for (double f : {1e-2, 1e-3, 1e-6, 0.3}) {
      const double w = s.tail_omega_rad_s(f);
      EXPECT_REL_CLOSE(s.energy_between_m2(w, std::numeric_limits<double>::infinity()), f * s.variance_m2(), 1e-8)
          << "fraction " << f;
    }
  }
}

TEST(SeaSpectrum, SeaStateAddsVariances) {
  // EVIDENCE-OF: EQ-SEA-5
  const Spectrum wind = Spectrum::pierson_moskowitz(units::kt_to_m_s(25.0));
  const Spectrum swell = Spectrum::jonswap(2.0, 15.0, 5.0);
  const SeaState sea = wind_sea_and_swell(wind, kPi, swell, 0.5 * kPi);
  EXPECT_REL_CLOSE(sea.significant_height_m(),
                   std::hypot(wind.significant_height_m(), swell.significant_height_m()), 1e-14);
}

}  // namespace
}  // namespace towdb::sea
