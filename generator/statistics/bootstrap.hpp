// Parametric bootstrap confidence interval of a fitted quantile (EQ-STAT-8).
#ifndef TOWDB_STATISTICS_BOOTSTRAP_HPP
#define TOWDB_STATISTICS_BOOTSTRAP_HPP

#include <cstdint>
#include <span>

namespace towdb::statistics {

enum class FitMethod {
  kGumbelMoments,  // EQ-STAT-3 (the thesis' method)
  kGumbelMl,       // EQ-STAT-6
  kGevMl,          // EQ-STAT-7
};

struct BootstrapOptions {
  FitMethod method = FitMethod::kGumbelMoments;  // fit used for the estimate and every replicate
  double level = 0.90;                           // two-sided coverage of the interval, in (0, 1)
  int replicates = 1000;                         // bootstrap samples R; percentile CI needs >= 100
  std::uint64_t seed = 19970601;                 // RandomStream(seed, replicate) per replicate
  int num_threads = 1;                           // towdb::parallel_for threads (<= 0: all); no effect on results
  double max_failed_fraction = 0.05;             // replicates whose refit fails, at most (else NumericalError)

  // Throws InputError unless level in [0.5, 0.999], replicates in [100, 1000000],
  // max_failed_fraction in [0, 0.5].
  void validate() const;
};

struct QuantileInterval {
  double probability = 0.0;  // F of the quantile
  double estimate = 0.0;     // x_F of the fit to the sample [sample unit]
  double lower = 0.0;        // percentile-interval bounds [sample unit]
  double upper = 0.0;
  double level = 0.0;        // coverage asked for
  int replicates_used = 0;   // replicates whose refit succeeded
};

// x_F with a parametric-bootstrap percentile interval. Same inputs -> same
// bits for any num_threads.
QuantileInterval bootstrap_quantile_interval(std::span<const double> sample, double probability,
                                             const BootstrapOptions& options = {});

// x_F of `method` fitted to `sample` (no interval).
double fitted_quantile(std::span<const double> sample, double probability, FitMethod method);

}  // namespace towdb::statistics

#endif  // TOWDB_STATISTICS_BOOTSTRAP_HPP
