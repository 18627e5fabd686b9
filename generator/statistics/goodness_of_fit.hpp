// Goodness of fit of an extreme-value distribution to a sample (EQ-STAT-9).
#ifndef TOWDB_STATISTICS_GOODNESS_OF_FIT_HPP
#define TOWDB_STATISTICS_GOODNESS_OF_FIT_HPP

#include <span>

#include "statistics/distributions.hpp"

namespace towdb::statistics {

// Anderson-Darling A^2 of the sample against a given distribution [-]
// (N >= 2; +inf if a value lies outside the support).
double anderson_darling(std::span<const double> sample, const Gumbel& dist);
double anderson_darling(std::span<const double> sample, const Gev& dist);

// Probability-plot correlation coefficient between the ordered sample and the
// distribution's quantiles at F_i = i/(N+1) [-], N >= 3. 1 = a straight plot.
double probability_plot_correlation(std::span<const double> sample, const Gumbel& dist);
double probability_plot_correlation(std::span<const double> sample, const Gev& dist);

}  // namespace towdb::statistics

#endif  // TOWDB_STATISTICS_GOODNESS_OF_FIT_HPP
