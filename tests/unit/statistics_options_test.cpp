// Edge cases and options validation of the statistics module: every bad input
// throws towdb::InputError naming the field.
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "statistics/statistics.hpp"
#include "test_support.hpp"

namespace towdb::statistics {
namespace {

using test::expect_input_error;

TEST(StatisticsOptions, SmallOrDegenerateSamplesAreNamedErrors) {
  const std::vector<double> two = {1.0, 2.0};
  const std::vector<double> constant(50, 41.06);
  const std::vector<double> with_nan = {1.0, 2.0, std::numeric_limits<double>::quiet_NaN(), 3.0};
  expect_input_error([&] { fit_gumbel_moments(two); }, "sample size N");
  expect_input_error([&] { fit_gumbel_ml(two); }, "sample size N");
  expect_input_error([&] { fit_gev_ml(std::vector<double>{1, 2, 3, 4, 5}); }, "sample size N");
  expect_input_error([&] { fit_gumbel_moments(constant); }, "sample range");
  expect_input_error([&] { fit_gumbel_ml(constant); }, "sample range");
  expect_input_error([&] { fit_gev_ml(constant); }, "sample range");
  expect_input_error([&] { fit_gumbel_moments(with_nan); }, "sample[2]");
  expect_input_error([&] { gumbel_from_moments(10.0, 0.0); }, "variance");
  expect_input_error([&] { empirical_distribution(std::vector<double>{}); }, "sample size N");
  expect_input_error([&] { empirical_quantile(std::vector<double>{1.0, 2.0, 3.0}, 0.9); }, "probability F");
}

TEST(StatisticsOptions, DistributionArguments) {
  const Gumbel g{1.0, 2.0};
  expect_input_error([&] { g.quantile(1.0); }, "probability F");
  expect_input_error([&] { g.quantile(0.0); }, "probability F");
  expect_input_error([&] { g.for_blocks(0.5); }, "blocks");
  expect_input_error([] { Gumbel{0.0, -1.0}.validate(); }, "gumbel.scale");
  expect_input_error([] { Gev{0.0, 1.0, std::numeric_limits<double>::infinity()}.validate(); }, "gev.shape");
}

TEST(StatisticsOptions, GevShapeBoundIsReportedNotThrown) {
  // Ten maxima drawn from GEV(50, 5, -0.6) (RandomStream(0, 77), rounded to
  // 0.1): with so few points of a bounded tail the likelihood keeps rising as
  // xi -> -1, so the fit stops at the shape bound -0.95 of EQ-STAT-7, says so,
  // and still beats the L-moment and Gumbel fits.
  const std::vector<double> x = {43.5, 52.2, 56.8, 41.2, 50.7, 53.3, 56.5, 53.6, 55.0, 47.1};
  const GevFit fit = fit_gev_ml(x);
  EXPECT_TRUE(fit.shape_at_bound);
  EXPECT_EQ(fit.distribution.shape, -0.95);
  EXPECT_GT(fit.distribution.pdf(56.8), 0.0);  // the support covers the data
  EXPECT_GT(fit.log_likelihood, gev_log_likelihood(x, fit_gev_lmoments(x)));
  EXPECT_GT(fit.log_likelihood, fit_gumbel_ml(x).log_likelihood);
}

TEST(StatisticsOptions, OptionsValidate) {
  MlOptions ml;
  ml.max_iterations = 1;
  expect_input_error([&] { ml.validate(); }, "ml.max_iterations");
  ml = MlOptions{};
  ml.relative_tolerance = 0.0;
  expect_input_error([&] { ml.validate(); }, "ml.relative_tolerance");
  const std::vector<double> x = {1.0, 2.5, 2.0, 4.0, 3.1, 2.2};
  BootstrapOptions b;
  b.level = 1.0;
  expect_input_error([&] { bootstrap_quantile_interval(x, 0.999, b); }, "bootstrap.level");
  b = BootstrapOptions{};
  b.replicates = 10;
  expect_input_error([&] { bootstrap_quantile_interval(x, 0.999, b); }, "bootstrap.replicates");
  b = BootstrapOptions{};
  expect_input_error([&] { bootstrap_quantile_interval(x, 1.5, b); }, "probability F");
}

}  // namespace
}  // namespace towdb::statistics
