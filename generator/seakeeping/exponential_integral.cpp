#include "seakeeping/exponential_integral.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::seakeeping {

namespace {

using Complex = std::complex<double>;

// Above this many e-folds of cancellation the series is abandoned for the
// continued fraction: e^12 ~ 1.6e5 leaves about 11 significant digits.
constexpr double kSeriesCancellationLimit = 12.0;
// Below this modulus the series always wins (few terms, no cancellation).
constexpr double kSeriesAlwaysRadius = 1.0;
constexpr int kMaxSeriesTerms = 2000;
constexpr int kMaxFractionTerms = 20000;
constexpr double kRelativeTolerance = 1e-16;
// The stopping tests compare squared moduli (std::norm) against this: the same
// test as |a| <= tol |b| without two hypot calls a term, which took a third of
// the strip theory's time (docs/performance.md).
constexpr double kRelativeToleranceSquared = kRelativeTolerance * kRelativeTolerance;
constexpr double kTiny = 1e-300;

Complex e1_series(Complex w) {
  // -gamma - ln w - sum (-w)^n / (n n!)
  Complex term(1.0, 0.0);  // (-w)^n / n!
  Complex sum(0.0, 0.0);
  for (int n = 1; n <= kMaxSeriesTerms; ++n) {
    term *= -w / static_cast<double>(n);
    const Complex contribution = term / static_cast<double>(n);
    sum += contribution;
    if (std::norm(contribution) <= kRelativeToleranceSquared * std::norm(sum)) {
      return -kEulerGamma - std::log(w) - sum;
    }
  }
  throw NumericalError("exponential integral series: iteration " + std::to_string(kMaxSeriesTerms) +
                       ", residual term not below tolerance for |w| = " + format_value(std::abs(w)));
}

// e^w E1(w) by the even continued fraction, modified Lentz algorithm.
Complex scaled_e1_fraction(Complex w) {
  Complex b = w + 1.0;
  Complex c = 1.0 / kTiny;
  Complex d = 1.0 / b;
  Complex h = d;
  for (int i = 1; i <= kMaxFractionTerms; ++i) {
    const double a = -static_cast<double>(i) * static_cast<double>(i);
    b += 2.0;
    d = 1.0 / (a * d + b);
    c = b + a / c;
    const Complex delta = c * d;
    h *= delta;
    if (std::norm(delta - 1.0) <= kRelativeToleranceSquared) return h;
  }
  throw NumericalError("exponential integral continued fraction: iteration " +
                       std::to_string(kMaxFractionTerms) + " did not converge for w = (" +
                       format_value(w.real()) + ", " + format_value(w.imag()) + ")");
}

bool use_series(Complex w) {
  const double modulus = std::abs(w);
  return modulus <= kSeriesAlwaysRadius || modulus + w.real() <= kSeriesCancellationLimit;
}

}  // namespace

Complex scaled_exponential_integral(Complex w) {
  if (w == Complex(0.0, 0.0)) {
    throw InputError("exponential integral argument = 0: E1 is singular there");
  }
  if (use_series(w)) return std::exp(w) * e1_series(w);
  return scaled_e1_fraction(w);
}

Complex exponential_integral_e1(Complex w) {
  if (w == Complex(0.0, 0.0)) {
    throw InputError("exponential integral argument = 0: E1 is singular there");
  }
  if (use_series(w)) return e1_series(w);
  return std::exp(-w) * scaled_e1_fraction(w);
}

}  // namespace towdb::seakeeping
