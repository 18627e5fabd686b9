#include "sea/spectrum.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::sea {
namespace {

// Pierson & Moskowitz (1964) constants of EQ-SEA-1 [-].
constexpr double kPmAlpha = 0.0081;
constexpr double kPmBeta = 0.74;
// JONSWAP peak widths (Hasselmann et al. 1973) [-].
constexpr double kJonswapSigmaBelowPeak = 0.07;
constexpr double kJonswapSigmaAbovePeak = 0.09;
// Outside [kEnhancedLo, kEnhancedHi] * w_p the JONSWAP enhancement gamma^r is
// 1 to the last bit (r < 1e-21), so the spectrum is exactly C * S0 there.
constexpr double kEnhancedLo = 0.3;
constexpr double kEnhancedHi = 3.0;
// Quadrature grid of numeric moments: log-spaced panels over [lo, hi] * w_p;
// below lo, exp(-1.25 (w_p/w)^4) < 1e-8000 underflows to 0.
constexpr double kMomentLo = 0.05;
constexpr double kMomentHi = 200.0;
constexpr int kMomentPanels = 4000;
// Largest panel width inside the enhanced band, as a fraction of w_p.
constexpr double kEnergyPanelWidth = 0.01;

// 5-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun 25.4.30).
constexpr std::array<double, 5> kGlNode = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                           0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kGlWeight = {0.2369268850561891, 0.4786286704993665,
                                             0.5688888888888889, 0.4786286704993665,
                                             0.2369268850561891};

template <typename F>
double gauss_legendre(const F& f, double lo, double hi) {
  const double half = 0.5 * (hi - lo);
  const double mid = 0.5 * (hi + lo);
  double sum = 0.0;
  for (std::size_t i = 0; i < kGlNode.size(); ++i) sum += kGlWeight[i] * f(mid + half * kGlNode[i]);
  return sum * half;
}

// Gamma(3/4) [-], for the T1 form of EQ-SEA-2 (EQ-SEA-4 with n = 1).
double gamma_three_quarters() { return std::tgamma(0.75); }

}  // namespace

Spectrum::Spectrum(SpectrumKind kind, double a, double b, double gamma)
    : kind_(kind), a_(a), b_(b), gamma_(gamma), peak_omega_rad_s_(std::pow(0.8 * b, 0.25)) {
  // EQ-SEA-4 (n = 0) for the base shape: m0 = A / (4 B).
  const double base_m0 = a_ / (4.0 * b_);
  if (gamma_ != 1.0) {
    norm_ = base_m0 / numeric_moment(0);
  }
  m0_m2_ = base_m0;
}

Spectrum Spectrum::pierson_moskowitz(double wind_speed_m_s) {
  require_in_range("pierson_moskowitz.wind_speed_m_s", wind_speed_m_s, 0.5, 60.0);
  const double g = kGravity_m_s2;
  const double b = kPmBeta * std::pow(g / wind_speed_m_s, 4);
  return Spectrum(SpectrumKind::kPiersonMoskowitz, kPmAlpha * g * g, b, 1.0);
}

Spectrum Spectrum::bretschneider_mean_period(double significant_height_m, double mean_period_s) {
  require_in_range("bretschneider.significant_height_m", significant_height_m, 1e-3, 40.0);
  require_in_range("bretschneider.mean_period_s", mean_period_s, 0.5, 40.0);
  // EQ-SEA-2: T1 = 2 pi m0/m1 = 2 pi B^(-1/4) / Gamma(3/4)  =>  B = (2 pi / (Gamma(3/4) T1))^4.
  const double b = std::pow(2.0 * kPi / (gamma_three_quarters() * mean_period_s), 4);
  const double a = significant_height_m * significant_height_m * b / 4.0;  // m0 = A/(4B) = Hs^2/16
  return Spectrum(SpectrumKind::kBretschneider, a, b, 1.0);
}

Spectrum Spectrum::bretschneider_peak_period(double significant_height_m, double peak_period_s) {
  require_in_range("bretschneider.significant_height_m", significant_height_m, 1e-3, 40.0);
  require_in_range("bretschneider.peak_period_s", peak_period_s, 0.5, 40.0);
  const double wp = 2.0 * kPi / peak_period_s;
  const double b = 1.25 * std::pow(wp, 4);  // dS0/dw = 0 at w^4 = 4B/5
  const double a = significant_height_m * significant_height_m * b / 4.0;
  return Spectrum(SpectrumKind::kBretschneider, a, b, 1.0);
}

Spectrum Spectrum::jonswap(double significant_height_m, double peak_period_s, double gamma) {
  require_in_range("jonswap.significant_height_m", significant_height_m, 1e-3, 40.0);
  require_in_range("jonswap.peak_period_s", peak_period_s, 0.5, 40.0);
  require_in_range("jonswap.gamma", gamma, 1.0, 10.0);
  const double wp = 2.0 * kPi / peak_period_s;
  const double b = 1.25 * std::pow(wp, 4);
  const double a = significant_height_m * significant_height_m * b / 4.0;
  return Spectrum(SpectrumKind::kJonswap, a, b, gamma);
}

double Spectrum::raw_density(double omega_rad_s) const {
  if (!(omega_rad_s > 0.0)) return 0.0;
  const double w4 = omega_rad_s * omega_rad_s * omega_rad_s * omega_rad_s;
  const double base = a_ / (w4 * omega_rad_s) * std::exp(-b_ / w4);
  if (gamma_ == 1.0) return base;
  const double sigma =
      omega_rad_s <= peak_omega_rad_s_ ? kJonswapSigmaBelowPeak : kJonswapSigmaAbovePeak;
  const double d = (omega_rad_s - peak_omega_rad_s_) / (sigma * peak_omega_rad_s_);
  return base * std::pow(gamma_, std::exp(-0.5 * d * d));
}

double Spectrum::density_m2_s(double omega_rad_s) const { return norm_ * raw_density(omega_rad_s); }

double Spectrum::numeric_moment(int n) const {
  // Log-spaced 5-point Gauss-Legendre panels over [kMomentLo, kMomentHi] * w_p,
  // plus the tail above, where exp(-B/w^4) = 1 - B/w^4 + O(1e-10):
  //   int_W^inf A w^(n-5) (1 - B w^-4) dw = A W^(n-4)/(4-n) - A B W^(n-8)/(8-n).
  const double wp = peak_omega_rad_s_;
  const double lo = kMomentLo * wp;
  const double ratio = std::pow(kMomentHi / kMomentLo, 1.0 / kMomentPanels);
  double sum = 0.0;
  double w0 = lo;
  for (int p = 0; p < kMomentPanels; ++p) {
    const double w1 = w0 * ratio;
    sum += gauss_legendre(
        [&](double w) { return std::pow(w, n) * norm_ * raw_density(w); }, w0, w1);
    w0 = w1;
  }
  const double top = w0;
  const double dn = static_cast<double>(n);
  sum += norm_ * (a_ * std::pow(top, dn - 4.0) / (4.0 - dn) -
                  a_ * b_ * std::pow(top, dn - 8.0) / (8.0 - dn));
  return sum;
}

double Spectrum::moment(int n) const {
  require_input(n >= 0 && n <= 3, "spectrum moment order n", n,
                "must be 0, 1, 2 or 3 (m4 and above diverge for a w^-5 tail)");
  if (gamma_ == 1.0) {
    // EQ-SEA-4: m_n = (A/4) B^((n-4)/4) Gamma(1 - n/4).
    const double dn = static_cast<double>(n);
    return 0.25 * a_ * std::pow(b_, (dn - 4.0) / 4.0) * std::tgamma(1.0 - dn / 4.0);
  }
  return n == 0 ? m0_m2_ : numeric_moment(n);
}

double Spectrum::significant_height_m() const { return 4.0 * std::sqrt(m0_m2_); }
double Spectrum::mean_period_s() const { return 2.0 * kPi * m0_m2_ / moment(1); }
double Spectrum::zero_crossing_period_s() const { return 2.0 * kPi * std::sqrt(m0_m2_ / moment(2)); }

double Spectrum::energy_between_m2(double omega_lo_rad_s, double omega_hi_rad_s) const {
  const double lo = std::max(omega_lo_rad_s, 0.0);
  const double hi = omega_hi_rad_s;
  if (!(hi > lo)) return 0.0;
  // EQ-SEA-4 cumulative form of the base shape:
  //   int_0^w S0 = (A / 4B) exp(-B / w^4),
  // differenced as (A/4B) exp(-B/hi^4) * (1 - exp(-(B/lo^4 - B/hi^4))) so that
  // narrow intervals keep their relative precision.
  auto base_energy = [&](double w_lo, double w_hi) {
    if (!(w_hi > w_lo)) return 0.0;
    const double x_hi = std::isinf(w_hi) ? 0.0 : b_ / std::pow(w_hi, 4);
    const double x_lo = w_lo > 0.0 ? b_ / std::pow(w_lo, 4) : std::numeric_limits<double>::infinity();
    return a_ / (4.0 * b_) * std::exp(-x_hi) * -std::expm1(-(x_lo - x_hi));
  };
  if (gamma_ == 1.0) return base_energy(lo, hi);
  const double band_lo = kEnhancedLo * peak_omega_rad_s_;
  const double band_hi = kEnhancedHi * peak_omega_rad_s_;
  double sum = norm_ * (base_energy(lo, std::min(hi, band_lo)) + base_energy(std::max(lo, band_hi), hi));
  const double in_lo = std::max(lo, band_lo);
  const double in_hi = std::min(hi, band_hi);
  if (in_hi > in_lo) {
    const double width = kEnergyPanelWidth * peak_omega_rad_s_;
    const int panels = std::max(1, static_cast<int>(std::ceil((in_hi - in_lo) / width)));
    const double h = (in_hi - in_lo) / panels;
    for (int p = 0; p < panels; ++p) {
      sum += gauss_legendre([&](double w) { return density_m2_s(w); }, in_lo + p * h,
                            p + 1 == panels ? in_hi : in_lo + (p + 1) * h);
    }
  }
  return sum;
}

double Spectrum::tail_omega_rad_s(double fraction) const {
  require_input(fraction > 0.0 && fraction < 1.0, "spectrum tail fraction", fraction,
                "must be strictly between 0 and 1");
  // Above 3 w_p the spectrum is C * S0 exactly, whose tail is
  // C (A/4B) (1 - exp(-B/w^4)) = fraction * m0 with m0 = A/(4B).
  const double scaled = fraction / norm_;
  if (scaled < 1.0) {
    const double w = std::pow(b_ / -std::log1p(-scaled), 0.25);
    if (gamma_ == 1.0 || w >= kEnhancedHi * peak_omega_rad_s_) return w;
  }
  // Bisection on the tail energy (monotone decreasing in w).
  double lo = 0.0;
  double hi = kEnhancedHi * peak_omega_rad_s_;
  const double target = fraction * m0_m2_;
  for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (energy_between_m2(mid, std::numeric_limits<double>::infinity()) > target) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

void SeaState::validate() const {
  require_input(!systems.empty() && systems.size() <= 8, "sea_state.systems (count)",
                static_cast<double>(systems.size()), "must hold 1 to 8 wave systems");
  for (std::size_t i = 0; i < systems.size(); ++i) {
    require_input(std::isfinite(systems[i].heading_rad),
                  "sea_state.systems[" + std::to_string(i) + "].heading_rad",
                  systems[i].heading_rad, "must be finite");
  }
}

double SeaState::variance_m2() const {
  double sum = 0.0;
  for (const WaveSystem& s : systems) sum += s.spectrum.variance_m2();
  return sum;
}

double SeaState::significant_height_m() const { return 4.0 * std::sqrt(variance_m2()); }

SeaState single_system(const Spectrum& spectrum, double heading_rad) {
  return SeaState{{WaveSystem{spectrum, heading_rad}}};
}

SeaState wind_sea_and_swell(const Spectrum& wind_sea, double wind_sea_heading_rad,
                            const Spectrum& swell, double swell_heading_rad) {
  return SeaState{{WaveSystem{wind_sea, wind_sea_heading_rad}, WaveSystem{swell, swell_heading_rad}}};
}

}  // namespace towdb::sea
