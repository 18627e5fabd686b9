// Golden check of the GEV and Gumbel maximum-likelihood fits against the
// published Port Pirie analysis (tests/data/statistics/portpirie.csv: Coles
// 2001, section 3.4.1, and ismev::gev.fit to 8 digits).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "statistics/statistics.hpp"
#include "test_support.hpp"

namespace towdb::statistics {
namespace {

std::vector<double> read_sea_levels() {
  std::vector<double> levels;  // columns: year, level_m
  for (const auto& f : test::read_csv_rows(test::source_dir() / "tests/data/statistics/portpirie.csv")) {
    levels.push_back(std::stod(f.at(1)));
  }
  return levels;
}

TEST(StatisticsPortPirie, GevMaximumLikelihoodMatchesIsmev) {
  // EVIDENCE-OF: EQ-STAT-7
  // ismev's optim (Nelder-Mead, reltol 1e-8) locates the optimum to ~1e-4 in
  // the parameters; both codes maximise the same likelihood.
  constexpr double kOptimizerAbsTol = 2e-4;
  const std::vector<double> x = read_sea_levels();
  ASSERT_EQ(x.size(), 65u);
  const GevFit fit = fit_gev_ml(x);
  EXPECT_ABS_CLOSE(fit.distribution.location, 3.87474692, kOptimizerAbsTol);
  EXPECT_ABS_CLOSE(fit.distribution.scale, 0.19804120, kOptimizerAbsTol);
  EXPECT_ABS_CLOSE(fit.distribution.shape, -0.05008773, kOptimizerAbsTol);
  EXPECT_ABS_CLOSE(fit.log_likelihood, 4.339058, 1e-6);  // -nllh, printed to 7 digits
  // Coles (2001) p. 60: 10- and 100-year return levels 4.30 m and 4.69 m
  // (F = 1 - 1/m), printed to 0.01 m.
  constexpr double kPrintedRoundingM = 0.005;
  EXPECT_ABS_CLOSE(fit.distribution.quantile(1.0 - 1.0 / 10.0), 4.30, kPrintedRoundingM);
  EXPECT_ABS_CLOSE(fit.distribution.quantile(1.0 - 1.0 / 100.0), 4.69, kPrintedRoundingM);
  EXPECT_FALSE(fit.used_fallback);
}

TEST(StatisticsPortPirie, GumbelIsNestedInGev) {
  // EVIDENCE-OF: EQ-STAT-6
  // The Gumbel is the GEV with xi = 0, so its maximised likelihood is lower,
  // and for xi_hat = -0.05 (s.e. 0.098, Coles 2001) the deviance
  // 2 (l_GEV - l_Gumbel) is small: below the chi^2_1 5% point 3.84.
  const std::vector<double> x = read_sea_levels();
  const GevFit gev = fit_gev_ml(x);
  const GumbelFit gum = fit_gumbel_ml(x);
  EXPECT_LT(gum.log_likelihood, gev.log_likelihood);
  EXPECT_LT(2.0 * (gev.log_likelihood - gum.log_likelihood), 3.84);
  const Gev gumbel_as_gev{gum.distribution.location, gum.distribution.scale, 0.0};
  EXPECT_REL_CLOSE(gum.log_likelihood, gev_log_likelihood(x, gumbel_as_gev), 1e-12);
}

}  // namespace
}  // namespace towdb::statistics
