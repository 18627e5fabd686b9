// CLI tests for `towdb validate` (thesis Appendix C comparison).
// Test plan:
//   cli-validate-1  a two-case table, one case that cannot run: exit 0, the
//                   failure is reported with its message, the other case has
//                   a ratio; report.md and cases.csv are written
//   cli-validate-2  a second invocation resumes: the ok case is reused
//                   bit for bit, not recomputed; other options are refused
//   cli-validate-3  bad arguments -> exit 2 with a named message
//   cli-validate-4  --database: each case asked of the bundled database; an answer is
//                   the one `towdb query` gives at the same inputs, bit for bit; a
//                   question outside the stored span is reported as refused, naming it;
//                   simulation options, a missing database and an --out that holds a
//                   simulation run's journal exit 2, nothing written
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace towdb::test {
namespace {

// Thesis Appendix C run 206 (T-ATF / FFG 7, 9 kt, 20 kt wind, head seas,
// 800 ft fiber, 79,000 lbf: 98.5 kips), and the same row with a mean tension
// above the hawser's breaking strength (parses, but the case cannot run).
constexpr const char* kTable =
    "case,tug,tow,speed_kt,wind_kt,heading_deg,length_ft,line,mean_lbf,days,dyn_kips\n"
    "206,T-ATF,FFG7,9.0,20.0,180.0,800.0,f,79000.0,500,98.5\n"
    "9999,T-ATF,FFG7,9.0,20.0,180.0,800.0,f,900000.0,500,98.5\n";

TEST(CliValidate, ReportsFailuresAndResumes) {  // cli-validate-1, cli-validate-2
  const auto dir = make_temp_dir("towdb-validate");
  { std::ofstream(dir / "table.csv") << kTable; }
  const std::string base = "validate --cases '" + (dir / "table.csv").string() + "' --out '" + (dir / "out").string() +
                           "' --days-scale 0.02 --response-frequencies 16 --no-plot";
  const std::string args = base + " --min-days 10";
  const CommandResult first = run_towdb(args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::string report = test::read_text(dir / "out" / "report.md");
  EXPECT_NE(report.find("## Targets"), std::string::npos);
  EXPECT_NE(report.find("| 9999 | T-ATF 166 | FFG 7 |"), std::string::npos) << report;
  EXPECT_NE(report.find("breaking strength"), std::string::npos) << report;
  const std::string journal = test::read_text(dir / "out" / "cases.csv");
  const auto ok_line = journal.find("\n206,T-ATF 166,FFG 7,");
  ASSERT_NE(ok_line, std::string::npos) << journal;
  const std::string line206 = journal.substr(ok_line + 1, journal.find('\n', ok_line + 1) - ok_line - 1);
  EXPECT_NE(line206.find(",10,ok,"), std::string::npos) << line206;  // 0.02 x 500 = 10 days

  const CommandResult second = run_towdb(args);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.err.find("2 cases (1 from"), std::string::npos) << second.err;
  const std::string journal2 = test::read_text(dir / "out" / "cases.csv");
  // The ok line is reused verbatim (same tension digits and run time).
  EXPECT_NE(journal2.find(line206), std::string::npos) << journal2;

  // Other options must not mix into the same journal.
  const CommandResult other = run_towdb(base + " --min-days 11");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("other options or ship files"), std::string::npos) << other.err;
  std::filesystem::remove_all(dir);
}

TEST(CliValidate, BadArgumentsExitTwo) {  // cli-validate-3
  const CommandResult missing = run_towdb("validate --out /tmp/x");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("--cases"), std::string::npos) << missing.err;
  const auto dir = make_temp_dir("towdb-validate-bad");
  { std::ofstream(dir / "table.csv") << kTable; }
  const CommandResult filter = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                         (dir / "out").string() + "' --filter colour=red");
  EXPECT_EQ(filter.exit_code, 2);
  EXPECT_NE(filter.err.find("unknown key 'colour'"), std::string::npos) << filter.err;
  const CommandResult nothing = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                          (dir / "out").string() + "' --filter tow=YRBM");
  EXPECT_EQ(nothing.exit_code, 2);
  EXPECT_NE(nothing.err.find("no cases selected"), std::string::npos) << nothing.err;
  // The output directory must be one (or be creatable in an existing one) ...
  const CommandResult out_file = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                           (dir / "table.csv").string() + "'");
  EXPECT_EQ(out_file.exit_code, 2);
  EXPECT_NE(out_file.err.find("--out = " + (dir / "table.csv").string() + ": is a file"), std::string::npos)
      << out_file.err;
  const CommandResult out_deep = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                           (dir / "no" / "such" / "out").string() + "'");
  EXPECT_EQ(out_deep.exit_code, 2);
  EXPECT_NE(out_deep.err.find("its parent directory"), std::string::npos) << out_deep.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
  const CommandResult slash = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                        (dir / "new").string() + "/' --filter tow=YRBM");
  EXPECT_EQ(slash.exit_code, 2);
  EXPECT_NE(slash.err.find("no cases selected"), std::string::npos) << slash.err;  // "new/" is a new directory
  // ... and every row's values in the ranges a sweep file accepts, the tug a tug.
  const std::string header = "case,tug,tow,speed_kt,wind_kt,heading_deg,length_ft,line,mean_lbf,days,dyn_kips\n";
  const std::vector<std::pair<std::string, std::string>> rows = {
      {"7,T-ATF,FFG7,9.0,20.0,400.0,800.0,f,79000.0,500,98.5", "table.csv:2: heading_deg = 400: must be in [0, 360]"},
      {"7,T-ATF,FFG7,9.0,20.0,0.0,800.0,f,79000.0,0,98.5", "table.csv:2: days = 0: must be in [1,"},
      {"7,T-ATF,FFG7,9.0,0.0,0.0,800.0,f,79000.0,500,98.5", "table.csv:2: wind_kt = 0: must be in [1, 100]"},
      {"7,FFG7,FFG7,9.0,20.0,0.0,800.0,f,79000.0,500,98.5", "table.csv:2: tug 'FFG7' is not a tug"},
  };
  for (const auto& [row, message] : rows) {
    { std::ofstream(dir / "table.csv") << header << row << "\n"; }
    const CommandResult r = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                      (dir / "rows").string() + "'");
    EXPECT_EQ(r.exit_code, 2) << row;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "rows")) << row;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliValidate, DatabaseAnswersAreTheQuerysAndRefusalsAreNamed) {  // cli-validate-4
  const auto dir = make_temp_dir("towdb-validate-db");
  // Run 206 (inside the bundled database's span) and thesis run 1045's inputs at 3 kt
  // (ARS 50 / AE 26, 800 ft fiber, 30 kt, 0 deg), below its stored 5-8.5 kt.
  {
    std::ofstream(dir / "table.csv") << "case,tug,tow,speed_kt,wind_kt,heading_deg,length_ft,line,mean_lbf,days,"
                                        "dyn_kips\n206,T-ATF,FFG7,9.0,20.0,180.0,800.0,f,79000.0,500,98.5\n"
                                        "1045,ARS50,AE26,3.0,30.0,0.0,800.0,f,84000.0,500,50.0\n";
  }
  const std::string base = "validate --cases '" + (dir / "table.csv").string() + "' --out '" + (dir / "out").string() +
                           "' --no-plot --database db/towdb.sqlite";
  const CommandResult r = run_towdb(base);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1 of 2 thesis cases answered"), std::string::npos) << r.out;
  const std::string report = test::read_text(dir / "out" / "report.md");
  EXPECT_NE(report.find("refused, by the input named first: speed_kt 1"), std::string::npos) << report;
  EXPECT_NE(report.find("| 1045 | ARS 50 | AE 26 | refused: speed_kt = 3 is outside the stored range"),
            std::string::npos)
      << report;

  const std::string journal = test::read_text(dir / "out" / "cases.csv");
  const auto at = journal.find("\n206,T-ATF 166,FFG 7,");
  ASSERT_NE(at, std::string::npos) << journal;
  std::vector<std::string> fields;
  std::stringstream line(journal.substr(at + 1, journal.find('\n', at + 1) - at - 1));
  for (std::string f; std::getline(line, f, ',');) fields.push_back(f);
  ASSERT_GE(fields.size(), 14u);
  EXPECT_EQ(fields[12], "ok");
  const CommandResult q = run_towdb(
      "query --db db/towdb.sqlite --tug T-ATF --tow FFG7 --line fiber --speed-kt 9 --wind-kt 20 --heading-deg 180 "
      "--length-ft 800 --mean-tension-lbf 79000 --json");
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_EQ(std::stod(fields[13]), nlohmann::json::parse(q.out).at("dynamic_999_kips").get<double>());

  // Simulation options have no meaning here; a database that is not there is named.
  const CommandResult mixed = run_towdb(base + " --days-scale 0.1");
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_NE(mixed.err.find("--days-scale"), std::string::npos) << mixed.err;
  const CommandResult missing = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                          (dir / "out2").string() + "' --database '" + (dir / "none.sqlite").string() +
                                          "'");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("--database = " + (dir / "none.sqlite").string()), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out2"));
  // A simulation run's journal (its resume state) is never overwritten.
  std::filesystem::create_directories(dir / "sim");
  { std::ofstream(dir / "sim" / "run-signature.txt") << "options\n"; }
  { std::ofstream(dir / "sim" / "cases.csv") << "journal\n"; }
  const CommandResult over = run_towdb("validate --cases '" + (dir / "table.csv").string() + "' --out '" +
                                       (dir / "sim").string() + "' --database db/towdb.sqlite");
  EXPECT_EQ(over.exit_code, 2);
  EXPECT_NE(over.err.find("holds a simulation run's journal"), std::string::npos) << over.err;
  EXPECT_EQ(test::read_text(dir / "sim" / "cases.csv"), "journal\n");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace towdb::test
