// CLI tests for `towdb build`, `towdb status`, `towdb sweep calibration` and
// `towdb mean-tension` (exit codes 0 ok, 1 failed cases, 2 bad input).
// Test plan:
//   cli-build-1  build --dry-run of the Table 5-3 grid: count line, 2880 = cases + 12 x skipped
//   cli-build-2  a real two-case build through the simulation chain, 1 and 2 threads identical;
//                the catenary's lowest point stored with each fit and, when missing (a fit
//                of schema 5), filled by the next build with the same bits
//   cli-build-3  a bad sweep file: exit 2 with file:line:key; an existing database is untouched
//   cli-build-4  status of a built database (text and JSON); dry run against it (states, nothing
//                written); missing and corrupt databases: 2
//   cli-build-5  sweep calibration reproduces the committed db/sweeps/appendix_c_calibration.toml
//   cli-build-6  mean-tension: components add up (EQ-SWEEP-1), margin 0.25 / 0.10 scales the hull,
//                free propeller = half locked, thesis eq. 2.9 direction correction of the sea term
//   cli-build-7  a database made on another machine kind (meta.numerics_fingerprint): the dry run
//                says a build would be refused (text, JSON); the build exits 2 naming both
//                fingerprints, the file's bytes unchanged; with nothing to compute, no refusal
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include "sweep/build/numerics.hpp"
#include "sweep/sweep.hpp"
#include "sweep_test_runner.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

namespace fs = std::filesystem;

// The first column of a SQL query's first row as text ("" if none).
std::string query_text(const fs::path& path, const std::string& sql) {
  sqlite3* db = nullptr;
  std::string v;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_stmt* st = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &st, nullptr) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW &&
        sqlite3_column_text(st, 0) != nullptr) {
      v = reinterpret_cast<const char*>(sqlite3_column_text(st, 0));
    }
    sqlite3_finalize(st);
  }
  sqlite3_close(db);
  return v;
}

bool exec_sql(const fs::path& path, const std::string& sql) {
  sqlite3* db = nullptr;
  bool ok = sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK &&
            sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK;
  sqlite3_close(db);
  return ok;
}

std::string last_line(const std::string& text) {
  std::string t = text;
  while (!t.empty() && t.back() == '\n') t.pop_back();
  const auto nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

TEST(CliBuild, DryRunListsTheThesisGrid) {  // cli-build-1
  const CommandResult r = run_towdb("build --sweep db/sweeps/thesis_table_5_3.toml --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int cases = 0, to_compute = 0, skipped = 0;
  const std::string line = last_line(r.out);
  ASSERT_EQ(std::sscanf(line.c_str(), "%d cases (%d to compute", &cases, &to_compute), 2) << line;
  const auto semicolon = line.find("); ");
  ASSERT_NE(semicolon, std::string::npos);
  ASSERT_EQ(std::sscanf(line.c_str() + semicolon + 3, "%d conditions skipped", &skipped), 1) << line;
  // Thesis Table 5-3: 2 tugs x 5 tows x 2 speeds x 3 winds x 4 headings x 4 towlines x 3 tensions.
  EXPECT_EQ(cases + 12 * skipped, 2880) << line;
  EXPECT_EQ(to_compute, cases);  // no database given: everything is new
  EXPECT_NE(r.out.find("calculated+15%"), std::string::npos);
  const CommandResult j = run_towdb("build --sweep db/sweeps/thesis_table_5_3.toml --dry-run --json");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc.at("cases").get<int>(), cases);
  EXPECT_EQ(doc.at("case_list").size(), static_cast<std::size_t>(cases));
  EXPECT_EQ(doc.at("skipped_conditions").size(), static_cast<std::size_t>(skipped));
}

TEST(CliBuild, RealBuildThroughTheSimulationChain) {  // cli-build-2
  // Two short cases through the registered simulation chain: done rows with
  // results and every day, and the same database from 1 and 2 threads.
  const fs::path dir = make_temp_dir("towdb-cli-build");
  const char* sweep = R"(format = "towdb-sweep-1"
description = "two real cases"

[defaults]
days = 4
base_seed = 3

[[case]]
label = "real-wire"
tug = "T-ATF 166"
tow = "FFG 7"
speed_kt = 9.0
wind_kt = 20.0
heading_deg = 0.0
line = "wire"
length_ft = 2000.0
mean_tension_lbf = 50000.0

[[case]]
label = "real-fiber"
tug = "T-ATF 166"
tow = "FFG 7"
speed_kt = 9.0
wind_kt = 20.0
heading_deg = 0.0
line = "fiber"
length_ft = 1500.0
mean_tension_lbf = 50000.0
)";
  { std::ofstream(dir / "real.toml") << sweep; }
  const fs::path db1 = dir / "one.db", db2 = dir / "two.db";
  const CommandResult one = run_towdb("build --sweep '" + (dir / "real.toml").string() + "' --db '" + db1.string() +
                                      "' --threads 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const CommandResult two = run_towdb("build --sweep '" + (dir / "real.toml").string() + "' --db '" + db2.string() +
                                      "' --threads 2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const CommandResult s = run_towdb("status --db '" + db1.string() + "' --json");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.out.find("\"done\": 2"), std::string::npos) << s.out;
  // The thesis's finding (6.3.2): at the same conditions the wire line's
  // dynamic tension is above the fiber line's.
  const CommandResult csv = run_towdb("export --db '" + db1.string() + "' --format appendix-c");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  const CommandResult csv2 = run_towdb("export --db '" + db2.string() + "' --format appendix-c");
  EXPECT_EQ(csv.out, csv2.out);  // 1 and 2 threads: the same numbers
  std::istringstream lines(csv.out);
  std::string header, wire, fiber;
  std::getline(lines, header);
  std::getline(lines, wire);
  std::getline(lines, fiber);
  const auto last_field = [](const std::string& row) { return std::stod(row.substr(row.rfind(',') + 1)); };
  EXPECT_GT(last_field(wire), last_field(fiber)) << csv.out;
  EXPECT_GT(last_field(fiber), 0.0);
  // Schema 6: each fit stores its catenary's lowest point; a fit stored
  // without it (written before schema 6) gets the same bits from the next
  // build of the sweep, which says so.
  const std::string kLowest =
      "SELECT group_concat(quote(lowest_elevation_ft), ' ') FROM (SELECT lowest_elevation_ft FROM towline_fits "
      "ORDER BY fit_id)";
  const std::string stored = query_text(db1, kLowest);
  EXPECT_EQ(query_int(db1, "SELECT count(*) FROM towline_fits WHERE lowest_elevation_ft IS NOT NULL"), 2) << stored;
  ASSERT_TRUE(exec_sql(db1, "UPDATE towline_fits SET lowest_elevation_ft = NULL"));
  const CommandResult again = run_towdb("build --sweep '" + (dir / "real.toml").string() + "' --db '" +
                                        db1.string() + "' --threads 1");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("0 scheduled"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("the catenary's lowest point added to 2 towline fits"), std::string::npos) << again.out;
  EXPECT_EQ(query_text(db1, kLowest), stored);
  fs::remove_all(dir);
}

fs::path built_database(const fs::path& dir) {
  const io::ShipCatalog catalog = io::ShipCatalog::load(source_dir() / "ships");
  const sweep::SweepFile file = sweep::parse_sweep(kSmallSweepToml, "small.toml");
  const auto cases = sweep::expand_sweep(file, catalog).cases;
  TestRunnerOptions o;
  o.fail_when = [](const sweep::CaseSpec& s) { return s.sweep_label == "explicit-1"; };
  sweep::BuildOptions b;
  b.progress = false;
  const fs::path db = dir / "built.db";
  sweep::run_build(db, file, cases, catalog, make_test_runner(o), b);
  return db;
}

TEST(CliBuild, BadSweepFileIsNamed) {  // cli-build-3
  const fs::path dir = make_temp_dir("towdb-cli-build");
  const fs::path db = built_database(dir);
  const std::string before = read_text(db);
  std::string text = kSmallSweepToml;
  text.replace(text.find("winds_kt = [20.0]"), 17, "winds_knots = [20.0]");
  { std::ofstream(dir / "bad.toml") << text; }
  const CommandResult r = run_towdb("build --sweep '" + (dir / "bad.toml").string() + "' --db '" + db.string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.toml:13: grid[1].winds_knots: unknown key; wrong unit suffix? this table expects 'winds_kt'"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(db), before);
  // A ship file missing from the ships directory: the sweep's YRBM cases cannot be resolved.
  const fs::path ships = dir / "ships";
  fs::copy(source_dir() / "ships", ships, fs::copy_options::recursive);
  fs::remove(ships / "yrbm.toml");
  { std::ofstream(dir / "small.toml") << kSmallSweepToml; }
  const CommandResult no_ship = run_towdb("--ships-dir '" + ships.string() + "' build --sweep '" +
                                          (dir / "small.toml").string() + "' --db '" + db.string() + "'");
  EXPECT_EQ(no_ship.exit_code, 2);
  EXPECT_NE(no_ship.err.find("small.toml:8: [[grid]] 'small-grid': vessel 'YRBM' is not known"), std::string::npos)
      << no_ship.err;
  EXPECT_EQ(read_text(db), before);
  // A towline file missing: the catalog itself is refused.
  fs::remove(ships / "towlines/fiber-hawser.toml");
  const CommandResult no_line = run_towdb("--ships-dir '" + ships.string() + "' build --sweep '" +
                                          (dir / "small.toml").string() + "' --db '" + db.string() + "'");
  EXPECT_EQ(no_line.exit_code, 2);
  EXPECT_FALSE(no_line.err.empty());
  EXPECT_EQ(read_text(db), before);
  const CommandResult missing = run_towdb("build --sweep /nonexistent.toml --dry-run");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("/nonexistent.toml: cannot open the sweep file"), std::string::npos) << missing.err;
  const CommandResult directory = run_towdb("build --sweep '" + dir.string() + "' --dry-run");
  EXPECT_EQ(directory.exit_code, 2);
  EXPECT_NE(directory.err.find("is a directory, expected a sweep file"), std::string::npos) << directory.err;
  // Values that would only fail when the case is computed are refused up front
  // (each with the database untouched): a calm Pierson-Moskowitz sea, a tug
  // named as the tow, a mean tension at the towline's breaking strength.
  const std::string one_case = "format = \"towdb-sweep-1\"\ndescription = \"one case\"\n[[case]]\nlabel = \"one\"\ntug = \"T-ATF\"\ntow = \"FFG7\"\nspeed_kt = 9.0\n"
                               "wind_kt = 20.0\nheading_deg = 0.0\nline = \"wire\"\nlength_ft = 2000.0\n"
                               "mean_tension_lbf = 50000.0\ndays = 3\n";
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> refused = {
      {{"wind_kt = 20.0", "wind_kt = 0.0"}, "wind_kt = 0: a pierson-moskowitz sea needs at least 1 kt"},
      {{"tow = \"FFG7\"", "tow = \"ARS50\""}, "'ARS50' is not a tow"},
      {{"mean_tension_lbf = 50000.0", "mean_tension_lbf = 360000.0"},
       "mean_tension_lbf = 360000: must be below the towline's breaking strength, 360000 lbf"},
  };
  for (const auto& [change, message] : refused) {
    std::string text_case = one_case;
    text_case.replace(text_case.find(change.first), change.first.size(), change.second);
    { std::ofstream(dir / "one.toml") << text_case; }
    const CommandResult r1 = run_towdb("build --sweep '" + (dir / "one.toml").string() + "' --db '" + db.string() + "'");
    EXPECT_EQ(r1.exit_code, 2) << change.second;
    EXPECT_NE(r1.err.find(message), std::string::npos) << r1.err;
    EXPECT_EQ(read_text(db), before);
  }
  { std::ofstream(dir / "one.toml") << one_case; }
  const CommandResult json_build =
      run_towdb("build --sweep '" + (dir / "one.toml").string() + "' --db '" + db.string() + "' --json");
  EXPECT_EQ(json_build.exit_code, 2);
  EXPECT_NE(json_build.err.find("build --json: only with --dry-run"), std::string::npos) << json_build.err;
  EXPECT_EQ(read_text(db), before);
  fs::remove_all(dir);
}

TEST(CliBuild, StatusSummarisesABuild) {  // cli-build-4
  const fs::path dir = make_temp_dir("towdb-cli-build");
  const fs::path db = built_database(dir);
  const CommandResult j = run_towdb("status --db '" + db.string() + "' --json");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc.at("cases").get<int>(), 18);
  EXPECT_EQ(doc.at("cases_by_status").at("done").get<int>(), 17);
  EXPECT_EQ(doc.at("cases_by_status").at("failed").get<int>(), 1);
  EXPECT_EQ(doc.at("results").get<int>(), 17);
  EXPECT_EQ(doc.at("builds").size(), 1u);
  EXPECT_EQ(doc.at("builds")[0].at("status").get<std::string>(), "completed");
  EXPECT_EQ(doc.at("speed_profiles").get<int>(), 0);  // one speed in the small sweep: no line along speed
  EXPECT_EQ(doc.at("cases_with_speed_profile").get<int>(), 0);
  ASSERT_EQ(doc.at("failed_cases").size(), 1u);
  EXPECT_EQ(doc.at("failed_cases")[0].at("sweep_label").get<std::string>(), "explicit-1");
  const CommandResult t = run_towdb("status --db '" + db.string() + "'");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("cases: 18, 17 done, 1 failed, 0 pending, 0 running"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("catenary solver did not converge"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("speed profiles (query EQ-QUERY-12): 0, used by 0 cases"), std::string::npos) << t.out;

  // A dry run against the built database: what a build would do, nothing written.
  const std::string before = read_text(db);
  { std::ofstream(dir / "small.toml") << kSmallSweepToml; }
  const CommandResult dry =
      run_towdb("build --sweep '" + (dir / "small.toml").string() + "' --db '" + db.string() + "' --dry-run");
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_EQ(last_line(dry.out), "18 cases (0 to compute, 17 done, 1 failed); 0 conditions skipped");
  EXPECT_EQ(read_text(db), before);

  const CommandResult missing = run_towdb("status --db '" + (dir / "none.db").string() + "'");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("database does not exist"), std::string::npos) << missing.err;
  { std::ofstream(dir / "junk.db", std::ios::binary) << std::string(4096, 'x'); }
  const CommandResult junk = run_towdb("status --db '" + (dir / "junk.db").string() + "'");
  EXPECT_EQ(junk.exit_code, 2);
  EXPECT_NE(junk.err.find("junk.db"), std::string::npos) << junk.err;
  fs::remove_all(dir);
}

TEST(CliBuild, CalibrationSweepIsReproduced) {  // cli-build-5
  // The repository's copy of the thesis table (tests/data/validation/README.md): no skip on a clean clone.
  const fs::path csv = source_dir() / "tests/data/validation/appendix_c_calibration.csv";
  ASSERT_TRUE(fs::exists(csv)) << csv;
  const CommandResult r = run_towdb("sweep calibration --csv '" + csv.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, read_text(source_dir() / "db/sweeps/appendix_c_calibration.toml"));
  const CommandResult dry = run_towdb("build --sweep db/sweeps/appendix_c_calibration.toml --dry-run");
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_EQ(last_line(dry.out), "240 cases (240 to compute, 240 new); 0 conditions skipped");
}

nlohmann::json mean_tension(const std::string& args) {
  const CommandResult r = run_towdb("mean-tension " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

TEST(CliBuild, MeanTensionBreakdown) {  // cli-build-6
  // EVIDENCE-OF: EQ-SWEEP-1
  constexpr double kSumRelTol = 1e-12;  // sums of the printed doubles
  const auto base = mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 180");
  const double tow = base.at("hull_lbf").get<double>() + base.at("propeller_lbf").get<double>() +
                     base.at("wind_lbf").get<double>() + base.at("sea_lbf").get<double>();
  EXPECT_REL_CLOSE(base.at("tow_resistance_lbf").get<double>(), tow, kSumRelTol);
  EXPECT_REL_CLOSE(base.at("total_lbf").get<double>(), 1.10 * tow, kSumRelTol);  // 10 % towline drag
  EXPECT_EQ(base.at("sea_lbf").get<double>(), 0.0);
  EXPECT_REL_CLOSE(base.at("relative_wind_kt").get<double>(), 25.0, kSumRelTol);  // head wind: V + U
  EXPECT_REL_CLOSE(base.at("grid_calculated_plus_15_lbf").get<double>(), 1.15 * base.at("total_lbf").get<double>(),
                   kSumRelTol);
  // Towing Manual margin 0.25 vs the thesis's 0.10: the hull term scales by 1.25 / 1.10.
  const auto manual = mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 180 --margin 0.25");
  EXPECT_REL_CLOSE(manual.at("hull_lbf").get<double>() / base.at("hull_lbf").get<double>(), 1.25 / 1.10, kSumRelTol);
  // Towing Manual: a free-spinning propeller has half the locked drag.
  const auto free_prop = mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 180 --propeller free");
  EXPECT_REL_CLOSE(free_prop.at("propeller_lbf").get<double>(), 0.5 * base.at("propeller_lbf").get<double>(),
                   kSumRelTol);
  EXPECT_EQ(mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 180 --propeller removed")
                .at("propeller_lbf")
                .get<double>(),
            0.0);
  // Thesis eq. 2.9: R_S = R_S,head cos(theta), theta from head seas (= 180 - heading), 0 beyond 90 deg.
  constexpr double kCosRelTol = 1e-12;
  EXPECT_REL_CLOSE(mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 180 --sea-head-lbf 10000")
                       .at("sea_lbf")
                       .get<double>(),
                   10000.0, kCosRelTol);
  EXPECT_REL_CLOSE(mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 120 --sea-head-lbf 10000")
                       .at("sea_lbf")
                       .get<double>(),
                   5000.0, kCosRelTol);
  EXPECT_EQ(mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 60 --sea-head-lbf 10000")
                .at("sea_lbf")
                .get<double>(),
            0.0);
  // Strip-theory sea resistance (thesis eq. 2.2): positive in head seas; the
  // "head" variant uses 180 deg whatever the heading; zero aft of beam (EQ-AR-4).
  const double rs_head = mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 30 --heading-deg 180 --sea-resistance "
                                      "strip-theory")
                             .at("sea_lbf")
                             .get<double>();
  EXPECT_GT(rs_head, 0.0);
  EXPECT_EQ(mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 30 --heading-deg 60 --sea-resistance strip-theory-head")
                .at("sea_lbf")
                .get<double>(),
            rs_head);
  EXPECT_EQ(mean_tension("--tow FFG7 --speed-kt 5 --wind-kt 30 --heading-deg 0 --sea-resistance strip-theory")
                .at("sea_lbf")
                .get<double>(),
            0.0);
  const CommandResult both = run_towdb(
      "mean-tension --tow FFG7 --speed-kt 5 --wind-kt 30 --heading-deg 180 --sea-resistance strip-theory "
      "--sea-head-lbf 1000");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--sea-head-lbf"), std::string::npos) << both.err;
  const CommandResult text = run_towdb("mean-tension --tow FFG7 --speed-kt 5 --wind-kt 20 --heading-deg 180");
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("sweep grid tensions (thesis ch. 5)"), std::string::npos) << text.out;
  const CommandResult missing = run_towdb("mean-tension --speed-kt 5 --wind-kt 20 --heading-deg 180");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("--tow"), std::string::npos) << missing.err;
  const CommandResult unknown = run_towdb("mean-tension --tow Titanic --speed-kt 5 --wind-kt 20 --heading-deg 180");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("Titanic"), std::string::npos) << unknown.err;
}


TEST(CliBuild, DatabaseOfAnotherMachineKindIsNotExtended) {  // cli-build-7
  const fs::path dir = make_temp_dir("towdb-cli-build-numerics");
  const fs::path db = dir / "other.sqlite";
  fs::copy_file(source_dir() / "db" / "towdb.sqlite", db);
  {
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open(db.c_str(), &raw), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(raw, "UPDATE meta SET value = '0123456789abcdef' WHERE key = 'numerics_fingerprint'",
                           nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(raw);
  }
  const std::string before = read_text(db);
  const std::string extra = "--sweep db/sweeps/thesis_table_5_3_extra_headings.toml --db '" + db.string() + "'";

  const CommandResult dry = run_towdb("build " + extra + " --dry-run");
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_NE(last_line(dry.out).find("records numerics fingerprint 0123456789abcdef"), std::string::npos) << dry.out;
  EXPECT_NE(last_line(dry.out).find("a build here would be refused"), std::string::npos) << dry.out;
  const CommandResult json = run_towdb("build " + extra + " --dry-run --json");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc.at("numerics_fingerprint").at("database").get<std::string>(), "0123456789abcdef");
  EXPECT_TRUE(doc.at("numerics_fingerprint").at("build_refused").get<bool>());

  const CommandResult build = run_towdb("build " + extra + " --threads 1");
  EXPECT_EQ(build.exit_code, 2);
  EXPECT_NE(build.err.find("meta.numerics_fingerprint = 0123456789abcdef"), std::string::npos) << build.err;
  EXPECT_NE(build.err.find(sweep::numerics_fingerprint()), std::string::npos) << build.err;  // this machine's
  EXPECT_EQ(read_text(db), before) << "the file was changed";

  // Every case of the bundled sweep is done: nothing to compute, nothing refused.
  const CommandResult same =
      run_towdb("build --sweep db/sweeps/bundled.toml --db '" + db.string() + "' --dry-run --json");
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_FALSE(nlohmann::json::parse(same.out).at("numerics_fingerprint").at("build_refused").get<bool>());
  fs::remove_all(dir);
}
}  // namespace
}  // namespace towdb::test
