#include "propulsion/bseries.hpp"

#include <cmath>
#include <string>

#include "common/error.hpp"

namespace towdb::propulsion {

namespace {

// x^k for the small non-negative integer exponents of the series (k <= 6);
// a plain product keeps results identical on every platform.
double int_power(double x, int k) {
  double result = 1.0;
  for (int i = 0; i < k; ++i) result *= x;
  return result;
}

enum class Derivative { kNone, kAdvanceRatio, kPitchRatio };

// Sum of C J^s (P/D)^t (A_E/A_0)^u Z^v, or of its partial derivative, in the
// table's fixed order (deterministic).
double evaluate(std::span<const BSeriesTerm> terms, const BSeriesBlades& b, double j, double pd,
                Derivative derivative) {
  const double z = static_cast<double>(b.blades);
  double sum = 0.0;
  for (const BSeriesTerm& term : terms) {
    double j_factor = int_power(j, term.j_power);
    double pd_factor = int_power(pd, term.pitch_power);
    if (derivative == Derivative::kAdvanceRatio) {
      if (term.j_power == 0) continue;
      j_factor = term.j_power * int_power(j, term.j_power - 1);
    } else if (derivative == Derivative::kPitchRatio) {
      if (term.pitch_power == 0) continue;
      pd_factor = term.pitch_power * int_power(pd, term.pitch_power - 1);
    }
    sum += term.coefficient * j_factor * pd_factor * int_power(b.expanded_area_ratio, term.area_power) *
           int_power(z, term.blade_power);
  }
  return sum;
}

}  // namespace

void BSeriesBlades::validate() const {
  require_in_range("propulsion: B-series blades", blades, kBSeriesBladesMin, kBSeriesBladesMax);
  require_in_range("propulsion: B-series expanded_area_ratio", expanded_area_ratio,
                   kBSeriesAreaRatioMin, kBSeriesAreaRatioMax);
}

double bseries_kt(const BSeriesBlades& b, double j, double pd) {
  return evaluate(bseries_kt_terms(), b, j, pd, Derivative::kNone);
}

double bseries_kq(const BSeriesBlades& b, double j, double pd) {
  return evaluate(bseries_kq_terms(), b, j, pd, Derivative::kNone);
}

double bseries_dkt_dj(const BSeriesBlades& b, double j, double pd) {
  return evaluate(bseries_kt_terms(), b, j, pd, Derivative::kAdvanceRatio);
}

double bseries_dkt_dpitch(const BSeriesBlades& b, double j, double pd) {
  return evaluate(bseries_kt_terms(), b, j, pd, Derivative::kPitchRatio);
}

double bseries_dkq_dj(const BSeriesBlades& b, double j, double pd) {
  return evaluate(bseries_kq_terms(), b, j, pd, Derivative::kAdvanceRatio);
}

double solve_bseries_pitch_ratio(const BSeriesBlades& b, double j, double kt_target, double pitch_lo,
                                 double pitch_hi) {
  constexpr double kResidualTol = 1e-13;  // K_T is O(0.1-0.6): ~12 significant digits
  constexpr int kMaxIterations = 100;     // bisection alone halves [0.5, 1.4] to 1e-27 in 90
  require_input(std::isfinite(j) && j >= 0.0, "propulsion: advance ratio J", j, "must be finite and >= 0");
  require_input(std::isfinite(kt_target), "propulsion: target K_T", kt_target, "must be finite");
  require_input(pitch_lo < pitch_hi, "propulsion: pitch bracket low end", pitch_lo,
                "must be below the high end " + format_value(pitch_hi));
  double lo = pitch_lo;
  double hi = pitch_hi;
  double f_lo = bseries_kt(b, j, lo) - kt_target;
  double f_hi = bseries_kt(b, j, hi) - kt_target;
  require_input(f_lo <= 0.0 && f_hi >= 0.0, "propulsion: target K_T", kt_target,
                "must lie between K_T at P/D = " + format_value(pitch_lo) + " (" +
                    format_value(f_lo + kt_target) + ") and at P/D = " + format_value(pitch_hi) +
                    " (" + format_value(f_hi + kt_target) + ")");
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  // Start from the secant (regula falsi) point; then Newton steps, replaced
  // by bisection whenever they leave the bracket.
  double x = lo - f_lo * (hi - lo) / (f_hi - f_lo);
  double residual = 0.0;
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    residual = bseries_kt(b, j, x) - kt_target;
    if (std::abs(residual) <= kResidualTol) return x;
    if (residual < 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    const double slope = bseries_dkt_dpitch(b, j, x);
    double next = x - residual / slope;
    if (!(slope > 0.0) || !(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == x) return x;  // the bracket has shrunk to one double
    x = next;
  }
  throw NumericalError("propulsion: B-series pitch solve (bracketed Newton) did not converge after " +
                       std::to_string(kMaxIterations) + " iterations: residual K_T - target = " +
                       format_value(residual) + " at P/D = " + format_value(x) +
                       ", J = " + format_value(j));
}

}  // namespace towdb::propulsion
