// Extreme-value distributions and the empirical distribution (EQ-STAT-1,2,4,5
// in statistics/statistics.hpp). Values carry the unit of the sample.
#ifndef TOWDB_STATISTICS_DISTRIBUTIONS_HPP
#define TOWDB_STATISTICS_DISTRIBUTIONS_HPP

#include <span>
#include <vector>

namespace towdb::statistics {

// Gumbel (Type I) distribution of maxima, EQ-STAT-2.
struct Gumbel {
  double location = 0.0;  // u, the mode [sample unit]
  double scale = 1.0;     // 1/alpha > 0 [sample unit]

  // Throws InputError unless location is finite and scale finite and > 0.
  void validate() const;
  double alpha() const { return 1.0 / scale; }  // [1/sample unit]
  double cdf(double x) const;
  double log_cdf(double x) const;  // ln F(x)
  double log_sf(double x) const;   // ln(1 - F(x)), accurate in both tails
  double pdf(double x) const;
  // x_F for 0 < F < 1 (InputError otherwise).
  double quantile(double probability) const;
  double mean() const;
  double variance() const;
  // Distribution of the maximum of `blocks` >= 1 independent maxima (EQ-STAT-4).
  Gumbel for_blocks(double blocks) const;
};

// Generalised extreme value distribution, EQ-STAT-5 (Coles' sign of xi:
// xi > 0 heavy (Frechet) tail, xi < 0 bounded (Weibull) tail).
struct Gev {
  double location = 0.0;  // mu [sample unit]
  double scale = 1.0;     // sigma > 0 [sample unit]
  double shape = 0.0;     // xi [-]

  void validate() const;
  double cdf(double x) const;
  double log_cdf(double x) const;
  double log_sf(double x) const;
  double pdf(double x) const;
  double quantile(double probability) const;
  Gev for_blocks(double blocks) const;
  // Support bound: upper end mu - sigma/xi for xi < 0 (+inf otherwise).
  double upper_end() const;
};

// One point of the empirical distribution (EQ-STAT-1).
struct EmpiricalPoint {
  double value = 0.0;        // x_(i) [sample unit]
  double probability = 0.0;  // F_i = i / (N + 1)
};

// The ordered sample with its plotting positions. Throws InputError for an
// empty sample or non-finite values.
std::vector<EmpiricalPoint> empirical_distribution(std::span<const double> sample);

// Empirical quantile at F, linear in F between plotting positions; F must lie
// in [1/(N+1), N/(N+1)] (InputError otherwise: the sample does not reach it).
double empirical_quantile(std::span<const double> sample, double probability);

// Validates a sample for fitting: at least `min_size` finite values, not all equal.
void require_fit_sample(std::span<const double> sample, std::size_t min_size, const char* what);

}  // namespace towdb::statistics

#endif  // TOWDB_STATISTICS_DISTRIBUTIONS_HPP
