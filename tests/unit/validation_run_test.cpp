// The validation runner's edges: options validation, days scaling, the
// database-unit -> SI conversion of a calibration row, the resume journal,
// and a failing case that is reported instead of aborting the run.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "test_support.hpp"
#include "validation/validation.hpp"

namespace towdb::validation {
namespace {

// Unit conversions are exact products: only the last bit may differ.
constexpr double kConversionRelTol = 1e-14;

sweep::CalibrationRow thesis_case_201() {
  // Thesis Appendix C run 201: T-ATF tows FFG 7, 9 kt, 20 kt wind, 0 deg,
  // 800 ft fiber, 79,000 lbf, 500 days, 78.7 kips.
  sweep::CalibrationRow r;
  r.case_number = 201;
  r.tug = "T-ATF 166";
  r.tow = "FFG 7";
  r.speed_kt = 9.0;
  r.wind_kt = 20.0;
  r.heading_deg = 0.0;
  r.length_ft = 800.0;
  r.line = "fiber";
  r.mean_tension_lbf = 79000.0;
  r.days = 500;
  r.dynamic_999_kips = 78.7;
  return r;
}

const io::ShipCatalog& catalog() {
  static const io::ShipCatalog c = io::ShipCatalog::load(test::source_dir() / "ships");
  return c;
}

TEST(ValidationRunOptions, RejectsOutOfRangeFields) {
  RunOptions o;
  EXPECT_NO_THROW(o.validate());
  o.days_scale = 0.0;
  EXPECT_THROW(o.validate(), InputError);
  o = RunOptions{};
  o.days_scale = std::nan("");
  EXPECT_THROW(o.validate(), InputError);
  o = RunOptions{};
  o.min_days = 9;  // the case statistics need >= 10 daily maxima
  EXPECT_THROW(o.validate(), InputError);
  o = RunOptions{};
  o.response_frequencies = 4;
  EXPECT_THROW(o.validate(), InputError);
  try {
    o.validate();
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("response_frequencies"), std::string::npos) << e.what();
  }
  // The encounter cutoff: [1, 3] rad/s (the transfer functions end at 3 rad/s).
  o = RunOptions{};
  o.encounter_cutoff_rad_s = 2.0;
  EXPECT_NO_THROW(o.validate());
  o.encounter_cutoff_rad_s = 0.5;
  EXPECT_THROW(o.validate(), InputError);
  o.encounter_cutoff_rad_s = 3.5;
  EXPECT_THROW(o.validate(), InputError);
}

TEST(ValidationRunOne, EncounterCutoffReachesTheRecords) {
  // Diagnostic of issue 17 (thesis eq. 3-22, the 5D grid's 2 rad/s): in head
  // seas at 9 kt a PM sea of 20 kt meets encounter frequencies above 2 rad/s
  // (w = 1.3 rad/s meets w_e = w + w^2 U / g = 2.1 rad/s), so a 2 rad/s cutoff
  // must change the case's outcome; the default (3 rad/s) is the chain's.
  sweep::CalibrationRow r = thesis_case_201();
  r.heading_deg = 180.0;
  RunOptions o;
  o.min_days = 10;
  o.days_scale = 0.001;
  const CaseOutcome full = run_one(r, catalog(), o);
  o.encounter_cutoff_rad_s = 2.0;
  const CaseOutcome cut = run_one(r, catalog(), o);
  ASSERT_EQ(full.status, CaseStatus::kOk) << full.error;
  ASSERT_EQ(cut.status, CaseStatus::kOk) << cut.error;
  EXPECT_NE(full.ours_kips, cut.ours_kips);
  EXPECT_GT(cut.ours_kips, 0.0);
}

TEST(ValidationRunOptions, DaysScaleRoundsAndRespectsTheFloor) {
  RunOptions o;
  sweep::CalibrationRow r = thesis_case_201();
  EXPECT_EQ(simulated_days(r, o), 500);
  o.days_scale = 0.05;
  EXPECT_EQ(simulated_days(r, o), 25);  // 0.05 x 500
  r.days = 300;
  EXPECT_EQ(simulated_days(r, o), 20);  // 15 -> the floor min_days = 20
  o.min_days = 10;
  EXPECT_EQ(simulated_days(r, o), 15);
}

TEST(ValidationCaseInputs, ConvertsDatabaseUnitsToSi) {
  const sweep::CalibrationRow r = thesis_case_201();
  const simulation::CaseInputs in = case_inputs(r, catalog(), 40);
  ASSERT_NE(in.tug, nullptr);
  ASSERT_NE(in.tow, nullptr);
  EXPECT_EQ(in.tug->name, "T-ATF 166");
  EXPECT_EQ(in.tow->name, "FFG 7");
  // 9 kt = 9 x 1852 / 3600 m/s (international knot).
  EXPECT_REL_CLOSE(in.speed_m_s, 9.0 * 1852.0 / 3600.0, kConversionRelTol);
  // 79,000 lbf x 4.4482216152605 N/lbf (exact definition of the pound-force).
  EXPECT_REL_CLOSE(in.mean_tension_n, 79000.0 * 4.4482216152605, kConversionRelTol);
  // 800 ft fiber hawser + the 90 ft chain pendant (ships/towlines) = 890 ft = 271.272 m.
  EXPECT_REL_CLOSE(in.towline.total_length_m(), 890.0 * 0.3048, kConversionRelTol);
  ASSERT_EQ(in.towline.segments.size(), 2u);
  EXPECT_EQ(in.towline.segments.front().component.kind, model::LineKind::kFiber);
  // Fully developed PM sea at 20 kt: Hs = 0.2092 U^2 / g = 2.257 m = 7.40 ft
  // (EQ-SEA-1, docs/physics.md 1.1; the thesis's Table 5-4 gives 7.2 ft, a frequency
  // cut-off explains part of the difference, so the closed form is checked).
  const double u = units::kt_to_m_s(20.0);
  EXPECT_REL_CLOSE(in.sea.significant_height_m(), 0.2092 * u * u / 9.80665, 2e-3);  // alpha, beta to 4 digits
  EXPECT_EQ(in.days, 40);
  EXPECT_EQ(in.seed, 201u);
}

TEST(ValidationCaseInputs, UnknownVesselThrowsInputError) {
  sweep::CalibrationRow r = thesis_case_201();
  r.tow = "Queen Mary";
  EXPECT_THROW(case_inputs(r, catalog(), 40), InputError);
}

TEST(ValidationRunOne, FailingCaseIsReportedNotThrown) {
  // A frigate named as the tug is an input error inside the case: the runner
  // must return status kFailed with the message, never throw.
  sweep::CalibrationRow r = thesis_case_201();
  r.tug = "FFG 7";  // not a tug
  RunOptions o;
  o.min_days = 10;
  o.days_scale = 0.001;
  const CaseOutcome c = run_one(r, catalog(), o);
  EXPECT_EQ(c.status, CaseStatus::kFailed);
  EXPECT_NE(c.error.find("not a tug"), std::string::npos) << c.error;
}

TEST(ValidationJournal, RoundTripsBitExactlyAndSkipsBrokenLines) {
  CaseOutcome a;
  a.row = thesis_case_201();
  a.days_run = 25;
  a.status = CaseStatus::kOk;
  a.ours_kips = 81.23456789012345;
  a.ci_low_kips = 70.1;
  a.ci_high_kips = 0.1 + 0.2;  // not representable in few digits
  a.hs_ft = 5.857;
  a.slack_fraction = 1e-7;
  a.above_breaking = true;
  a.runtime_s = 3.5;
  a.extension_sd_ft = 1.0 / 3.0;
  a.extension_min_ft = -25.6;
  a.extension_max_ft = 10.4;
  a.fit_min_ft = -19.685039370078741;
  a.fit_max_ft = 19.685039370078741;
  a.days_outside_fit = 7;
  CaseOutcome b = a;
  b.row.case_number = 202;
  b.status = CaseStatus::kFailed;
  b.extension_sd_ft = std::numeric_limits<double>::quiet_NaN();  // a failed or database case: unknown
  b.days_outside_fit = -1;
  b.error = "NumericalError: catenary, iteration 3, residual 1e-3, \"x\"\nmore";
  const std::string text = journal_header() + "\n" + journal_line(a) + "\n" + journal_line(b) + "\n" +
                           "203,T-ATF 166,FFG 7,9";  // an interrupted last line
  const std::vector<CaseOutcome> back = parse_journal(text);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].row.case_number, 201);
  EXPECT_EQ(back[0].row.tow, "FFG 7");
  EXPECT_EQ(back[0].row.line, "fiber");
  EXPECT_EQ(back[0].ours_kips, a.ours_kips);
  EXPECT_EQ(back[0].ci_high_kips, a.ci_high_kips);
  EXPECT_EQ(back[0].slack_fraction, a.slack_fraction);
  EXPECT_EQ(back[0].row.dynamic_999_kips, 78.7);
  EXPECT_EQ(back[0].days_run, 25);
  EXPECT_TRUE(back[0].above_breaking);
  EXPECT_EQ(back[0].extension_sd_ft, a.extension_sd_ft);
  EXPECT_EQ(back[0].extension_min_ft, a.extension_min_ft);
  EXPECT_EQ(back[0].fit_max_ft, a.fit_max_ft);
  EXPECT_EQ(back[0].days_outside_fit, 7);
  EXPECT_TRUE(std::isnan(back[1].extension_sd_ft));
  EXPECT_EQ(back[1].days_outside_fit, -1);
  EXPECT_EQ(back[1].status, CaseStatus::kFailed);
  EXPECT_EQ(back[1].error.find(','), std::string::npos);
  EXPECT_EQ(back[1].error.find('\n'), std::string::npos);
}

TEST(ValidationJournal, ResumeReusesMatchingOkCasesOnly) {
  // An ok outcome with the same case number and days is reused verbatim (no
  // run: its tension 12345 kips is not something the physics would give);
  // a different day count is recomputed.
  sweep::CalibrationRow r = thesis_case_201();
  r.tug = "FFG 7";  // would fail if run
  RunOptions o;
  o.days_scale = 0.05;  // 25 days
  CaseOutcome done;
  done.row = r;
  done.days_run = 25;
  done.status = CaseStatus::kOk;
  done.ours_kips = 12345.0;
  int called = 0;
  const auto out = run_all({r}, catalog(), o, {done}, [&](const CaseOutcome&, int, int) { ++called; });
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].ours_kips, 12345.0);
  EXPECT_EQ(called, 0);
  done.days_run = 26;
  const auto again = run_all({r}, catalog(), o, {done}, [&](const CaseOutcome&, int, int) { ++called; });
  EXPECT_EQ(again[0].status, CaseStatus::kFailed);
  EXPECT_EQ(called, 1);
}

}  // namespace
}  // namespace towdb::validation
