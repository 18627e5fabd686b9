// The 9-coefficient polynomial towline model (thesis eq. 3.4, EQ-TOWLINE-11),
// its least-squares fit to dynamics runs (EQ-TOWLINE-12, program t3fer97) and
// the excitation set the runs use (EQ-TOWLINE-14, file input.cas).
// Units: xi [m], xi_dot [m/s], tau [N]; a_mn in N / (m^m (m/s)^n).
#ifndef TOWDB_TOWLINE_POLYNOMIAL_HPP
#define TOWDB_TOWLINE_POLYNOMIAL_HPP

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "towline/shallow_sag.hpp"

namespace towdb::towline {

// tau = sum over 1 <= m + n <= 3 of a_mn xi^m xi_dot^n, stored in the order
// a10, a01, a20, a11, a02, a30, a21, a12, a03.
struct PolynomialCoefficients {
  static constexpr int kCount = 9;
  // (m, n) powers of xi and xi_dot for each stored coefficient.
  static constexpr std::array<std::array<int, 2>, kCount> kPowers = {
      {{1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {3, 0}, {2, 1}, {1, 2}, {0, 3}}};
  std::array<double, kCount> a{};

  double a10() const { return a[0]; }  // [N/m]
  double a01() const { return a[1]; }  // [N s/m]
  double a20() const { return a[2]; }  // [N/m^2]
  double a11() const { return a[3]; }  // [N s/m^2]
  double a02() const { return a[4]; }  // [N s^2/m^2]
  double a30() const { return a[5]; }  // [N/m^3]
  double a21() const { return a[6]; }  // [N s/m^3]
  double a12() const { return a[7]; }  // [N s^2/m^3]
  double a03() const { return a[8]; }  // [N s^3/m^3]

  // EQ-TOWLINE-11, without any slack or breaking-strength limit [N]. Inline:
  // the surge integrator calls it four times per RK4 step. The terms are summed
  // in coefficient order, which fixes the rounding (results are bit-reproducible).
  double evaluate_n(double xi_m, double xi_dot_m_s) const { return evaluate(xi_m, xi_dot_m_s); }
  // The same for any number type with +, * and double * T (the surge
  // integrator's vector lanes: each lane rounds exactly as evaluate_n does).
  // (Forced inline: GCC 12 otherwise calls the vector version out of line.)
  template <typename T>
#if defined(__GNUC__)
  [[gnu::always_inline]]
#endif
  inline T evaluate(T x, T v) const {
    const T m[kCount] = {x, v, x * x, x * v, v * v, x * x * x, x * x * v, x * v * v, v * v * v};
    T tau{};  // +0 in every lane
    for (std::size_t k = 0; k < kCount; ++k) tau += a[k] * m[k];
    return tau;
  }
};

struct PolynomialFit {
  PolynomialCoefficients coefficients;
  double rms_error_n = 0.0;    // over the samples used
  double max_error_n = 0.0;    // largest |polynomial - sample| over the samples used
  double rms_tension_n = 0.0;  // RMS of the samples' tau over the samples used
  int samples_used = 0;
  int samples_excluded = 0;    // tau above max_dynamic_tension_n
};

// How samples taken while the line was slack (TensionSample::slack) enter.
enum class SlackFit {
  // Thesis t3fer97: like any other sample, (P - tau)^2.
  kTwoSided,
  // Beyond the thesis: the simulation limits the model to tau >= -T_min, so
  // a slack sample only asks P <= tau: penalty max(0, P - tau)^2. The fitted
  // quantity is then exactly the limited model max(P, -T_min) the
  // simulation uses (EQ-TOWLINE-12), and the fit is not spent on the flat
  // slack branch. The objective stays convex (active-set iteration).
  kOneSided,
};

// How the fit treats small, slow motions (EQ-TOWLINE-16).
struct SmallMotionFit {
  // a10 held at this value [N/m] instead of fitted (NaN: fitted, as t3fer97).
  // The quasi-static limit: for xi = A sin(w t) with A, w -> 0 the tension is
  // the static catenary's k_s A, and of the nine terms only a10 survives.
  double fixed_a10_n_m = std::numeric_limits<double>::quiet_NaN();
  // Per-sample weights (empty: all 1): row i of the least squares is
  // multiplied by weights[i], so the fit minimises sum (w_i e_i)^2.
  std::vector<double> weights;
};

// EQ-TOWLINE-12: least squares over the samples with tau <= max_dynamic_tension_n
// (breaking strength minus mean tension; +inf keeps all). Columns are scaled by
// the largest |xi| and |xi_dot| before a column-pivoting QR solve. The errors
// reported are those of the model as used: P itself with kTwoSided (thesis),
// max(P, min_dynamic_tension_n) with kOneSided (min_dynamic_tension_n is the
// slack limit -T_min), unweighted. Throws InputError if fewer than 9 samples
// remain, the columns are degenerate or the weights do not match the samples,
// NumericalError if the active set does not settle.
PolynomialFit fit_polynomial(const std::vector<TensionSample>& samples,
                             double max_dynamic_tension_n,
                             double min_dynamic_tension_n = -std::numeric_limits<double>::infinity(),
                             SlackFit slack = SlackFit::kTwoSided, const SmallMotionFit& small = {});

// EQ-TOWLINE-17: amplitude of the first harmonic of P(A sin wt, A w cos wt) [N]:
// sqrt(b^2 + c^2), b = a10 A + (3/4) a30 A^3 + (1/4) a12 A^3 w^2,
// c = a01 A w + (1/4) a21 A^3 w + (3/4) a03 A^3 w^3 (the even terms have none).
double first_harmonic_n(const PolynomialCoefficients& c, double amplitude_m, double omega_rad_s);

// EQ-TOWLINE-18: the Gaussian equivalent linear line of the polynomial. For a
// stationary zero-mean Gaussian extension with variances s2 of xi [m^2] and
// v2 of xi_dot [m^2/s^2] (xi and xi_dot uncorrelated), the k, c minimising
// E[(P - k xi - c xi_dot)^2] are k = E[dP/dxi], c = E[dP/dxi_dot]:
//   k = a10 + 3 a30 s2 + a12 v2,  c = a01 + a21 s2 + 3 a03 v2
// (the even terms have none). Caughey, J. Acoust. Soc. Am. 35 (1963);
// Roberts & Spanos, Random Vibration and Statistical Linearization (1990) ch. 5.
struct EquivalentLinearLine {
  double stiffness_n_m = 0.0;
  double damping_n_s_m = 0.0;
};
EquivalentLinearLine gaussian_equivalent_line(const PolynomialCoefficients& c, double xi_variance_m2,
                                              double xi_dot_variance_m2_s2);

// One prescribed extension p0(t) = amplitude sin(omega t).
struct Excitation {
  double amplitude_m = 0.0;
  double omega_rad_s = 0.0;
};

// EQ-TOWLINE-14. Defaults: 8 frequencies x 7 amplitudes = 56 runs, as the
// thesis's input.cas. Why these values:
//  * frequencies 0.03-1.6 rad/s: the tension model is evaluated at the
//    encounter frequencies of the first-order extension (Pierson-Moskowitz
//    peaks 0.84 rad/s at 20 kt and 0.48 rad/s at 35 kt wind, energy between
//    about 0.7 and 3 peak frequencies, shifted up to about 1.6 rad/s in head
//    seas at 9 kt and folded towards 0 in following seas) and at the slow
//    second-order surge motions (difference frequencies and the surge
//    resonance of a tow on its towline spring, 0.02-0.2 rad/s);
//  * amplitudes up to 6 m: relative tow-point motion in the heaviest
//    database seas (35 kt wind: Hs = 0.2092 U^2/g = 6.9 m, Tp = 13.1 s) and
//    slow-drift surge; capped at a velocity amplitude a w <= 3.5 m/s, the
//    extreme orbital velocity of those seas (significant pi Hs / Tp =
//    1.66 m/s times 2.1, the expected largest of ~7000 Rayleigh amplitudes in
//    a day): at wave frequency the small tug follows the orbital motion while
//    the large tow hardly surges. Each frequency uses the same 7 fractions of
//    its maximum amplitude, from 2% (linear response) to 100%.
struct ExcitationOptions {
  std::vector<double> frequencies_rad_s = {0.03, 0.07, 0.15, 0.3, 0.5, 0.75, 1.1, 1.6};
  std::vector<double> amplitude_fractions = {0.02, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0};
  double max_amplitude_m = 6.0;   // largest extension amplitude at low frequency
  double max_velocity_m_s = 3.5;  // amplitude x omega never exceeds this
  void validate() const;
};

// Frequency-major list: for each frequency, the amplitudes in increasing order.
std::vector<Excitation> excitation_set(const ExcitationOptions& options = {});

}  // namespace towdb::towline

#endif  // TOWDB_TOWLINE_POLYNOMIAL_HPP
