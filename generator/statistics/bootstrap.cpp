#include "statistics/bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "common/random.hpp"
#include "statistics/fit.hpp"

namespace towdb::statistics {
namespace {

// Either fitted distribution, to draw replicates from and to take quantiles of.
struct Fitted {
  bool gev = false;
  Gumbel gumbel;
  Gev gev_dist;
  double quantile(double f) const { return gev ? gev_dist.quantile(f) : gumbel.quantile(f); }
};

Fitted fit(std::span<const double> sample, FitMethod method) {
  Fitted out;
  switch (method) {
    case FitMethod::kGumbelMoments:
      out.gumbel = fit_gumbel_moments(sample);
      break;
    case FitMethod::kGumbelMl:
      out.gumbel = fit_gumbel_ml(sample).distribution;
      break;
    case FitMethod::kGevMl:
      out.gev = true;
      out.gev_dist = fit_gev_ml(sample).distribution;
      break;
  }
  return out;
}

// Hyndman & Fan (1996) type-7 quantile of sorted values.
double type7_quantile(const std::vector<double>& sorted, double p) {
  const double h = (static_cast<double>(sorted.size()) - 1.0) * p;
  const std::size_t lo = static_cast<std::size_t>(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[lo + 1] - sorted[lo]);
}

}  // namespace

void BootstrapOptions::validate() const {
  require_in_range("bootstrap.level", level, 0.5, 0.999);
  require_input(replicates >= 100 && replicates <= 1000000, "bootstrap.replicates", replicates,
                "must be an integer from 100 to 1000000");
  require_in_range("bootstrap.max_failed_fraction", max_failed_fraction, 0.0, 0.5);
}

double fitted_quantile(std::span<const double> sample, double probability, FitMethod method) {
  return fit(sample, method).quantile(probability);
}

QuantileInterval bootstrap_quantile_interval(std::span<const double> sample, double probability,
                                             const BootstrapOptions& options) {
  options.validate();
  require_input(probability > 0.0 && probability < 1.0, "bootstrap probability F", probability,
                "must be strictly between 0 and 1");
  const Fitted base = fit(sample, options.method);
  const std::size_t n = sample.size();
  const std::size_t r = static_cast<std::size_t>(options.replicates);
  std::vector<double> estimates(r, 0.0);
  std::vector<unsigned char> ok(r, 0);
  // EQ-STAT-8: one independent stream per replicate, outputs per index only.
  parallel_for(0, static_cast<std::int64_t>(r), options.num_threads, [&](std::int64_t i) {
    RandomStream stream(options.seed, static_cast<std::uint64_t>(i));
    std::vector<double> draw(n);
    for (double& x : draw) x = base.quantile(stream.uniform_open01());
    try {
      estimates[static_cast<std::size_t>(i)] = fit(draw, options.method).quantile(probability);
      ok[static_cast<std::size_t>(i)] = 1;
    } catch (const NumericalError&) {
      ok[static_cast<std::size_t>(i)] = 0;
    }
  });
  std::vector<double> good;
  good.reserve(r);
  for (std::size_t i = 0; i < r; ++i) {
    if (ok[i] != 0) good.push_back(estimates[i]);
  }
  const double failed = static_cast<double>(r - good.size()) / static_cast<double>(r);
  if (failed > options.max_failed_fraction) {
    throw NumericalError("bootstrap refit: " + std::to_string(r - good.size()) + " of " + std::to_string(r) +
                         " replicate fits failed (fraction " + format_value(failed) +
                         " > bootstrap.max_failed_fraction)");
  }
  std::sort(good.begin(), good.end());
  QuantileInterval out;
  out.probability = probability;
  out.estimate = base.quantile(probability);
  out.lower = type7_quantile(good, 0.5 * (1.0 - options.level));
  out.upper = type7_quantile(good, 0.5 * (1.0 + options.level));
  out.level = options.level;
  out.replicates_used = static_cast<int>(good.size());
  return out;
}

}  // namespace towdb::statistics
