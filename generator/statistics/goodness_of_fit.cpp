#include "statistics/goodness_of_fit.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/error.hpp"

namespace towdb::statistics {
namespace {

template <typename Dist>
double anderson_darling_impl(std::span<const double> sample, const Dist& dist) {
  dist.validate();
  require_input(sample.size() >= 2, "anderson-darling: sample size N", static_cast<double>(sample.size()),
                "must be at least 2");
  std::vector<double> x(sample.begin(), sample.end());
  for (double v : x) require_input(std::isfinite(v), "anderson-darling: sample value", v, "must be finite");
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // EQ-STAT-9 with 1-based i -> (2 i + 1) for 0-based i.
    sum += static_cast<double>(2 * i + 1) * (dist.log_cdf(x[i]) + dist.log_sf(x[n - 1 - i]));
  }
  return -static_cast<double>(n) - sum / static_cast<double>(n);
}

template <typename Dist>
double ppcc_impl(std::span<const double> sample, const Dist& dist) {
  dist.validate();
  require_fit_sample(sample, 3, "probability-plot correlation");
  std::vector<double> x(sample.begin(), sample.end());
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  std::vector<double> q(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) q[i] = dist.quantile(static_cast<double>(i + 1) / (n + 1.0));
  double mx = 0.0;
  double mq = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    mq += q[i];
  }
  mx /= n;
  mq /= n;
  double sxx = 0.0;
  double sqq = 0.0;
  double sxq = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sqq += (q[i] - mq) * (q[i] - mq);
    sxq += (x[i] - mx) * (q[i] - mq);
  }
  return sxq / std::sqrt(sxx * sqq);
}

}  // namespace

double anderson_darling(std::span<const double> sample, const Gumbel& dist) {
  return anderson_darling_impl(sample, dist);
}
double anderson_darling(std::span<const double> sample, const Gev& dist) {
  return anderson_darling_impl(sample, dist);
}
double probability_plot_correlation(std::span<const double> sample, const Gumbel& dist) {
  return ppcc_impl(sample, dist);
}
double probability_plot_correlation(std::span<const double> sample, const Gev& dist) {
  return ppcc_impl(sample, dist);
}

}  // namespace towdb::statistics
