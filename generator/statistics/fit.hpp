// Fitting extreme-value distributions to a sample of maxima (EQ-STAT-3, 6, 7).
#ifndef TOWDB_STATISTICS_FIT_HPP
#define TOWDB_STATISTICS_FIT_HPP

#include <span>

#include "statistics/distributions.hpp"

namespace towdb::statistics {

// EQ-STAT-3 from a given mean and variance (variance > 0) [sample unit, unit^2].
Gumbel gumbel_from_moments(double mean, double variance);
// EQ-STAT-3 from a sample (N >= 3, not constant); unbiased variance (N - 1).
Gumbel fit_gumbel_moments(std::span<const double> sample);

struct MlOptions {
  int max_iterations = 200;          // Newton iterations before NumericalError
  double relative_tolerance = 1e-10;  // stop when every step is below this (standardised units)

  // Throws InputError unless max_iterations in [5, 10000] and tolerance in [1e-15, 1e-3].
  void validate() const;
};

struct GumbelFit {
  Gumbel distribution;
  double log_likelihood = 0.0;  // at the optimum, in the sample's units
  int iterations = 0;
};

struct GevFit {
  Gev distribution;
  double log_likelihood = 0.0;
  int iterations = 0;
  bool used_fallback = false;  // Nelder-Mead restart was needed
  bool shape_at_bound = false;  // xi ended at -0.95 or 1.5 (EQ-STAT-7): treat the fit with suspicion
};

// EQ-STAT-6. N >= 3, not constant. Throws NumericalError if the root is not found.
GumbelFit fit_gumbel_ml(std::span<const double> sample, const MlOptions& options = {});
// EQ-STAT-7. N >= 10 (three parameters need a real sample), not constant.
GevFit fit_gev_ml(std::span<const double> sample, const MlOptions& options = {});
// Hosking, Wallis & Wood (1985) L-moment estimates (the ML starting point), N >= 3.
Gev fit_gev_lmoments(std::span<const double> sample);

// Log-likelihoods of a sample (for tests and model comparison).
double gumbel_log_likelihood(std::span<const double> sample, const Gumbel& dist);
double gev_log_likelihood(std::span<const double> sample, const Gev& dist);

}  // namespace towdb::statistics

#endif  // TOWDB_STATISTICS_FIT_HPP
