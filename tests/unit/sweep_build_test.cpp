// The database builder (generator/sweep/build/build.hpp) with the closed-form test
// runner of tests/support/sweep_test_runner.hpp.
// Test plan:
//   sweep-build-1  a build stores every case, its fit, its results and every day; the stored
//                  numbers are the runner's SI values in the schema's units (kips, lbf, ft)
//   sweep-build-2  1 thread and 2 threads give identical rows, bit for bit (EQ-SWEEP-7)
//   sweep-build-3  incremental: a second build computes nothing; a new code version recomputes
//                  everything; a changed ship file (a value's text) recomputes exactly the cases
//                  that use it, replacing them in place (same case_id, EQ-SWEEP-5/6)
//   sweep-build-4  a failing case and a NaN-returning case are stored as 'failed' with their
//                  reason; --retry-failed recomputes them
//   sweep-build-5  dry-run plan: states new/done/changed; nothing is written
//   sweep-build-6  corrupt, read-only, locked, non-towdb databases and a database with an
//                  unfinished build: named InputError, the file's bytes unchanged
//   sweep-build-7  a second concurrent build on the same file is refused
//   sweep-build-8  the thesis Appendix A Gumbel check value through the writer (kips)
//   sweep-build-9  a stop request (SIGINT) leaves unstarted cases pending and the build
//                  'interrupted'; the next build continues without --resume
//   sweep-build-10 the progress line: done/total, rate, ETA, failures
//   sweep-build-11 the numerics fingerprint (sweep/build/numerics.hpp): 16 hex digits, the same
//                  from any thread; an MPI rank with another one is refused by name
//   sweep-build-12 a database records the fingerprint of its first build; a build that
//                  would compute cases with another one is refused untouched, one with
//                  nothing to compute is not
//   sweep-build-13 the sweep's coverage notes and skipped conditions are stored (schema 5
//                  coverage_notes); the next build of the same sweep file replaces them
//   sweep-build-14 schema 6: each fit stores the runner's lowest point (ft); fits stored without
//                  it are filled by the next build from an up-to-date case, once; fits of
//                  cases outside the sweep stay NULL
//   sweep-build-15 schema 7, day_records = "maxima": a build drops the stored cases' per-day slack
//                  and snatch and writes new cases without them; every other stored value is the
//                  same as with "all"
//   sweep-build-16 schema 8, maxima_precision = "binary16": a build repacks the stored cases'
//                  maxima and writes new cases as binary16, each maximum the binary16 of its
//                  binary32 value; every other stored value is the same as with "binary32"
//   sweep-build-17 ship and towline files edited in comments and layout only (rekey.hpp): the
//                  stored cases are re-keyed, not recomputed, and the database then equals a fresh
//                  build from the edited files (keys, fits, results, days); the dry run says so;
//                  a value's edit in the same files is recomputed
//   sweep-build-18 schema 10, heading profiles (profiles.hpp EQ-SWEEP-8): the last stage stores one
//                  profile per line of two or more headings (none for a single heading or a swell
//                  sea), the function's values in kips; 1 and 2 threads give the same rows; a second
//                  build computes none; changed cases get new profiles and the old ones are
//                  removed; a line whose profile fails keeps none and is named
//   sweep-build-19 schema 11, speed profiles (speed_profiles.hpp EQ-SWEEP-9): the grid of a line
//                  (0.25 kt from its lowest to its highest speed, stored speeds exact) and its mean
//                  tensions (the stored ones at stored speeds, geometric in between, constant for a
//                  given tension); one profile per line of two or more speeds, the function's values
//                  as binary16 kips; 1 and 2 threads give the same rows; a second build computes
//                  none; a stop in the stage resumes to the same rows; a failing line keeps none
//   sweep-build-20 the build's profile functions are the linear model without the wave-induced
//                  surge damping (simulation_runner.hpp profile_options), bit for bit, in head
//                  seas where that damping is not zero
#include <sqlite3.h>
#include <sys/file.h>
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "store/database.hpp"
#include "store/packed_days.hpp"
#include "sweep/build/numerics.hpp"
#include "sweep/build/progress.hpp"
#include "sweep/build/simulation_runner.hpp"
#include "sweep/sweep.hpp"
#include "sweep_test_runner.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

namespace fs = std::filesystem;

struct Fixture {
  fs::path dir = make_temp_dir("towdb-sweep-build");
  io::ShipCatalog catalog = io::ShipCatalog::load(source_dir() / "ships");
  sweep::SweepFile file = sweep::parse_sweep(kSmallSweepToml, "small.toml");
  std::vector<sweep::CaseSpec> cases = sweep::expand_sweep(file, catalog).cases;
  ~Fixture() { fs::remove_all(dir); }

  sweep::BuildSummary build(const fs::path& db, int threads, const sweep::CaseRunner& runner,
                            sweep::BuildOptions o = {}) {
    o.threads = threads;
    o.progress = false;
    return sweep::run_build(db, file, cases, catalog, runner, o);
  }
};

// Replaces the first `from` in a file by `to` (the test fails when absent).
void replace_in_file(const fs::path& path, const std::string& from, const std::string& to) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << path;
  text.replace(at, from.size(), to);
  std::ofstream(path, std::ios::trunc) << text;
}

// The tables a case's computation fills (fits, cases, results, days), without
// the provenance columns and the rows of the vessel and component files.
std::string computed_tables(const fs::path& db) {
  std::set<std::string> excluded = provenance_columns();
  for (const char* c : {"cases.tug_vessel_id", "cases.tow_vessel_id", "cases.case_id", "results.case_id",
                        "case_days.case_id"}) {
    excluded.insert(c);
  }
  const std::string all = dump_database(db, excluded);
  return all.substr(all.find("[towline_fits]"));
}

constexpr int kSmallSweepCases = 18;  // 1 tug x 2 tows x 2 headings x 2 towlines x 2 tensions + 2

TEST(SweepBuild, StoresEveryCaseInSchemaUnits) {  // sweep-build-1
  Fixture f;
  ASSERT_EQ(static_cast<int>(f.cases.size()), kSmallSweepCases);
  const fs::path db = f.dir / "a.db";
  const sweep::BuildSummary s = f.build(db, 2, make_test_runner());
  EXPECT_EQ(s.total, kSmallSweepCases);
  EXPECT_EQ(s.done, kSmallSweepCases);
  EXPECT_EQ(s.failed, 0);
  EXPECT_FALSE(s.interrupted);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE status = 'done'"), kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM results"), kSmallSweepCases);
  // 16 grid cases of 30 days, explicit-1 with 40 days, explicit-2 with the default 30.
  EXPECT_EQ(query_int(db, "SELECT sum(days) FROM case_days"), 16 * 30 + 40 + 30);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM case_days WHERE length(max_dynamic_kips) = 4 * days"), kSmallSweepCases);
  // schema 9: the three keys as the 32 bytes of their SHA-256
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE typeof(case_key) = 'blob' AND length(case_key) = 32 AND "
                          "length(inputs_sha256) = 32 AND length(condition_key) = 32"),
            kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM builds WHERE status = 'completed' AND cases_done = 18"), 1);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM vessels"), 6);  // T-ATF, ARS 50, FFG 7, YRBM, AE 26, CG 47
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE fit_id IS NULL"), 0);
  // Schema 3: the 16 grid cases store T_calc (mean = 1.15 T_calc for their "calculated+15%" half), the two
  // [[case]] entries NULL (schema/README.md).
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE calculated_mean_tension_lbf IS NOT NULL"), 16);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE mean_tension_label = 'calculated+15%' AND "
                          "abs(mean_tension_lbf / calculated_mean_tension_lbf - 1.15) < 1e-12"),
            8);

  // Every stored number against the runner's SI value converted by hand.
  store::Database d = store::Database::open(db, store::Database::Mode::kReadOnly);
  store::Statement st = d.prepare(
      "SELECT c.case_id, c.speed_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf, c.seed, r.dynamic_999_kips, "
      "r.gumbel_alpha_per_kip, r.daily_max_variance_kips2, f.a10_lbf_per_ft, f.span_ft, f.breaking_strength_lbf, "
      "c.spectrum, c.swell_heading_deg FROM cases c JOIN results r USING (case_id) JOIN towline_fits f USING "
      "(fit_id) ORDER BY c.case_id");
  std::size_t i = 0;
  while (st.step()) {
    ASSERT_LT(i, f.cases.size());
    const sweep::CaseSpec& spec = f.cases[i];
    EXPECT_EQ(st.column_int(0), static_cast<std::int64_t>(i + 1)) << "case_id in sweep order (EQ-SWEEP-7)";
    EXPECT_EQ(st.column_double(1), spec.speed_kt);
    EXPECT_EQ(st.column_double(2), spec.heading_deg);
    EXPECT_EQ(st.column_double(3), spec.length_ft);
    EXPECT_EQ(st.column_double(4), spec.mean_tension_lbf);
    EXPECT_EQ(st.column_int(5), spec.seed);
    const sweep::CaseOutcome o = closed_form_outcome(spec, f.catalog);
    // Unit conversions are single multiplications: equal to the last bit or two.
    constexpr double kConversionRelTol = 1e-14;  // a few ulps of double rounding
    EXPECT_REL_CLOSE(st.column_double(6), o.statistics.dynamic_999_n / 4448.2216152605, kConversionRelTol);
    EXPECT_REL_CLOSE(st.column_double(7), o.statistics.gumbel_alpha_per_n * 4448.2216152605, kConversionRelTol);
    EXPECT_REL_CLOSE(st.column_double(8), o.statistics.daily_max_variance_n2 / (4448.2216152605 * 4448.2216152605),
                     kConversionRelTol);
    // a10 [N/m] -> [lbf/ft]: times 0.3048 / 4.4482216152605.
    EXPECT_REL_CLOSE(st.column_double(9), o.fit.coefficients_si[0] * 0.3048 / 4.4482216152605, kConversionRelTol);
    EXPECT_REL_CLOSE(st.column_double(10), o.fit.span_m / 0.3048, kConversionRelTol);
    EXPECT_REL_CLOSE(st.column_double(11), o.fit.breaking_strength_n / 4.4482216152605, kConversionRelTol);
    if (spec.sweep_label == "explicit-2") {
      EXPECT_EQ(st.column_text(12), "jonswap+swell");
      EXPECT_EQ(st.column_double(13), 90.0);
      EXPECT_EQ(st.column_int(5), 42);  // the explicit seed
    }
    ++i;
  }
  EXPECT_EQ(i, f.cases.size());
  // Type I check at the database level: x_0.999 = u - ln(-ln 0.999)/alpha (EQ-STAT-3).
  store::Statement g = d.prepare("SELECT gumbel_u_kips, gumbel_alpha_per_kip, dynamic_999_kips FROM results");
  while (g.step()) {
    constexpr double kQuantileRelTol = 1e-12;  // same formula, rounding only
    EXPECT_REL_CLOSE(g.column_double(2), g.column_double(0) - std::log(-std::log(0.999)) / g.column_double(1),
                     kQuantileRelTol);
  }
}

TEST(SweepBuild, OneAndTwoThreadsGiveIdenticalRows) {  // sweep-build-2
  Fixture f;
  const fs::path one = f.dir / "one.db", two = f.dir / "two.db";
  f.build(one, 1, make_test_runner());
  f.build(two, 2, make_test_runner(sleeping(3)));  // sleeps shuffle the completion order
  const std::string a = dump_database(one, provenance_columns());
  const std::string b = dump_database(two, provenance_columns());
  EXPECT_GT(a.size(), 10000u);
  EXPECT_EQ(a, b);
}

TEST(SweepBuild, IncrementalRecomputesOnlyChangedCases) {  // sweep-build-3
  Fixture f;
  const fs::path db = f.dir / "inc.db";
  f.build(db, 2, make_test_runner());
  const std::string first = dump_database(db, provenance_columns());

  const sweep::BuildSummary again = f.build(db, 2, make_test_runner());
  EXPECT_EQ(again.up_to_date, kSmallSweepCases);
  EXPECT_EQ(again.scheduled, 0);
  EXPECT_EQ(dump_database(db, provenance_columns()), first);

  sweep::BuildOptions v2;
  v2.code_version = "99.0.0-test";
  const sweep::BuildSummary recomputed = f.build(db, 2, make_test_runner(), v2);
  EXPECT_EQ(recomputed.scheduled, kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases"), kSmallSweepCases);  // replaced in place
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM results WHERE code_version = '99.0.0-test'"), kSmallSweepCases);

  // A changed YRBM ship file (a value's text: new content) recomputes the
  // 8 YRBM cases only, with the same case_ids.
  const fs::path ships = f.dir / "ships";
  fs::copy(source_dir() / "ships", ships, fs::copy_options::recursive);
  replace_in_file(ships / "yrbm.toml", "YRBM of about 650 LT", "YRBM of about 650 LT (edited)");
  const io::ShipCatalog edited = io::ShipCatalog::load(ships);
  const std::int64_t yrbm_ids_before =
      query_int(db, "SELECT sum(case_id) FROM cases WHERE tow_name = 'YRBM'");
  sweep::BuildOptions o = v2;
  o.threads = 2;
  o.progress = false;
  const sweep::BuildSummary s = sweep::run_build(db, f.file, f.cases, edited, make_test_runner(), o);
  EXPECT_EQ(s.scheduled, 8);
  EXPECT_EQ(s.up_to_date, kSmallSweepCases - 8);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases"), kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT sum(case_id) FROM cases WHERE tow_name = 'YRBM'"), yrbm_ids_before);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM vessels WHERE name = 'YRBM'"), 2);  // both file versions kept
  EXPECT_EQ(query_int(db, "SELECT count(DISTINCT tow_vessel_id) FROM cases WHERE tow_name = 'YRBM'"), 1);
}

TEST(SweepBuild, FailedCasesAreStoredWithTheirReason) {  // sweep-build-4
  Fixture f;
  const fs::path db = f.dir / "fail.db";
  TestRunnerOptions opts;
  opts.fail_when = [](const sweep::CaseSpec& s) { return s.sweep_label == "explicit-1"; };
  opts.nan_when = [](const sweep::CaseSpec& s) { return s.tow == "YRBM" && s.heading_deg == 0.0; };
  const sweep::BuildSummary s = f.build(db, 2, make_test_runner(opts));
  EXPECT_EQ(s.failed, 1 + 4);
  EXPECT_EQ(s.done, kSmallSweepCases - 5);
  EXPECT_EQ(s.failures.size(), 5u);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE status = 'failed' AND error_message LIKE "
                          "'numerical error: test runner: catenary solver did not converge (iteration 50%'"),
            1);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE status = 'failed' AND error_message LIKE "
                          "'numerical error: case runner output: statistics.dynamic_999_n = nan is not finite'"),
            4);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM results r JOIN cases c USING (case_id) WHERE c.status = 'failed'"),
            0);
  EXPECT_EQ(query_int(db, "SELECT cases_failed FROM builds"), 5);

  // Not retried by default, recomputed with retry_failed.
  const sweep::BuildSummary kept = f.build(db, 2, make_test_runner());
  EXPECT_EQ(kept.scheduled, 0);
  EXPECT_EQ(kept.previously_failed, 5);
  sweep::BuildOptions retry;
  retry.retry_failed = true;
  const sweep::BuildSummary redone = f.build(db, 2, make_test_runner(), retry);
  EXPECT_EQ(redone.scheduled, 5);
  EXPECT_EQ(redone.done, 5);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE status = 'done'"), kSmallSweepCases);
}

TEST(SweepBuild, DryRunPlanWritesNothing) {  // sweep-build-5
  Fixture f;
  const fs::path db = f.dir / "plan.db";
  auto plan = sweep::plan_build(db, f.cases, f.catalog, kVersion);
  EXPECT_FALSE(fs::exists(db));
  ASSERT_EQ(static_cast<int>(plan.size()), kSmallSweepCases);
  for (const auto& p : plan) EXPECT_EQ(p.state, sweep::CaseState::kNew);
  f.build(db, 1, make_test_runner());
  const std::string before = test::read_text(db);
  plan = sweep::plan_build(db, f.cases, f.catalog, kVersion);
  for (const auto& p : plan) EXPECT_EQ(p.state, sweep::CaseState::kDone);
  plan = sweep::plan_build(db, f.cases, f.catalog, "99.0.0-test");
  for (const auto& p : plan) EXPECT_EQ(p.state, sweep::CaseState::kChanged);
  EXPECT_EQ(test::read_text(db), before);
}

void expect_refused(Fixture& f, const fs::path& db, const std::string& message_part,
                    sweep::BuildOptions o = {}) {
  const std::string before = fs::exists(db) ? test::read_text(db) : "";
  try {
    f.build(db, 1, make_test_runner(), o);
    ADD_FAILURE() << "no error for " << db;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(message_part), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(db.string()), std::string::npos) << "names the file: " << e.what();
  }
  EXPECT_EQ(fs::exists(db) ? test::read_text(db) : "", before) << "the file was changed";
}

TEST(SweepBuild, BadDatabasesAreRefusedUntouched) {  // sweep-build-6
  Fixture f;
  const fs::path corrupt = f.dir / "corrupt.db";
  { std::ofstream(corrupt, std::ios::binary) << std::string(8192, '\x5a'); }
  expect_refused(f, corrupt, "not a valid towdb database");

  const fs::path other = f.dir / "other.db";
  {
    sqlite3* raw = nullptr;
    sqlite3_open(other.c_str(), &raw);
    sqlite3_exec(raw, "CREATE TABLE t (x); INSERT INTO t VALUES (1);", nullptr, nullptr, nullptr);
    sqlite3_close(raw);
  }
  expect_refused(f, other, "not a towdb database");

  const fs::path good = f.dir / "good.db";
  f.build(good, 1, make_test_runner());
  const std::string reference = dump_database(good, {});

  fs::permissions(good, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  expect_refused(f, good, "read-only");
  fs::permissions(good, fs::perms::owner_read | fs::perms::owner_write);

  {  // another connection holds the write lock
    sqlite3* raw = nullptr;
    sqlite3_open(good.c_str(), &raw);
    ASSERT_EQ(sqlite3_exec(raw, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr), SQLITE_OK);
    sweep::BuildOptions v2;
    v2.code_version = "99.0.0-test";  // would rewrite every case
    try {
      f.build(good, 1, make_test_runner(), v2);
      ADD_FAILURE() << "no error for a locked database";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("another process holds a lock"), std::string::npos) << e.what();
    }
    sqlite3_exec(raw, "ROLLBACK", nullptr, nullptr, nullptr);
    sqlite3_close(raw);
  }
  EXPECT_EQ(dump_database(good, {}), reference);

  {  // a build that never finished (as after kill -9), in a rollback-journal file
    sqlite3* raw = nullptr;
    sqlite3_open(good.c_str(), &raw);
    sqlite3_exec(raw, "UPDATE builds SET status = 'running', finished_utc = NULL; PRAGMA journal_mode = DELETE;",
                 nullptr, nullptr, nullptr);
    sqlite3_close(raw);
  }
  const std::string unfinished = dump_database(good, {});
  const std::string unfinished_bytes = test::read_text(good);
  sweep::BuildOptions v3;
  v3.code_version = "99.0.0-test";
  try {
    f.build(good, 1, make_test_runner(), v3);
    ADD_FAILURE() << "no error for an unfinished build";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did not finish (killed or crashed); run again with --resume"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(dump_database(good, {}), unfinished);
  EXPECT_EQ(test::read_text(good), unfinished_bytes) << "the file was changed";
}

TEST(SweepBuild, ConcurrentBuildIsRefused) {  // sweep-build-7
  Fixture f;
  const fs::path db = f.dir / "busy.db";
  f.build(db, 1, make_test_runner());
  const int fd = ::open(db.c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // what a running build holds
  expect_refused(f, db, "another towdb build is writing to this database");
  ::close(fd);
}

TEST(SweepBuild, ThesisGumbelCheckValueThroughTheWriter) {  // sweep-build-8
  // EVIDENCE-OF: EQ-STAT-3 — thesis Appendix A sample output: daily maxima with mean 41.06 kips and
  // variance 10.80 kips^2 give x_0.999 = 57.27 kips. The runner hands the writer SI values; the
  // database must show the thesis's kips.
  Fixture f;
  const double kip_n = units::kips_to_n(1.0);
  const statistics::Gumbel g = statistics::gumbel_from_moments(41.06 * kip_n, 10.80 * kip_n * kip_n);
  sweep::CaseRunner runner = [&](const sweep::CaseSpec& spec, const io::ShipCatalog& cat) {
    sweep::CaseOutcome o = closed_form_outcome(spec, cat);
    o.statistics.gumbel_u_n = g.location;
    o.statistics.gumbel_alpha_per_n = g.alpha();
    o.statistics.daily_max_mean_n = 41.06 * kip_n;
    o.statistics.daily_max_variance_n2 = 10.80 * kip_n * kip_n;
    o.statistics.dynamic_999_n = g.quantile(0.999);
    return o;
  };
  const fs::path db = f.dir / "thesis.db";
  f.build(db, 1, runner);
  store::Database d = store::Database::open(db, store::Database::Mode::kReadOnly);
  store::Statement st =
      d.prepare("SELECT daily_max_mean_kips, daily_max_variance_kips2, dynamic_999_kips FROM results LIMIT 1");
  ASSERT_TRUE(st.step());
  // The thesis prints mean and variance with 4 significant figures (+-0.005 each moves x_0.999 by
  // up to +-0.009 kips) and the result to +-0.005 kips: 0.014 / 57.27 = 2.4e-4.
  constexpr double kThesisPrintRelTol = 3e-4;
  EXPECT_REL_CLOSE(st.column_double(0), 41.06, 1e-12);
  EXPECT_REL_CLOSE(st.column_double(1), 10.80, 1e-12);
  EXPECT_REL_CLOSE(st.column_double(2), 57.27, kThesisPrintRelTol);
}

TEST(SweepBuild, StopRequestLeavesCasesPending) {  // sweep-build-9
  Fixture f;
  const fs::path db = f.dir / "stop.db";
  std::atomic<bool> stop{true};  // as if SIGINT arrived before the first case started
  sweep::BuildOptions o;
  o.stop = &stop;
  const sweep::BuildSummary s = f.build(db, 2, make_test_runner(), o);
  EXPECT_TRUE(s.interrupted);
  EXPECT_EQ(s.done, 0);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE status = 'pending'"), kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM builds WHERE status = 'interrupted'"), 1);
  const sweep::BuildSummary next = f.build(db, 2, make_test_runner());  // no --resume needed
  EXPECT_EQ(next.done, kSmallSweepCases);
  EXPECT_FALSE(next.interrupted);
}

TEST(SweepBuild, ProgressLine) {  // sweep-build-10
  // 13 of 240 cases finished (1 failed) after 26 s: 0.5 cases/s, 227 left -> 454 s = 7m34s.
  EXPECT_EQ(sweep::ProgressBar::format(12, 1, 240, 26.0),
            "13/240 cases [#-----------------------]   5.4%  0.50 cases/s  ETA 7m34s  1 failed");
  EXPECT_EQ(sweep::ProgressBar::format(0, 0, 10, 1.0),
            "0/10 cases [------------------------]   0.0%  0.00 cases/s  ETA ?  0 failed");
  EXPECT_EQ(sweep::ProgressBar::format(10, 0, 10, 5.0),
            "10/10 cases [########################] 100.0%  2.00 cases/s  ETA 0s  0 failed");
}


TEST(SweepBuild, NumericsFingerprintNamesAMismatchingRank) {  // sweep-build-11
  const std::string here = sweep::numerics_fingerprint();
  ASSERT_EQ(here.size(), 16u);
  EXPECT_EQ(here.find_first_not_of("0123456789abcdef"), std::string::npos) << here;
  std::string other_thread;
  std::thread([&] { other_thread = sweep::numerics_fingerprint(); }).join();
  EXPECT_EQ(other_thread, here);
  EXPECT_EQ(sweep::numerics_mismatch(3, here, here), "");
  const std::string refusal = sweep::numerics_mismatch(3, here, "0123456789abcdef");
  EXPECT_NE(refusal.find("MPI rank 3"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find(here), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("0123456789abcdef"), std::string::npos) << refusal;
}

TEST(SweepBuild, DatabaseKeepsOneNumericsFingerprint) {  // sweep-build-12
  Fixture f;
  const fs::path db = f.dir / "numerics.db";
  f.build(db, 1, make_test_runner());
  {
    store::Database d = store::Database::open(db, store::Database::Mode::kReadOnly);
    store::Statement st = d.prepare("SELECT value FROM meta WHERE key = 'numerics_fingerprint'");
    ASSERT_TRUE(st.step());
    EXPECT_EQ(st.column_text(0), sweep::numerics_fingerprint());
  }
  // As if another machine kind had computed the database, stored with a
  // rollback journal like the bundled one (a writable open would switch it to
  // WAL: the refusal must come first).
  {
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open(db.c_str(), &raw), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(raw,
                           "UPDATE meta SET value = '0123456789abcdef' WHERE key = 'numerics_fingerprint';"
                           "PRAGMA journal_mode = DELETE;",
                           nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(raw);
  }
  sweep::BuildOptions v2;
  v2.code_version = "99.0.0-test";  // every case would be recomputed here
  expect_refused(f, db, "numerics_fingerprint = 0123456789abcdef", v2);
  const sweep::BuildSummary nothing_to_do = f.build(db, 1, make_test_runner());
  EXPECT_EQ(nothing_to_do.scheduled, 0);
}

TEST(SweepBuild, CoverageNotesAreStoredAndReplaced) {  // sweep-build-13
  Fixture f;
  const fs::path db = f.dir / "coverage.db";
  sweep::BuildOptions o;
  o.coverage_notes = {{"small-grid", "T-ATF 166", "FFG 7", "FFG 7 at 5 kt only"},
                      {"small-grid", "T-ATF 166", "YRBM", "YRBM at 5 kt only"}};
  o.skipped = {{"small-grid", "T-ATF 166", "YRBM", 9.0, "wind_kt=35", 180.0, "T_calc above 125,000 lbf down to 3 kt"}};
  f.build(db, 1, make_test_runner(), o);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM coverage_notes WHERE kind = 'grid_note'"), 2);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM coverage_notes WHERE kind = 'skipped' AND nominal_speed_kt = 9 AND "
                          "sea = 'wind_kt=35' AND heading_deg = 180 AND tow_name = 'YRBM' AND "
                          "note = 'T_calc above 125,000 lbf down to 3 kt'"),
            1);
  // The same sweep file again, now with one note: the earlier build's notes go, this build's stay.
  o.coverage_notes.pop_back();
  o.skipped.clear();
  f.build(db, 1, make_test_runner(), o);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM coverage_notes"), 1);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM coverage_notes WHERE build_id = (SELECT max(build_id) FROM builds)"),
            1);
}

TEST(SweepBuild, LowestPointIsStoredAndFilledForOlderFits) {  // sweep-build-14
  Fixture f;
  const fs::path db = f.dir / "lowest.db";
  f.build(db, 1, make_test_runner());
  const std::int64_t fits = query_int(db, "SELECT count(*) FROM towline_fits");
  ASSERT_GT(fits, 2);
  // Every case's fit holds the runner's value in ft (case_id = sweep order, EQ-SWEEP-7).
  for (std::size_t i = 0; i < f.cases.size(); ++i) {
    const double expected_ft = units::m_to_ft(closed_form_outcome(f.cases[i], f.catalog).fit.lowest_elevation_m);
    store::Database d = store::Database::open(db, store::Database::Mode::kReadOnly);
    store::Statement st = d.prepare(
        "SELECT f.lowest_elevation_ft FROM cases c JOIN towline_fits f ON f.fit_id = c.fit_id WHERE c.case_id = ?");
    st.bind(1, static_cast<std::int64_t>(i + 1));
    ASSERT_TRUE(st.step()) << i;
    EXPECT_EQ(st.column_double(0), expected_ft) << i;
    EXPECT_LT(expected_ft, 0.0) << i;  // a 100 N/m line sags below the water
  }
  // A database written before schema 6: NULL everywhere. The next build fills every fit of the
  // sweep with the LowestPointFn's value, once; cases outside the sweep keep NULL.
  {
    store::Database d = store::Database::open(db, store::Database::Mode::kReadWrite);
    d.exec("UPDATE towline_fits SET lowest_elevation_ft = NULL");
  }
  sweep::BuildOptions o;
  int calls = 0;
  o.lowest_elevation_m = [&calls](const sweep::CaseSpec& spec, const io::ShipCatalog&) {
    ++calls;
    return -units::ft_to_m(spec.length_ft / 100.0);
  };
  const sweep::BuildSummary s = f.build(db, 1, make_test_runner(), o);
  EXPECT_EQ(s.scheduled, 0);
  EXPECT_EQ(s.lowest_points_filled, fits);
  EXPECT_EQ(calls, fits);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM towline_fits WHERE abs(lowest_elevation_ft + length_ft / 100.0) "
                          "< 1e-9"),
            fits);
  EXPECT_EQ(f.build(db, 1, make_test_runner(), o).lowest_points_filled, 0);
  EXPECT_EQ(calls, fits);
  // A sweep with one of the cases only: the other fits stay NULL.
  {
    store::Database d = store::Database::open(db, store::Database::Mode::kReadWrite);
    d.exec("UPDATE towline_fits SET lowest_elevation_ft = NULL");
  }
  o.threads = 1;
  o.progress = false;
  const sweep::BuildSummary s1 = sweep::run_build(db, f.file, {f.cases.front()}, f.catalog, make_test_runner(), o);
  EXPECT_EQ(s1.lowest_points_filled, 1);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM towline_fits WHERE lowest_elevation_ft IS NULL"), fits - 1);
}

TEST(SweepBuild, MaximaOnlyDayRecordsKeepEverythingButThePerDaySlackAndSnatch) {  // sweep-build-15
  Fixture f;
  const fs::path db = f.dir / "maxima.db";
  const fs::path reference = f.dir / "all.db";
  f.build(db, 1, make_test_runner());
  {
    // The test runner's line never goes slack: give three cases per-day slack and snatch records.
    store::Database d = store::Database::open(db, store::Database::Mode::kReadWrite);
    d.exec("UPDATE case_days SET slack_time_s = max_dynamic_kips, snatch_events = max_dynamic_kips WHERE case_id <= 3");
  }
  std::set<std::string> not_compared = provenance_columns();
  for (const char* c : {"case_days.slack_time_s", "case_days.snatch_events", "case_days.slack_snatch_stored"}) {
    not_compared.insert(c);
  }
  const std::string before = dump_database(db, not_compared);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM case_days WHERE slack_snatch_stored = 1"), kSmallSweepCases);

  f.file.day_records = sweep::DayRecords::kMaxima;
  const sweep::BuildSummary s = f.build(db, 1, make_test_runner());
  EXPECT_EQ(s.scheduled, 0);
  EXPECT_EQ(s.slack_snatch_dropped, kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM case_days WHERE slack_snatch_stored = 0 AND slack_time_s IS NULL "
                          "AND snatch_events IS NULL"),
            kSmallSweepCases);
  EXPECT_EQ(dump_database(db, not_compared), before);  // every maximum, fit and result kept
  EXPECT_EQ(f.build(db, 1, make_test_runner()).slack_snatch_dropped, 0);

  // Cases computed under "maxima" store no per-day slack and snatch, and the same everything else.
  sweep::BuildOptions v2;
  v2.code_version = "99.0.0-test";
  EXPECT_EQ(f.build(db, 2, make_test_runner(), v2).done, kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM case_days WHERE slack_snatch_stored = 0"), kSmallSweepCases);
  f.file.day_records = sweep::DayRecords::kAll;
  f.build(reference, 1, make_test_runner());  // the same two builds (the first version's fits stay)
  f.build(reference, 2, make_test_runner(), v2);
  EXPECT_EQ(query_int(reference, "SELECT count(*) FROM case_days WHERE slack_snatch_stored = 1"), kSmallSweepCases);
  EXPECT_EQ(dump_database(db, not_compared), dump_database(reference, not_compared));
}

// Every case's daily maxima, by case id.
std::map<std::int64_t, store::CaseDays> all_case_days(const fs::path& path) {
  store::Database d = store::Database::open(path, store::Database::Mode::kReadOnly);
  std::vector<std::int64_t> ids;
  store::Statement st = d.prepare("SELECT case_id FROM case_days ORDER BY case_id");
  while (st.step()) ids.push_back(st.column_int(0));
  std::map<std::int64_t, store::CaseDays> out;
  for (const std::int64_t id : ids) out[id] = store::read_case_days(d, id);
  return out;
}

TEST(SweepBuild, Binary16MaximaKeepEverythingElseAndRoundEachMaximumOnce) {  // sweep-build-16
  Fixture f;
  const fs::path db = f.dir / "half.db";
  const fs::path reference = f.dir / "single.db";
  f.build(db, 1, make_test_runner());
  const std::map<std::int64_t, store::CaseDays> single = all_case_days(db);
  std::set<std::string> not_compared = provenance_columns();
  for (const char* c : {"case_days.max_dynamic_kips", "case_days.maxima_bytes"}) not_compared.insert(c);
  const std::string before = dump_database(db, not_compared);

  f.file.maxima_precision = sweep::MaximaPrecision::kBinary16;
  const sweep::BuildSummary s = f.build(db, 1, make_test_runner());
  EXPECT_EQ(s.scheduled, 0);
  EXPECT_EQ(s.maxima_repacked, kSmallSweepCases);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM case_days WHERE maxima_bytes = 2 AND length(max_dynamic_kips) = "
                          "2 * days"),
            kSmallSweepCases);
  EXPECT_EQ(dump_database(db, not_compared), before);  // every fit and result kept
  const std::map<std::int64_t, store::CaseDays> half = all_case_days(db);
  ASSERT_EQ(half.size(), single.size());
  for (const auto& [id, days] : single) {
    const std::vector<double>& h = half.at(id).max_dynamic_kips;
    ASSERT_EQ(h.size(), days.max_dynamic_kips.size());
    for (std::size_t i = 0; i < h.size(); ++i) {
      // binary16 rounding to nearest: at most half a unit in the 11th significant bit.
      EXPECT_LE(std::fabs(h[i] - days.max_dynamic_kips[i]), std::ldexp(std::fabs(days.max_dynamic_kips[i]), -11))
          << "case " << id << " day " << i;
    }
  }
  EXPECT_EQ(f.build(db, 1, make_test_runner()).maxima_repacked, 0);

  // Cases computed under "binary16" store what a repack of binary32 cases stores.
  sweep::BuildOptions v2;
  v2.code_version = "99.0.0-test";
  EXPECT_EQ(f.build(db, 2, make_test_runner(), v2).done, kSmallSweepCases);
  f.file.maxima_precision = sweep::MaximaPrecision::kBinary32;
  f.build(reference, 1, make_test_runner());
  f.build(reference, 2, make_test_runner(), v2);
  EXPECT_EQ(query_int(reference, "SELECT count(*) FROM case_days WHERE maxima_bytes = 4"), kSmallSweepCases);
  {
    store::Database d = store::Database::open(reference, store::Database::Mode::kReadWrite);
    EXPECT_EQ(store::pack_maxima_binary16(d), kSmallSweepCases);
  }
  std::set<std::string> provenance = provenance_columns();
  EXPECT_EQ(dump_database(db, provenance), dump_database(reference, provenance));
}

}  // namespace
}  // namespace towdb::test

namespace towdb::test {
namespace {

TEST(SweepBuild, CommentOnlyEditsReKeyInsteadOfRecomputing) {  // sweep-build-17
  Fixture f;
  const fs::path db = f.dir / "rekey.db";
  f.build(db, 2, make_test_runner());
  const std::int64_t fits_before = query_int(db, "SELECT count(*) FROM towline_fits");

  // Comments, blank lines and spacing: the same TOML documents.
  const fs::path ships = f.dir / "ships";
  fs::copy(source_dir() / "ships", ships, fs::copy_options::recursive);
  { std::ofstream(ships / "yrbm.toml", std::ios::app) << "\n\n# edited: a comment and blank lines\n"; }
  replace_in_file(ships / "towlines/fiber-hawser.toml", "format = \"towdb-towline-1\"",
                  "# the format line, commented\nformat    =    \"towdb-towline-1\"");
  const io::ShipCatalog edited = io::ShipCatalog::load(ships);
  ASSERT_NE(edited.vessel("YRBM").vessel.content_sha256, f.catalog.vessel("YRBM").vessel.content_sha256);

  const std::vector<sweep::PlannedCase> plan = sweep::plan_build(db, f.cases, edited, kVersion);
  int to_rekey = 0;
  for (const auto& p : plan) {
    to_rekey += p.rekey ? 1 : 0;
    EXPECT_EQ(p.state, sweep::CaseState::kDone);
  }
  sweep::BuildOptions o;
  o.threads = 2;
  o.progress = false;
  const sweep::BuildSummary s = sweep::run_build(db, f.file, f.cases, edited, make_test_runner(), o);
  EXPECT_EQ(s.scheduled, 0);
  EXPECT_EQ(s.rekeyed, to_rekey);
  // Every case that uses an edited file: the YRBM's, and every fiber case (the hawser).
  const std::int64_t expected =
      query_int(db, "SELECT count(*) FROM cases WHERE tow_name = 'YRBM' OR line_type = 'fiber'");
  EXPECT_EQ(s.rekeyed, expected);
  EXPECT_GT(s.rekeyed, 0);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM towline_fits"), fits_before);  // moved, none left behind

  // The re-keyed database holds what a fresh build from the edited files computes.
  const fs::path fresh = f.dir / "fresh.db";
  sweep::run_build(fresh, f.file, f.cases, edited, make_test_runner(), o);
  EXPECT_EQ(computed_tables(db), computed_tables(fresh));
  const sweep::BuildSummary again = sweep::run_build(db, f.file, f.cases, edited, make_test_runner(), o);
  EXPECT_EQ(again.up_to_date, kSmallSweepCases);
  EXPECT_EQ(again.rekeyed, 0);

  // A value's text edited in the same file: its cases are recomputed.
  replace_in_file(ships / "yrbm.toml", "YRBM of about 650 LT", "YRBM of about 650 LT (edited)");
  const io::ShipCatalog changed = io::ShipCatalog::load(ships);
  const sweep::BuildSummary recomputed = sweep::run_build(db, f.file, f.cases, changed, make_test_runner(), o);
  EXPECT_EQ(recomputed.rekeyed, 0);
  EXPECT_EQ(recomputed.scheduled, 8);
}

TEST(SweepBuild, StoresOneHeadingProfilePerLine) {  // sweep-build-18
  Fixture f;
  int calls = 0;
  std::mutex calls_mutex;
  // sigma(h) = 1,000 N (2 + cos h) (1 + H / 1e6 lbf): distinct per line and heading.
  auto closed_form = [&](const sweep::CaseSpec& spec, const io::ShipCatalog&, const std::vector<double>& headings) {
    if (headings.size() > 1) {  // a line's profile (single headings warm the response cache)
      const std::lock_guard<std::mutex> lock(calls_mutex);
      ++calls;
    }
    if (spec.tow == "YRBM" && spec.line == model::LineKind::kFiber) {
      throw NumericalError("test: this line's linear model fails");
    }
    std::vector<double> sigma;
    for (double h : headings) sigma.push_back(1000.0 * (2.0 + std::cos(units::deg_to_rad(h))) * (1.0 + spec.mean_tension_lbf / 1e6));
    return sigma;
  };
  sweep::BuildOptions o;
  o.heading_profile = closed_form;
  const fs::path db = f.dir / "profiles.db";
  const sweep::BuildSummary s = f.build(db, 2, make_test_runner(), o);
  // The grid's 8 lines (2 tows x 2 towlines x 2 tensions, headings 0 and 180); the explicit
  // cases are a single heading and a swell sea.
  EXPECT_EQ(s.profiles.lines, 8);
  const int failing = static_cast<int>(query_int(
      db, "SELECT count(DISTINCT mean_tension_lbf) FROM cases WHERE tow_name = 'YRBM' AND line_type = 'fiber'"));
  ASSERT_GT(failing, 0);  // the failure path is exercised
  EXPECT_EQ(s.profiles.failed, failing);
  EXPECT_EQ(s.profiles.computed, 8 - failing);
  ASSERT_EQ(s.profiles.failures.size(), static_cast<std::size_t>(failing));
  EXPECT_NE(s.profiles.failures.front().find("this line's linear model fails"), std::string::npos);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM heading_profiles"), 8 - failing);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE profile_id IS NOT NULL"), 2 * (8 - failing));
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE sweep_label LIKE 'explicit%' AND profile_id IS NOT NULL"), 0);
  {
    auto d = store::Database::open(db, store::Database::Mode::kReadOnly);
    auto st = d.prepare(
        "SELECT p.mean_tension_lbf, p.heading_step_deg, p.headings, p.sigma_kips_f32, c.mean_tension_lbf FROM "
        "heading_profiles p JOIN cases c ON c.profile_id = p.profile_id");
    int rows = 0;
    while (st.step()) {
      ++rows;
      const double m = st.column_double(4);
      EXPECT_EQ(st.column_double(0), m);
      EXPECT_EQ(st.column_double(1), sweep::kProfileStepDeg);
      ASSERT_EQ(st.column_int(2), sweep::kProfileHeadings);
      const std::vector<double> kips = store::unpack_float32(st.column_blob(3), sweep::kProfileHeadings, "test");
      for (int j = 0; j < sweep::kProfileHeadings; ++j) {
        const double h = sweep::kProfileStepDeg * j;
        const double expected = units::n_to_kips(1000.0 * (2.0 + std::cos(units::deg_to_rad(h))) * (1.0 + m / 1e6));
        EXPECT_EQ(kips[j], static_cast<double>(static_cast<float>(expected))) << h;
      }
    }
    EXPECT_EQ(rows, 2 * (8 - failing));
  }
  // One thread: the same rows.
  const fs::path one = f.dir / "one.db";
  f.build(one, 1, make_test_runner(), o);
  EXPECT_EQ(dump_database(one, provenance_columns()), dump_database(db, provenance_columns()));

  // Up to date: nothing computed (the failed line is tried again).
  calls = 0;
  const sweep::BuildSummary again = f.build(db, 2, make_test_runner(), o);
  EXPECT_EQ(again.profiles.up_to_date, 8 - failing);
  EXPECT_EQ(again.profiles.computed, 0);
  EXPECT_EQ(calls, failing);

  // A stop request during the stage (as SIGINT would): the build ends interrupted with the
  // profiles not yet written left for the next build, which computes only those.
  const fs::path stopped = f.dir / "stopped.db";
  std::atomic<bool> stop{false};
  sweep::BuildOptions stopping = o;
  stopping.stop = &stop;
  stopping.heading_profile = [&](const sweep::CaseSpec& spec, const io::ShipCatalog& catalog,
                                 const std::vector<double>& headings) {
    stop = true;  // the first call (the warm-up's) asks to stop
    return closed_form(spec, catalog, headings);
  };
  const sweep::BuildSummary cut = f.build(stopped, 2, make_test_runner(), stopping);
  EXPECT_TRUE(cut.interrupted);
  EXPECT_EQ(cut.profiles.computed, 0);
  EXPECT_EQ(query_int(stopped, "SELECT count(*) FROM heading_profiles"), 0);
  EXPECT_EQ(query_int(stopped, "SELECT count(*) FROM builds WHERE status = 'interrupted'"), 1);
  const sweep::BuildSummary resumed = f.build(stopped, 2, make_test_runner(), o);
  EXPECT_FALSE(resumed.interrupted);
  EXPECT_EQ(resumed.profiles.computed, 8 - failing);
  EXPECT_EQ(dump_database(stopped, provenance_columns()), dump_database(db, provenance_columns()));

  // New cases (a new code version): new profiles, the old ones removed.
  o.code_version = "99.0.0-test";
  const sweep::BuildSummary v2 = f.build(db, 2, make_test_runner(), o);
  EXPECT_EQ(v2.profiles.computed, 8 - failing);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM heading_profiles"), 8 - failing);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM heading_profiles WHERE profile_id NOT IN (SELECT profile_id FROM "
                          "cases WHERE profile_id IS NOT NULL)"),
            0);
}

TEST(SweepBuild, SpeedProfileGridJoinsTheStoredTensionsGeometrically) {  // sweep-build-19
  // Three stored speeds 2 kt apart: 17 points, the stored ones exact.
  const auto p = sweep::speed_profile_points({5.0, 7.0, 9.0}, {100.0, 121.0, 144.0});
  ASSERT_EQ(p.size(), 17u);
  EXPECT_EQ(p[0].speed_kt, 5.0);
  EXPECT_EQ(p[0].mean_tension_lbf, 100.0);
  EXPECT_EQ(p[8].speed_kt, 7.0);
  EXPECT_EQ(p[8].mean_tension_lbf, 121.0);
  EXPECT_EQ(p[16].mean_tension_lbf, 144.0);
  EXPECT_NEAR(p[4].speed_kt, 6.0, 1e-12);
  EXPECT_NEAR(p[4].mean_tension_lbf, 110.0, 1e-9);   // sqrt(100 x 121)
  EXPECT_NEAR(p[12].mean_tension_lbf, 132.0, 1e-9);  // sqrt(121 x 144)
  // The AE 26's 5, 6.75 and 8.5 kt: 15 points, 6.75 kt among them; a given tension stays.
  const auto q = sweep::speed_profile_points({5.0, 6.75, 8.5}, {60000.0, 60000.0, 60000.0});
  ASSERT_EQ(q.size(), 15u);
  EXPECT_EQ(q[7].speed_kt, 6.75);
  for (const auto& pt : q) EXPECT_EQ(pt.mean_tension_lbf, 60000.0);
  // A span that is not a multiple of the step: the points are closer than 0.25 kt.
  const auto r = sweep::speed_profile_points({5.0, 5.6}, {1.0, 2.0});
  ASSERT_EQ(r.size(), 4u);
  EXPECT_NEAR(r[1].speed_kt, 5.2, 1e-12);
  EXPECT_THROW(sweep::speed_profile_points({5.0, 5.0}, {1.0, 1.0}), InputError);
  EXPECT_THROW(sweep::speed_profile_points({5.0}, {1.0}), InputError);
  EXPECT_THROW(sweep::speed_profile_points({5.0, 6.0}, {1.0, -1.0}), InputError);
}

TEST(SweepBuild, StoresOneSpeedProfilePerLine) {  // sweep-build-19
  Fixture f;
  f.file = sweep::parse_sweep(R"(format = "towdb-sweep-1"
description = "speed lines"
[defaults]
days = 20
base_seed = 3
[[grid]]
label = "speeds"
tugs = ["T-ATF 166"]
tows = ["FFG 7", "YRBM"]
speeds_kt = [5.0, 6.0, 7.5]
winds_kt = [20.0]
headings_deg = [0.0, 180.0]
towlines = [ { line = "wire", length_ft = 1000.0 } ]
mean_tensions = [
  { label = "calculated", basis = "calculated", factor = 1.0 },
  { label = "given-60k", basis = "given", value_lbf = 60000.0 },
]
)", "speeds.toml");
  f.cases = sweep::expand_sweep(f.file, f.catalog).cases;
  ASSERT_EQ(f.cases.size(), 24u);
  std::mutex m;
  std::map<std::string, std::vector<sweep::SpeedPoint>> asked;  // tow|heading|label -> the line's points
  // sigma(V, m) = 1,000 N (1 + V / 10 kt) (1 + m / 1e6 lbf); YRBM at 0 deg fails.
  auto closed_form = [&](const sweep::CaseSpec& spec, const io::ShipCatalog&,
                         const std::vector<sweep::SpeedPoint>& points) {
    if (spec.tow == "YRBM" && spec.heading_deg == 0.0) throw NumericalError("test: this line's linear model fails");
    if (points.size() > 1) {
      const std::lock_guard<std::mutex> lock(m);
      asked[spec.tow + "|" + sweep::canonical_number(spec.heading_deg) + "|" + spec.mean_tension_label] = points;
    }
    std::vector<double> sigma;
    for (const auto& p : points) sigma.push_back(1000.0 * (1.0 + p.speed_kt / 10.0) * (1.0 + p.mean_tension_lbf / 1e6));
    return sigma;
  };
  sweep::BuildOptions o;
  o.speed_profile = closed_form;
  const fs::path db = f.dir / "speed.db";
  const sweep::BuildSummary s = f.build(db, 2, make_test_runner(), o);
  EXPECT_EQ(s.speed_profiles.lines, 8);  // 2 tows x 2 headings x 2 tensions
  EXPECT_EQ(s.speed_profiles.failed, 2);
  EXPECT_EQ(s.speed_profiles.computed, 6);
  ASSERT_EQ(s.speed_profiles.failures.size(), 2u);
  EXPECT_NE(s.speed_profiles.failures.front().find("this line's linear model fails"), std::string::npos);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM speed_profiles"), 6);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE speed_profile_id IS NOT NULL"), 18);
  ASSERT_EQ(asked.size(), 6u);
  // The calculated line's points: the stored cases' tensions at 5, 6 and 7.5 kt, geometric between.
  {
    auto d = store::Database::open(db, store::Database::Mode::kReadOnly);
    auto st = d.prepare(
        "SELECT speed_kt, mean_tension_lbf FROM cases WHERE tow_name = 'FFG 7' AND heading_deg = 180 AND "
        "mean_tension_label = 'calculated' ORDER BY speed_kt");
    std::vector<double> stored;
    while (st.step()) stored.push_back(st.column_double(1));
    ASSERT_EQ(stored.size(), 3u);
    const auto& pts = asked.at("FFG 7|180|calculated");
    ASSERT_EQ(pts.size(), 11u);  // 5 to 7.5 kt every 0.25 kt
    EXPECT_EQ(pts[0].mean_tension_lbf, stored[0]);
    EXPECT_EQ(pts[4].speed_kt, 6.0);
    EXPECT_EQ(pts[4].mean_tension_lbf, stored[1]);
    EXPECT_EQ(pts[10].mean_tension_lbf, stored[2]);
    EXPECT_NEAR(pts[2].mean_tension_lbf, std::sqrt(stored[0] * stored[1]), 1e-9 * stored[1]);
    EXPECT_NEAR(pts[7].mean_tension_lbf, std::sqrt(stored[1] * stored[2]), 1e-9 * stored[2]);
    for (const auto& pt : asked.at("FFG 7|180|given-60k")) EXPECT_EQ(pt.mean_tension_lbf, 60000.0);
    // Each stored row: the grid and the function's values in kips, binary16.
    auto rows = d.prepare(
        "SELECT p.speed_first_kt, p.speed_step_kt, p.speeds, p.sigma_kips_f16, c.tow_name, c.heading_deg, "
        "c.mean_tension_label FROM speed_profiles p JOIN cases c ON c.speed_profile_id = p.speed_profile_id "
        "WHERE c.speed_kt = 5");
    int n = 0;
    while (rows.step()) {
      ++n;
      EXPECT_EQ(rows.column_double(0), 5.0);
      EXPECT_EQ(rows.column_double(1), 0.25);
      ASSERT_EQ(rows.column_int(2), 11);
      const auto& line = asked.at(rows.column_text(4) + "|" + sweep::canonical_number(rows.column_double(5)) + "|" +
                                  rows.column_text(6));
      std::vector<double> expected;
      for (const auto& pt : line) {
        expected.push_back(units::n_to_kips(1000.0 * (1.0 + pt.speed_kt / 10.0) * (1.0 + pt.mean_tension_lbf / 1e6)));
      }
      std::string packed;
      ASSERT_TRUE(store::pack_float16(expected, &packed));
      EXPECT_EQ(rows.column_blob(3), packed);
    }
    EXPECT_EQ(n, 6);
  }
  // One thread: the same rows; a second build: none computed (the failing lines tried again).
  const fs::path one = f.dir / "one.db";
  f.build(one, 1, make_test_runner(), o);
  EXPECT_EQ(dump_database(one, provenance_columns()), dump_database(db, provenance_columns()));
  const sweep::BuildSummary again = f.build(db, 2, make_test_runner(), o);
  EXPECT_EQ(again.speed_profiles.up_to_date, 6);
  EXPECT_EQ(again.speed_profiles.computed, 0);
  // A stop request during the stage: interrupted, nothing written, resumed to the same rows.
  const fs::path stopped = f.dir / "stopped.db";
  std::atomic<bool> stop{false};
  sweep::BuildOptions stopping = o;
  stopping.stop = &stop;
  stopping.speed_profile = [&](const sweep::CaseSpec& spec, const io::ShipCatalog& catalog,
                               const std::vector<sweep::SpeedPoint>& points) {
    stop = true;  // the warm-up's first call asks to stop
    return closed_form(spec, catalog, points);
  };
  const sweep::BuildSummary cut = f.build(stopped, 2, make_test_runner(), stopping);
  EXPECT_TRUE(cut.interrupted);
  EXPECT_EQ(query_int(stopped, "SELECT count(*) FROM speed_profiles"), 0);
  const sweep::BuildSummary resumed = f.build(stopped, 2, make_test_runner(), o);
  EXPECT_EQ(resumed.speed_profiles.computed, 6);
  EXPECT_EQ(dump_database(stopped, provenance_columns()), dump_database(db, provenance_columns()));
}

TEST(SweepBuild, SpeedProfileLineFoldsHeadingsAndSkipsTwoTensionsAtOneSpeed) {  // sweep-build-19
  Fixture f;
  f.file = sweep::parse_sweep(R"(format = "towdb-sweep-1"
description = "folded headings"
[defaults]
days = 20
base_seed = 3
[[grid]]
label = "folded"
tugs = ["T-ATF 166"]
tows = ["FFG 7"]
speeds_kt = [5.0, 6.0]
winds_kt = [20.0]
headings_deg = [30.0, 330.0]
towlines = [ { line = "wire", length_ft = 1000.0 } ]
mean_tensions = [ { label = "given-60k", basis = "given", value_lbf = 60000.0 } ]
)", "folded.toml");
  f.cases = sweep::expand_sweep(f.file, f.catalog).cases;
  ASSERT_EQ(f.cases.size(), 4u);
  sweep::BuildOptions o;
  o.speed_profile = [](const sweep::CaseSpec&, const io::ShipCatalog&, const std::vector<sweep::SpeedPoint>& points) {
    return std::vector<double>(points.size(), 1000.0);
  };
  const fs::path db = f.dir / "folded.db";
  const sweep::BuildSummary s = f.build(db, 2, make_test_runner(), o);
  // 30 and 330 deg are one line: one profile of 5 speeds, all four cases pointed at it.
  EXPECT_EQ(s.speed_profiles.lines, 1);
  EXPECT_EQ(s.speed_profiles.computed, 1);
  EXPECT_EQ(query_int(db, "SELECT speeds FROM speed_profiles"), 5);
  EXPECT_EQ(query_int(db, "SELECT count(*) FROM cases WHERE speed_profile_id IS NOT NULL"), 4);

  // Two mean tensions at one speed under one label (a given tension edited at one speed): no line.
  f.cases[1].mean_tension_lbf = 61000.0;
  const fs::path two = f.dir / "two.db";
  const sweep::BuildSummary t = f.build(two, 2, make_test_runner(), o);
  EXPECT_EQ(t.speed_profiles.lines, 0);
  EXPECT_EQ(query_int(two, "SELECT count(*) FROM speed_profiles"), 0);
}

TEST(SweepBuild, ProfilesLeaveOutTheWaveInducedSurgeDamping) {  // sweep-build-20
  Fixture f;
  const sweep::CaseSpec& spec = f.cases.front();  // the small sweep's first case, at 5 kt
  const model::Vessel& tug = f.catalog.vessel(spec.tug).vessel;
  const model::Vessel& tow = f.catalog.vessel(spec.tow).vessel;
  simulation::CaseInputs in;
  in.tug = &tug;
  in.tow = &tow;
  in.towline = f.catalog.towline(tug, spec.line, spec.length_m());
  in.speed_m_s = spec.speed_m_s();
  in.sea = sweep::sea_state(spec.sea, 180.0);
  in.mean_tension_n = spec.mean_tension_n();
  in.days = spec.days;
  in.seed = static_cast<std::uint64_t>(spec.seed);

  const simulation::CaseOptions chain;
  ASSERT_TRUE(chain.wave_surge_damping);
  simulation::CaseOptions without = chain;
  without.wave_surge_damping = false;
  EXPECT_FALSE(sweep::profile_options(chain).wave_surge_damping);

  const std::vector<double> headings{180.0};
  const std::vector<double> profile = sweep::linear_heading_profile(chain)(spec, f.catalog, headings);
  ASSERT_EQ(profile.size(), 1u);
  EXPECT_EQ(profile[0], simulation::linear_tension_sigma_by_heading_n(in, without, headings)[0]);
  // In head seas the wave-induced damping is not zero, so the chain's own
  // linear sigma differs: the option is what the profile leaves out.
  EXPECT_NE(profile[0], simulation::linear_tension_sigma_by_heading_n(in, chain, headings)[0]);

  sweep::SpeedPoint point;
  point.speed_kt = spec.speed_kt;
  point.mean_tension_lbf = spec.mean_tension_lbf;
  sweep::CaseSpec head = spec;
  head.heading_deg = 180.0;
  const std::vector<double> along_speed = sweep::linear_speed_profile(chain)(head, f.catalog, {point});
  ASSERT_EQ(along_speed.size(), 1u);
  EXPECT_EQ(along_speed[0], std::sqrt(simulation::linear_tension_variance_n2(in, without)));
}

}  // namespace
}  // namespace towdb::test
