#include "seakeeping/gauss_legendre.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::seakeeping {

QuadratureRule gauss_legendre(int n, double lo, double hi) {
  require_input(n >= 1, "gauss_legendre n", n, "at least 1 node");
  constexpr int kMaxNewton = 100;
  constexpr double kRootTolerance = 1e-15;
  QuadratureRule rule;
  rule.nodes.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  const double half = 0.5 * (hi - lo);
  const double mid = 0.5 * (hi + lo);
  const double dn = static_cast<double>(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Tricomi's initial guess for the i-th largest root.
    double t = std::cos(kPi * (static_cast<double>(i) + 0.75) / (dn + 0.5));
    double derivative = 0.0;
    bool converged = false;
    for (int iteration = 0; iteration < kMaxNewton; ++iteration) {
      double p0 = 1.0;
      double p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double dk = static_cast<double>(k);
        const double p2 = ((2.0 * dk - 1.0) * t * p1 - (dk - 1.0) * p0) / dk;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0;
      derivative = dn * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / derivative;
      t -= step;
      if (std::abs(step) < kRootTolerance) {
        converged = true;
        break;
      }
    }
    if (!converged) {
      throw NumericalError("gauss_legendre Newton: iteration " + std::to_string(kMaxNewton) +
                           " did not converge for n = " + std::to_string(n));
    }
    const double w = 2.0 / ((1.0 - t * t) * derivative * derivative);
    const std::size_t a = static_cast<std::size_t>(i);
    const std::size_t b = static_cast<std::size_t>(n - 1 - i);
    rule.nodes[a] = mid - half * t;
    rule.nodes[b] = mid + half * t;
    rule.weights[a] = half * w;
    rule.weights[b] = half * w;
  }
  return rule;
}

const QuadratureRule& cached_gauss_legendre(int n, double lo, double hi) {
  static std::mutex mutex;
  static std::map<std::tuple<int, double, double>, std::unique_ptr<const QuadratureRule>> rules;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = rules[std::make_tuple(n, lo, hi)];
  if (!slot) slot = std::make_unique<const QuadratureRule>(gauss_legendre(n, lo, hi));
  return *slot;
}

}  // namespace towdb::seakeeping
