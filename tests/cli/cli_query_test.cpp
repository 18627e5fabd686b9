// CLI tests for `towdb query`, `max-speed`, `min-length` and `export`.
// Test plan:
//   cli-query-1  query --json has the documented keys and the interpolated value
//   cli-query-2  --csv prints one header and one row; text output names the checks with their margins;
//                a failed check exits 3, both passed 0
//   cli-query-3  --batch answers every CSV row; a bad row is reported and exits 2
//   cli-query-4  bad input (unknown vessel, NaN, length < 0, heading 400, p = 0 and 1,
//                missing flags, missing or corrupt database) -> exit 2 with a named message; a
//                question outside the stored span names the `towdb simulate` command that
//                computes it directly, and that command runs
//   cli-query-5  max-speed / min-length land on the analytic crossing
//   cli-query-6  thesis Appendix C rows: each answered exactly at its node (batch), and
//                export --format appendix-c reproduces the rows
//   cli-query-7  export --format posse-csv: the documented header (schema/posse-csv.md)
//   cli-query-8  query --leave-one-out --json reports both spaces and the chosen one
//   cli-query-9  --hs-ft on a wind-sea database: answered at the equivalent wind (text, JSON, CSV); a far
//                --tp-s exits 2 naming both periods (EQ-QUERY-10)
//   cli-query-10 the README's question on the bundled database: the catenary's lowest point in
//                text (above or below the waterline), JSON and CSV (schema 6)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../query/synthetic_db.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

using nlohmann::json;

// One CLI process writes doubles with shortest round-trip text: exact.
constexpr double kRoundTripRelTol = 1e-15;

class CliQuery : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("towdb-cli-query");
    // dynamic_999 = 250 + 10 s - 0.1 l + 0.5 w + 5 y_999, beta = 5 kips, mean 70,000 lbf.
    GridSpec g;
    g.nominal_mean_lbf = [](double, double) { return 70000.0; };
    g.u_kips = [](double s, double w, double, double l, double) { return 250.0 + 10.0 * s - 0.1 * l + 0.5 * w; };
    g.beta_kips = [](double, double, double, double, double) { return 5.0; };
    db_ = (dir_ / "grid.towdb").string();
    write_synthetic_db(db_, grid_cases(g));
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static double expected_999(double s, double w, double l) {
    return 250.0 + 10.0 * s - 0.1 * l + 0.5 * w + 5.0 * reduced_variate_999();
  }
  std::string base() const {
    return "query --db '" + db_ + "' --tug T-ATF --tow 'LHA 1' --line wire --wind-kt 25 --heading-deg 300 ";
  }
  std::filesystem::path dir_;
  std::string db_;
};

TEST_F(CliQuery, JsonHasTheDocumentedKeys) {  // cli-query-1
  const CommandResult r = run_towdb(base() + "--speed-kt 6 --length-ft 1200 --mean-tension-lbf 70000 --json");
  ASSERT_EQ(r.exit_code, 3) << r.err;  // answered; the extreme check fails (below)
  const json j = json::parse(r.out);
  for (const char* key : {"dynamic_tension_kips", "extreme_tension_lbf", "breaking_strength_lbf", "checks", "warnings",
                          "nearest_cases", "uncertainty_kips"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  // Linear in every input: interpolation is exact (EQ-QUERY-6).
  EXPECT_REL_CLOSE(j.at("dynamic_tension_kips").get<double>(), expected_999(6.0, 25.0, 1200.0), 1e-12);
  EXPECT_REL_CLOSE(j.at("extreme_tension_lbf").get<double>(), 70000.0 + 1000.0 * expected_999(6.0, 25.0, 1200.0),
                   1e-12);
  EXPECT_EQ(j.at("breaking_strength_lbf").get<double>(), 360000.0);
  ASSERT_EQ(j.at("checks").size(), 2u);
  EXPECT_EQ(j.at("checks")[0].at("limit_lbf").get<double>(), 240000.0);
  EXPECT_EQ(j.at("checks")[1].at("limit_lbf").get<double>(), 120000.0);
  // Margins: limit - value, in lbf and percent of the limit (negative: failed).
  const double extreme = 70000.0 + 1000.0 * expected_999(6.0, 25.0, 1200.0);
  EXPECT_FALSE(j.at("checks")[0].at("passed").get<bool>());
  EXPECT_REL_CLOSE(j.at("checks")[0].at("margin_lbf").get<double>(), 240000.0 - extreme, 1e-9);
  EXPECT_REL_CLOSE(j.at("checks")[0].at("margin_percent").get<double>(), 100.0 * (240000.0 - extreme) / 240000.0, 1e-9);
  EXPECT_TRUE(j.at("checks")[1].at("passed").get<bool>());
  EXPECT_REL_CLOSE(j.at("checks")[1].at("margin_lbf").get<double>(), 50000.0, 1e-12);
  EXPECT_EQ(j.at("nearest_cases").size(), 4u);
  EXPECT_TRUE(j.at("warnings").is_array());
  EXPECT_EQ(j.at("query").at("heading_deg").get<double>(), 300.0);
  EXPECT_EQ(j.at("query").at("tow").get<std::string>(), "LHA 1");
  // Names as the database spells them, whatever the spelling asked (here "tatf", "lha-1").
  const CommandResult lower = run_towdb("query --db '" + db_ +
                                        "' --tug tatf --tow lha-1 --line wire --wind-kt 25 --heading-deg 300 "
                                        "--speed-kt 6 --length-ft 1200 --mean-tension-lbf 70000 --json");
  ASSERT_EQ(lower.exit_code, 3) << lower.err;
  EXPECT_EQ(json::parse(lower.out).at("query").at("tug").get<std::string>(), "T-ATF 166");
  EXPECT_EQ(json::parse(lower.out).at("query").at("tow").get<std::string>(), "LHA 1");
}

TEST_F(CliQuery, CsvAndTextOutput) {  // cli-query-2
  const CommandResult csv = run_towdb(base() + "--speed-kt 6 --length-ft 1200 --mean-tension-lbf 70000 --csv");
  ASSERT_EQ(csv.exit_code, 3) << csv.err;  // a failed check (README, "Exit codes")
  std::istringstream in(csv.out);
  std::string header, row, extra;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header.rfind("tug,tow,line,speed_kt,wind_kt,", 0), 0u) << header;
  EXPECT_NE(row.find(",fail,pass,"), std::string::npos) << row;  // 70 + 1000 x > 240,000 lbf
  // Computed values rounded as in the text (0.1 kips, 1 lbf); JSON keeps full precision.
  char expected_cells[96];
  std::snprintf(expected_cells, sizeof expected_cells, ",70000,0.001,1,%.1f,%.1f,%.0f,360000,",
                expected_999(6.0, 25.0, 1200.0), expected_999(6.0, 25.0, 1200.0),
                70000.0 + 1000.0 * expected_999(6.0, 25.0, 1200.0));
  EXPECT_NE(row.find(expected_cells), std::string::npos) << row << "\nexpected " << expected_cells;
  const CommandResult text = run_towdb(base() + "--speed-kt 6 --length-ft 1200 --mean-tension-lbf 70000");
  ASSERT_EQ(text.exit_code, 3) << text.err;
  EXPECT_NE(text.out.find("check extreme <= BS/1.5"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("FAIL (limit 240,000 lbf, exceeded by "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("pass (limit 120,000 lbf, margin 50,000 lbf = 41.7 %)"), std::string::npos) << text.out;
  // Both checks pass on the 2,000 ft line (157 kips + 70,000 lbf < 240,000 lbf): exit 0.
  const CommandResult ok = run_towdb(base() + "--speed-kt 6 --length-ft 2000 --mean-tension-lbf 70000");
  ASSERT_EQ(ok.exit_code, 0) << ok.err << ok.out;
  EXPECT_NE(text.out.find("nearest stored cases"), std::string::npos) << text.out;
}

TEST_F(CliQuery, BatchAnswersEveryRow) {  // cli-query-3
  const std::string input =
      "tug,tow,speed_kt,wind_kt,heading_deg,line,length_ft,mean_tension_lbf,probability,tow_days\n"
      "T-ATF,LHA1,6,25,60,wire,1200,70000,,\n"
      "T-ATF,LHA1,4,30,90,wire,900,65000,0.01,30\n"
      "Titanic,LHA1,6,25,60,wire,1200,70000,,\n";
  const CommandResult r = run_towdb("query --db '" + db_ + "' --batch --json", input);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("line 4: tug 'Titanic' is not in the database"), std::string::npos) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j.size(), 3u);
  EXPECT_REL_CLOSE(j[0].at("dynamic_tension_kips").get<double>(), expected_999(6.0, 25.0, 1200.0), 1e-12);
  // 30 days at p = 0.01: x = u + beta (ln 30 - ln(-ln 0.99)) (EQ-QUERY-2, -3).
  const double u = expected_999(4.0, 30.0, 900.0) - 5.0 * reduced_variate_999();
  EXPECT_REL_CLOSE(j[1].at("dynamic_tension_kips").get<double>(), u + 5.0 * (std::log(30.0) - std::log(-std::log(0.99))),
                   1e-12);
  EXPECT_TRUE(j[2].contains("error"));
  const CommandResult bad_header = run_towdb("query --db '" + db_ + "' --batch", "tug,tow,colour\nx,y,z\n");
  EXPECT_EQ(bad_header.exit_code, 2);
  EXPECT_NE(bad_header.err.find("unknown column 'colour'"), std::string::npos) << bad_header.err;
  const CommandResult twice = run_towdb("query --db '" + db_ + "' --batch", "tug,speed_kt,speed_kt\nT-ATF,6,7\n");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("column 'speed_kt' appears more than once"), std::string::npos) << twice.err;
}

TEST_F(CliQuery, BadInputExitsTwoWithANamedMessage) {  // cli-query-4
  const std::string ok = "--speed-kt 6 --length-ft 1200 ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"query --db '" + db_ + "' --tug Titanic --tow LHA1 --line wire --wind-kt 25 --heading-deg 0 " + ok,
       "tug 'Titanic' is not in the database"},
      {base() + "--speed-kt nan --length-ft 1200", "--speed-kt"},
      {base() + "--speed-kt 6 --length-ft -100", "--length-ft"},
      {"query --db '" + db_ + "' --tug T-ATF --tow LHA1 --line wire --wind-kt 25 --heading-deg 400 " + ok,
       "--heading-deg"},
      {base() + ok + "--probability 0", "--probability"},
      {base() + ok + "--probability 1", "--probability"},
      {"query --db '" + db_ + "' --tow LHA1 --line wire --wind-kt 25 --heading-deg 0 " + ok,
       "missing required option(s): --tug"},
      {base() + ok + "--speed-kt 12", ""},  // CLI11: --speed-kt given twice
      {"query --db '" + (dir_ / "missing.towdb").string() + "' --tug T-ATF --tow LHA1 --line wire --wind-kt 25 " +
           "--heading-deg 0 " + ok,
       "database does not exist"},
  };
  for (const auto& [args, text] : cases) {
    const CommandResult r = run_towdb(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(text), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
  {
    std::ofstream(dir_ / "corrupt.towdb", std::ios::binary) << std::string(4096, '\x7f');
  }
  const CommandResult corrupt = run_towdb("query --db '" + (dir_ / "corrupt.towdb").string() +
                                          "' --tug T-ATF --tow LHA1 --line wire --wind-kt 25 --heading-deg 0 " + ok);
  EXPECT_EQ(corrupt.exit_code, 2) << corrupt.err;
  EXPECT_NE(corrupt.err.find("corrupt.towdb"), std::string::npos) << corrupt.err;
  const CommandResult range = run_towdb(base() + "--speed-kt 12 --length-ft 1200 --mean-tension-lbf 70000");
  EXPECT_EQ(range.exit_code, 2);
  EXPECT_NE(range.err.find("speed_kt = 12 is outside the stored range [3, 9] kt"), std::string::npos) << range.err;
  // The refusal names the command that computes the question directly, and
  // that command runs (shortened to 3 days).
  const std::string hint = "or compute it directly: towdb ";
  const std::size_t at = range.err.find(hint);
  ASSERT_NE(at, std::string::npos) << range.err;
  std::string direct = range.err.substr(at + hint.size());
  direct = direct.substr(0, direct.find('\n'));
  const std::size_t days = direct.find(" --days 100");
  ASSERT_NE(days, std::string::npos) << direct;
  EXPECT_NE(direct.find("--speed-kt 12 "), std::string::npos) << direct;
  EXPECT_NE(direct.find("--mean-tension-lbf 70000 "), std::string::npos) << direct;
  const CommandResult simulated = run_towdb(direct.replace(days, 11, " --days 3 --json"));
  EXPECT_EQ(simulated.exit_code, 0) << direct << "\n" << simulated.err;
  const CommandResult extrap =
      run_towdb(base() + "--speed-kt 12 --length-ft 1200 --mean-tension-lbf 70000 --extrapolate --json");
  ASSERT_EQ(extrap.exit_code, 3) << extrap.err;  // answered; the extreme check fails
  const json j = json::parse(extrap.out);
  EXPECT_EQ(j.at("warnings")[0].at("kind").get<std::string>(), "extrapolated");
  EXPECT_REL_CLOSE(j.at("dynamic_tension_kips").get<double>(), expected_999(12.0, 25.0, 1200.0), 1e-12);
}

TEST_F(CliQuery, InverseQueries) {  // cli-query-5
  // EVIDENCE-OF: EQ-QUERY-5: 70,000 + 1000 x <= 240,000 lbf <=> x <= 170 kips.
  const std::string cond = "--db '" + db_ + "' --tug T-ATF --tow LHA1 --line wire --wind-kt 30 --heading-deg 60 "
                           "--mean-tension-lbf 70000 --json ";
  const CommandResult s = run_towdb("max-speed " + cond + "--length-ft 1800");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const json js = json::parse(s.out);
  ASSERT_TRUE(js.at("found").get<bool>());
  const double y = reduced_variate_999();
  EXPECT_ABS_CLOSE(js.at("max_speed_kt").get<double>(), (170.0 - 250.0 + 180.0 - 15.0 - 5.0 * y) / 10.0, 1e-5);
  const CommandResult l = run_towdb("min-length " + cond + "--speed-kt 6");
  ASSERT_EQ(l.exit_code, 0) << l.err;
  const json jl = json::parse(l.out);
  ASSERT_TRUE(jl.at("found").get<bool>());
  EXPECT_ABS_CLOSE(jl.at("min_length_ft").get<double>(), (250.0 + 60.0 + 15.0 + 5.0 * y - 170.0) / 0.1, 1e-2);
  const CommandResult none = run_towdb("max-speed " + cond + "--length-ft 800");
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_FALSE(json::parse(none.out).at("found").get<bool>());
  const CommandResult text = run_towdb("max-speed --db '" + db_ +
                                       "' --tug T-ATF --tow LHA1 --line wire --wind-kt 30 --heading-deg 60 "
                                       "--mean-tension-lbf 70000 --length-ft 800");
  EXPECT_NE(text.out.find("none passes"), std::string::npos) << text.out;
  // Conditions outside the stored data are bad input, as for query, not "none passes".
  const CommandResult outside = run_towdb("max-speed --db '" + db_ +
                                          "' --tug T-ATF --tow LHA1 --line wire --wind-kt 100 --heading-deg 60 "
                                          "--mean-tension-lbf 70000 --length-ft 1800");
  EXPECT_EQ(outside.exit_code, 2) << outside.out;
  EXPECT_NE(outside.err.find("no speed_kt in the stored range"), std::string::npos) << outside.err;
  EXPECT_NE(outside.err.find("wind_kt = 100 is outside the stored range"), std::string::npos) << outside.err;
}

// Canonical vessel names for the thesis labels of Appendix C.
std::string canonical(const std::string& label) {
  static const std::map<std::string, std::string> names = {{"T-ATF", "T-ATF 166"}, {"ARS50", "ARS 50"},
                                                           {"LHA1", "LHA 1"},      {"AE26", "AE 26"},
                                                           {"FFG7", "FFG 7"},      {"YRBM", "YRBM"}};
  return names.at(label);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

TEST(CliQueryThesis, AppendixCRowsAreAnsweredAndExported) {  // cli-query-6
  // Source: Desroches (1997) Appendix C, 240-row subset (tests/data/query/README.md).
  std::ifstream in(source_dir() / "tests/data/query/appendix_c_calibration.csv");
  ASSERT_TRUE(in) << "tests/data/query/appendix_c_calibration.csv";
  std::string header, line;
  std::getline(in, header);
  auto strip_cr = [](std::string& s) {
    if (!s.empty() && s.back() == '\r') s.pop_back();  // the file has CRLF line ends
  };
  strip_cr(header);
  std::vector<std::string> rows;
  std::vector<SyntheticCase> cases;
  std::string batch = "tug,tow,speed_kt,wind_kt,heading_deg,line,length_ft,mean_tension_lbf\n";
  std::vector<double> dyn;
  while (std::getline(in, line)) {
    strip_cr(line);
    if (line.empty()) continue;
    rows.push_back(line);
    const auto f = split(line);
    SyntheticCase c;
    c.case_id = std::stoll(f[0]);
    c.tug = canonical(f[1]);
    c.tow = canonical(f[2]);
    c.speed_kt = std::stod(f[3]);
    c.wind_kt = std::stod(f[4]);
    c.heading_deg = std::stod(f[5]);
    c.length_ft = std::stod(f[6]);
    c.line = f[7] == "w" ? "wire" : "fiber";
    c.mean_tension_lbf = std::stod(f[8]);
    c.days = std::stoi(f[9]);
    const double x = std::stod(f[10]);
    c.alpha_per_kip = 10.0 / x;  // beta = x / 10, u = x - beta y_999: dynamic_999 = x
    c.u_kips = x - x / 10.0 * reduced_variate_999();
    cases.push_back(c);
    dyn.push_back(x);
    batch += f[1] + "," + f[2] + "," + f[3] + "," + f[4] + "," + f[5] + "," + c.line + "," + f[6] + "," + f[8] + "\n";
  }
  ASSERT_EQ(rows.size(), 240u);
  const auto dir = make_temp_dir("towdb-cli-appc");
  const std::string db = (dir / "appc.towdb").string();
  write_synthetic_db(db, cases);

  const CommandResult q = run_towdb("query --db '" + db + "' --batch --json", batch);
  ASSERT_EQ(q.exit_code, 0) << q.err;
  const json j = json::parse(q.out);
  ASSERT_EQ(j.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_REL_CLOSE(j[i].at("dynamic_tension_kips").get<double>(), dyn[i], 1e-12) << rows[i];
  }

  const CommandResult e = run_towdb("export --db '" + db + "' --format appendix-c");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  std::istringstream out(e.out);
  std::string out_header;
  std::getline(out, out_header);
  EXPECT_EQ(out_header, header);
  std::vector<std::string> exported;
  while (std::getline(out, line)) exported.push_back(line);
  std::sort(rows.begin(), rows.end());
  std::sort(exported.begin(), exported.end());
  EXPECT_EQ(exported, rows);
  std::filesystem::remove_all(dir);
}

TEST_F(CliQuery, PosseCsvHasTheDocumentedHeader) {  // cli-query-7
  const CommandResult e = run_towdb("export --db '" + db_ + "' --format posse-csv");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  std::istringstream out(e.out);
  std::string header, first;
  std::getline(out, header);
  // schema/posse-csv.md, version 1 column list.
  EXPECT_EQ(header,
            "case_id,tug,tow,line_type,speed_kt,spectrum,wind_kt,hs_ft,tp_s,gamma,heading_deg,length_ft,"
            "mean_tension_lbf,mean_tension_label,days,gumbel_u_kips,gumbel_alpha_per_kip,dynamic_999_kips,"
            "dynamic_99_kips,ci_level,ci_low_kips,ci_high_kips,extreme_999_lbf,breaking_strength_lbf,"
            "above_breaking_strength,slack_fraction,snatch_events_per_day,code_version");
  std::getline(out, first);
  const auto f = split(first);
  ASSERT_GE(f.size(), 23u);
  // extreme_999_lbf = mean + 1000 dynamic_999 (EQ-QUERY-4), round-trip text.
  EXPECT_REL_CLOSE(std::stod(f[22]), std::stod(f[12]) + 1000.0 * std::stod(f[17]), kRoundTripRelTol);
  int count = 1;
  while (std::getline(out, first)) ++count;
  EXPECT_EQ(count, 4 * 3 * 4 * 3 * 3);  // grid_cases: 144 nodes, 3 mean tensions on average
  const CommandResult bad = run_towdb("export --db '" + db_ + "' --format xml");
  EXPECT_EQ(bad.exit_code, 2);
}

TEST_F(CliQuery, LeaveOneOutReport) {  // cli-query-8
  const CommandResult r = run_towdb("query --db '" + db_ + "' --leave-one-out --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j.at("chosen_space").get<std::string>(), "linear");  // linear data: exact in linear space
  bool saw_log = false;
  for (const auto& row : j.at("leave_one_out")) {
    if (row.at("space") == "linear") {
      EXPECT_LT(row.at("max_rel_error").get<double>(), 1e-12) << row.dump();
    }
    if (row.at("space") == "log") saw_log = true;
  }
  EXPECT_TRUE(saw_log);
}

TEST_F(CliQuery, HsIsAnsweredThroughTheEquivalentWind) {  // cli-query-9
  // Hs = 0.2092 U^2 / g (EQ-SEA-1): 25 kt = 12.861 m/s -> 3.5283 m = 11.576 ft; Tp = 2 pi U / (0.877 g) = 9.40 s.
  const std::string sea = "query --db '" + db_ +
                          "' --tug T-ATF --tow 'LHA 1' --line wire --heading-deg 300 --speed-kt 6 --length-ft 2000 "
                          "--mean-tension-lbf 70000 --hs-ft 11.5763 ";
  const CommandResult j = run_towdb(sea + "--tp-s 9.4 --json");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const json a = json::parse(j.out);
  EXPECT_NEAR(a.at("equivalent_wind_kt").get<double>(), 25.0, 1e-3);
  EXPECT_NEAR(a.at("dynamic_tension_kips").get<double>(), expected_999(6.0, 25.0, 2000.0), 1e-3);
  EXPECT_EQ(a.at("warnings")[0].at("kind").get<std::string>(), "equivalent_wind");
  const CommandResult text = run_towdb(sea);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("equivalent wind kt (fully developed sea of this Hs)  25.00"), std::string::npos)
      << text.out;
  const CommandResult csv = run_towdb(sea + "--csv");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_NE(csv.out.find("uncertainty_kips,catenary_sag_ft,catenary_depth_ft,equivalent_wind_kt,"), std::string::npos) << csv.out;
  EXPECT_NE(csv.out.find(",25.00,0,"), std::string::npos) << csv.out;
  const CommandResult swell = run_towdb(sea + "--tp-s 14");
  EXPECT_EQ(swell.exit_code, 2);
  EXPECT_NE(swell.err.find("tp_s = 14 s"), std::string::npos) << swell.err;
  EXPECT_NE(swell.err.find("has Tp = 9.4 s"), std::string::npos) << swell.err;
  EXPECT_TRUE(swell.out.empty());
}

}  // namespace
TEST(CliQueryBundled, CatenaryLowestPointIsInEveryOutput) {  // cli-query-10
  const std::string q = "query --db '" + (source_dir() / "db" / "towdb.sqlite").string() +
                        "' --tug T-ATF --tow FFG7 --line fiber --speed-kt 7 --wind-kt 30 --heading-deg 150 "
                        "--length-ft 1200 ";
  const CommandResult j = run_towdb(q + "--json");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const double depth = json::parse(j.out).at("catenary_depth_ft").get<double>();
  // A taut 1,200 ft fiber line at 67,000 lbf hangs between tow points 6-30 ft up: its lowest point
  // lies within a few tens of feet of the waterline.
  EXPECT_LT(std::abs(depth), 50.0);
  const CommandResult text = run_towdb(q);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  std::ostringstream shown;
  shown << std::fixed << std::setprecision(1) << std::abs(depth) << (depth >= 0.0 ? " below" : " above")
        << " the waterline";
  EXPECT_NE(text.out.find("catenary lowest point ft"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(shown.str()), std::string::npos) << text.out;
  const CommandResult csv = run_towdb(q + "--csv");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  std::ostringstream cell;
  cell << std::fixed << std::setprecision(1) << depth;
  EXPECT_NE(csv.out.find("," + cell.str() + ","), std::string::npos) << csv.out;
}

}  // namespace towdb::test
