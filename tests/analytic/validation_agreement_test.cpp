// Agreement measures of the thesis-database validation (validation.hpp
// EQ-VALIDATION-1..5) against closed forms and a published worked example.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "test_support.hpp"
#include "validation/validation.hpp"

namespace towdb::validation {
namespace {

// Exact arithmetic on small integers and ratios: only rounding of the last bit.
constexpr double kExactRelTol = 1e-14;

// EVIDENCE-OF: EQ-VALIDATION-3
TEST(ValidationAgreement, SpearmanMatchesPublishedWorkedExample) {
  // Worked example of Spearman's coefficient (IQ vs hours of TV per week,
  // 10 people, no ties) in the Wikipedia article "Spearman's rank correlation
  // coefficient": sum d^2 = 194, rho = 1 - 6*194 / (10*99) = -29/165 = -0.175757...
  const std::vector<double> iq = {106, 100, 86, 101, 99, 103, 97, 113, 112, 110};
  const std::vector<double> tv = {7, 27, 2, 50, 28, 29, 20, 12, 6, 17};
  EXPECT_REL_CLOSE(spearman_rank_correlation(iq, tv), -29.0 / 165.0, kExactRelTol);
}

// EVIDENCE-OF: EQ-VALIDATION-3
TEST(ValidationAgreement, SpearmanIsOneForAnyIncreasingMapAndMinusOneForDecreasing) {
  // Rank correlation sees only the order: y = exp(x) is +1, y = -x^3 is -1,
  // while the Pearson correlation of these pairs is below 1.
  std::vector<double> x, up, down;
  for (int i = 0; i < 12; ++i) {
    x.push_back(0.7 * i - 3.0);
    up.push_back(std::exp(x.back()));
    down.push_back(-x.back() * x.back() * x.back());
  }
  EXPECT_REL_CLOSE(spearman_rank_correlation(x, up), 1.0, kExactRelTol);
  EXPECT_REL_CLOSE(spearman_rank_correlation(x, down), -1.0, kExactRelTol);
}

// EVIDENCE-OF: EQ-VALIDATION-3
TEST(ValidationAgreement, TiesGetAverageRanksAndPearsonOfRanks) {
  // x = (1, 2, 2, 3) has ranks (1, 2.5, 2.5, 4); y = (1, 2, 3, 4) ranks (1, 2, 3, 4).
  // Deviations from 2.5: (-1.5, 0, 0, 1.5) and (-1.5, -0.5, 0.5, 1.5):
  // sxy = 4.5, sxx = 4.5, syy = 5 -> rho = 4.5 / sqrt(22.5) = 3 / sqrt(10).
  const std::vector<double> x = {1, 2, 2, 3};
  const std::vector<double> y = {1, 2, 3, 4};
  const std::vector<double> r = average_ranks(x);
  EXPECT_EQ(r, (std::vector<double>{1.0, 2.5, 2.5, 4.0}));
  EXPECT_REL_CLOSE(spearman_rank_correlation(x, y), 3.0 / std::sqrt(10.0), kExactRelTol);
}

// EVIDENCE-OF: EQ-VALIDATION-2
TEST(ValidationAgreement, MedianOfOddAndEvenSamples) {
  EXPECT_EQ(median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_THROW(median({}), InputError);
}

// EVIDENCE-OF: EQ-VALIDATION-1
// EVIDENCE-OF: EQ-VALIDATION-4
// EVIDENCE-OF: EQ-VALIDATION-5
TEST(ValidationAgreement, RatiosSharesAndGeometricMean) {
  // Ratios 1, 1.5, 1/1.5, 2, 0.4: within 1.5 are the first three (the bounds
  // are inclusive), within 2 the first four. Geometric mean = (1 * 1.5 / 1.5
  // * 2 * 0.4)^(1/5) = 0.8^(1/5); median ratio = 1.
  const std::vector<double> thesis = {100.0, 100.0, 150.0, 50.0, 250.0};
  const std::vector<double> ours = {100.0, 150.0, 100.0, 100.0, 100.0};
  const Agreement a = agreement("test", ours, thesis);
  EXPECT_EQ(a.count, 5);
  EXPECT_REL_CLOSE(a.median_ratio, 1.0, kExactRelTol);
  EXPECT_REL_CLOSE(a.within_1_5, 3.0 / 5.0, kExactRelTol);
  EXPECT_REL_CLOSE(a.within_2, 4.0 / 5.0, kExactRelTol);
  EXPECT_REL_CLOSE(a.geometric_mean_ratio, std::pow(0.8, 0.2), kExactRelTol);
  const double l15 = std::log(1.5), l2 = std::log(2.0), l04 = std::log(0.4);
  EXPECT_REL_CLOSE(a.log_rms, std::sqrt((2 * l15 * l15 + l2 * l2 + l04 * l04) / 5.0), kExactRelTol);
}

TEST(ValidationAgreement, RejectsNonPositiveAndMismatchedSamples) {
  EXPECT_THROW(agreement("x", std::vector<double>{1.0, 0.0}, std::vector<double>{1.0, 1.0}), InputError);
  EXPECT_THROW(agreement("x", std::vector<double>{1.0}, std::vector<double>{1.0, 1.0}), InputError);
  EXPECT_THROW(spearman_rank_correlation(std::vector<double>{1.0}, std::vector<double>{1.0}), InputError);
}

// EVIDENCE-OF: EQ-VALIDATION-4
TEST(ValidationAgreement, ReportSplitsAtTheThesisValidityLimitAndChecksTargets) {
  // Four valid cases with ratios 1, 1, 1.2, 3 and one case above 300 kips with
  // ratio 0.5: the valid summary must not see the 0.5 (thesis 6.2 limit).
  const auto make = [](int n, const char* tow, double thesis, double ours) {
    CaseOutcome c;
    c.row.case_number = n;
    c.row.tug = "T-ATF 166";
    c.row.tow = tow;
    c.row.line = "wire";
    c.row.heading_deg = 0.0;
    c.row.dynamic_999_kips = thesis;
    c.ours_kips = ours;
    c.status = CaseStatus::kOk;
    return c;
  };
  std::vector<CaseOutcome> cases = {make(1, "FFG 7", 100, 100), make(2, "FFG 7", 50, 50), make(3, "YRBM", 200, 240),
                                    make(4, "YRBM", 20, 60), make(5, "LHA 1", 400, 200)};
  CaseOutcome failed = make(6, "AE 26", 80, 0);
  failed.status = CaseStatus::kFailed;
  cases.push_back(failed);
  const Report rep = make_report(cases);
  EXPECT_EQ(rep.failed, 1);
  EXPECT_EQ(rep.valid.count, 4);
  EXPECT_EQ(rep.above_limit.count, 1);
  EXPECT_REL_CLOSE(rep.valid.median_ratio, 1.1, kExactRelTol);
  EXPECT_REL_CLOSE(rep.valid.within_1_5, 0.75, kExactRelTol);
  EXPECT_REL_CLOSE(rep.above_limit.median_ratio, 0.5, kExactRelTol);
  EXPECT_TRUE(rep.median_ok);
  EXPECT_TRUE(rep.within_ok);
  ASSERT_EQ(rep.by_tow.size(), 2u);  // FFG 7 and YRBM (LHA 1 is above the limit)
  EXPECT_EQ(rep.by_tow[0].group, "tow FFG 7");
  EXPECT_REL_CLOSE(rep.by_tow[1].median_ratio, 2.1, kExactRelTol);  // (1.2 + 3) / 2
}

TEST(ValidationAgreement, ExtensionTableGroupsSimulatedCasesByLineAndHeading) {
  // Three simulated wire cases at 0 deg and one fiber case at 180 deg, plus a
  // database answer (extension unknown) that the table must leave out.
  const auto make = [](int n, const char* line, double heading, double sd, double lo, double hi, int outside,
                       double slack) {
    CaseOutcome c;
    c.row.case_number = n;
    c.row.line = line;
    c.row.heading_deg = heading;
    c.row.dynamic_999_kips = 100.0;
    c.ours_kips = 50.0 * n;
    c.status = CaseStatus::kOk;
    c.extension_sd_ft = sd;
    c.extension_min_ft = lo;
    c.extension_max_ft = hi;
    c.fit_min_ft = -20.0;
    c.fit_max_ft = 10.0;
    c.days_outside_fit = outside;
    c.slack_fraction = slack;
    return c;
  };
  std::vector<CaseOutcome> cases = {make(1, "wire", 0.0, 1.0, -5.0, 4.0, 0, 0.0),    // reach max(0.25, 0.4)
                                    make(2, "wire", 0.0, 3.0, -30.0, 6.0, 4, 0.01),  // reach max(1.5, 0.6)
                                    make(3, "wire", 0.0, 2.0, -2.0, 9.0, 0, 0.0),    // reach max(0.1, 0.9)
                                    make(4, "fiber", 180.0, 7.0, -10.0, 20.0, 9, 0.0)};
  CaseOutcome from_database;
  from_database.row.case_number = 5;
  from_database.row.line = "wire";
  from_database.row.dynamic_999_kips = 100.0;
  from_database.ours_kips = 90.0;
  from_database.status = CaseStatus::kOk;  // extension NaN, days_outside_fit -1 by default
  cases.push_back(from_database);
  const Report rep = make_report(cases);
  ASSERT_EQ(rep.extension_by_line_heading.size(), 2u);
  const auto& fiber = rep.extension_by_line_heading[0];  // "fiber 180 deg" sorts before "wire 000 deg"
  const auto& wire = rep.extension_by_line_heading[1];
  EXPECT_EQ(fiber.group, "fiber 180 deg");
  EXPECT_EQ(fiber.count, 1);
  EXPECT_REL_CLOSE(fiber.median_reach, 2.0, kExactRelTol);
  EXPECT_EQ(wire.group, "wire 000 deg");
  EXPECT_EQ(wire.count, 3);                                  // not the database's answer
  EXPECT_REL_CLOSE(wire.median_ratio, 1.0, kExactRelTol);    // 0.5, 1.0, 1.5
  EXPECT_REL_CLOSE(wire.median_sd_ft, 2.0, kExactRelTol);
  EXPECT_REL_CLOSE(wire.median_reach, 0.9, kExactRelTol);    // 0.4, 1.5, 0.9
  EXPECT_EQ(wire.cases_outside_fit, 1);
  EXPECT_EQ(wire.cases_slack, 1);
  EXPECT_NE(report_markdown(rep, "note").find("| wire 000 deg | 3 | 1.00 | 2.0 | 0.90 | 1 | 1 |"), std::string::npos);
  // Only database answers: no extension table at all.
  const Report db = make_report({from_database});
  EXPECT_TRUE(db.extension_by_line_heading.empty());
  EXPECT_EQ(report_markdown(db, "note").find("extension by line"), std::string::npos);
}

}  // namespace
}  // namespace towdb::validation
