// The whole chain held to its measured agreement with the thesis database
// (issue 17's regression floor; label "validation", not in the default suite).
//
// Runs all 240 calibration cases of tests/data/validation/
// appendix_c_calibration.csv (thesis Appendix C) through `towdb validate` with
// the run of docs/validation.md: days = max(60, round(0.2 x the thesis's
// days)), seed = thesis case number. The run is deterministic for any thread
// count, so its measures are reproducible; this test asserts they have not
// fallen below the values the chain reached (docs/validation.md, "Where the
// chain stands"), so that no later change can lose agreement silently. A
// change that improves them should raise the floors here in the same commit.
//
// Environment: TOWDB_VALIDATION_THREADS (default 0: all cores; no effect on
// the numbers), TOWDB_VALIDATION_OUT (keep the output there; an existing
// cases.csv there is resumed).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "validation/validation.hpp"

namespace towdb::test {
namespace {

// The measures of the default chain on this run (version 0.4.0, with the surge
// diffraction force; measured 2026-12-07 at commit 0cd6235, 398 s on 2 cores;
// docs/validation.md), cases with the thesis tension <= 300 kips. Version 0.3.0
// reached 0.756, 56 %, 0.59 and 0.825 / 0.789 / 1.102 / 1.325.
constexpr double kMeasuredSpearman = 0.767;
constexpr double kMeasuredWithin15 = 0.57;
constexpr double kMeasuredWireSpearman = 0.617;
// Median ratio ours / thesis at 0, 60, 120 and 180 deg.
constexpr double kMeasuredHeadingMedian[] = {0.969, 0.878, 1.145, 1.338};

// Slack for a floor: the daily maxima of a 60-2,000-day nonlinear simulation
// move in their last digits with the compiler and libm, which moves a case's
// Type I fit by well under 1 % and these sample measures (187 cases) by a few
// thousandths; a change of the physics that matters moves them by hundredths
// or more (docs/validation.md: the leads that moved the answers moved a
// heading median by 0.03 to 3.4 and Spearman by 0.01 to 0.1).
constexpr double kSpearmanSlack = 0.02;
constexpr double kWithinSlack = 0.03;
// The wire lines are 71 of the 187 cases: one case's rank moves more.
constexpr double kWireSpearmanSlack = 0.03;
// On |ln(median ratio)|: the distance to agreement may not grow by more
// than 5 % of the ratio.
constexpr double kLogMedianSlack = 0.05;

TEST(ValidationAgreementFloor, TheChainKeepsItsMeasuredAgreementWithTheThesis) {
  // EVIDENCE-OF: issue 17 (the calibration measures as a floor), EQ-VALIDATION-2..4
  const auto table = source_dir() / "tests" / "data" / "validation" / "appendix_c_calibration.csv";
  ASSERT_TRUE(std::filesystem::exists(table)) << table;
  const bool keep = std::getenv("TOWDB_VALIDATION_OUT") != nullptr;
  const std::filesystem::path out =
      keep ? std::filesystem::path(env_or("TOWDB_VALIDATION_OUT", "")) : make_temp_dir("towdb-floor") / "out";
  const CommandResult r = run_towdb("validate --cases '" + table.string() + "' --out '" + out.string() +
                                    "' --days-scale 0.2 --min-days 60 --no-plot --threads " +
                                    env_or("TOWDB_VALIDATION_THREADS", "0"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const validation::Report report = validation::make_report(validation::parse_journal(read_text(out / "cases.csv")));
  std::cout << read_text(out / "report.md");

  EXPECT_EQ(report.outcomes.size(), 240u);
  EXPECT_EQ(report.failed, 0);
  EXPECT_GE(report.valid.spearman, kMeasuredSpearman - kSpearmanSlack);
  EXPECT_GE(report.valid.within_1_5, kMeasuredWithin15 - kWithinSlack);
  bool wire_seen = false;
  for (const auto& g : report.by_line) {
    if (g.group.find("wire") == std::string::npos) continue;
    wire_seen = true;
    EXPECT_GE(g.spearman, kMeasuredWireSpearman - kWireSpearmanSlack) << g.group;
  }
  EXPECT_TRUE(wire_seen);
  ASSERT_EQ(report.by_heading.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& g = report.by_heading[i];
    EXPECT_LE(std::abs(std::log(g.median_ratio)), std::abs(std::log(kMeasuredHeadingMedian[i])) + kLogMedianSlack)
        << g.group << ": median ratio " << g.median_ratio;
  }
  if (!keep) std::filesystem::remove_all(out.parent_path());
}

}  // namespace
}  // namespace towdb::test
