// CLI tests for `towdb audit` and the default mean tension of `towdb query`.
// Test plan:
//   cli-audit-1  counts: every question is answered or refused (with its reason); a
//                complete group is always answered, a group whose only cell lacks a node
//                only on a face away from it; the JSON has the documented keys
//   cli-audit-2  the summary is stored in meta.last_audit and `towdb status` shows it
//   cli-audit-3  the same seed gives the same JSON with 1 and 2 threads
//   cli-audit-4  bad input exits 2 naming the field, the value and the allowed range,
//                and stores nothing; so does a database whose stored values the query
//                library refuses
//   cli-audit-5  a read-only database is refused before any work (not as root)
//   cli-audit-6  query without --mean-tension-lbf: the calculated mean tension of the
//                database's recorded sweep basis (= towdb mean-tension in head seas),
//                with its breakdown; the library default with the reason when the
//                database records no basis or the sweep file changed
//   cli-audit-7  audit draws the calculated mean tension when the database has a basis
//   cli-audit-8  the query's default mean tension comes from the nodes' stored T_calc (query.h EQ-QUERY-9)
//   cli-audit-9  a sweep file edited since the build (a comment) is still the audit's basis when its model
//                reproduces the calculated mean tension the database stores; a changed model is not
//   cli-audit-10 a ship file edited since the build is named (stderr and the summary)
//   cli-audit-11 the summary names the build whose content it measured; `towdb status` says
//                whether a later build has computed cases since, and an audit without the
//                record is named as such
//   cli-audit-12 --replay: an earlier audit's questions answered again from a database
//                against that audit's simulations (the same answers from the same
//                database, errors against edited simulations, a refusal from another
//                database); nothing stored; a bad replay file exits 2 naming the field
//
// The databases are synthetic (tests/query/synthetic_db.hpp) and the direct
// simulations 3 days long: the errors mean nothing here, only the bookkeeping.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../query/synthetic_db.hpp"
#include "io/ship_file.hpp"
#include "store/database.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

using nlohmann::json;

// One process computes both numbers with the same code: equal to the last bits.
constexpr double kSameCodeRelTol = 1e-12;

std::vector<SyntheticCase> group(const std::string& tow, double nominal_mean_lbf) {
  GridSpec g;
  g.tow = tow;
  g.speeds_kt = {5.0, 6.0};
  g.winds_kt = {20.0, 25.0};
  g.headings_deg = {60.0, 120.0};
  g.lengths_ft = {1000.0, 2000.0};
  g.nominal_mean_lbf = [nominal_mean_lbf](double, double) { return nominal_mean_lbf; };
  g.u_kips = [](double s, double w, double, double l, double) { return 40.0 + 5.0 * s + 0.5 * w - 0.005 * l; };
  g.beta_kips = [](double, double, double, double, double) { return 4.0; };
  return grid_cases(g);
}

// LHA 1: a complete grid (every node stores 0.6 and 1.15 of 70,000 lbf, so any
// mean tension of the group's span is inside every node). FFG 7: the same grid
// without its (6 kt, 25 kt, 120 deg, 2000 ft) node: its only cell is incomplete.
void write_two_group_db(const std::filesystem::path& path) {
  std::vector<SyntheticCase> cases = group("LHA 1", 70000.0);
  for (const SyntheticCase& c : group("FFG 7", 70000.0)) {
    const bool dropped = c.speed_kt == 6.0 && c.wind_kt == 25.0 && c.heading_deg == 120.0 && c.length_ft == 2000.0;
    if (!dropped) cases.push_back(c);
  }
  write_synthetic_db(path, cases);
}

// A sweep file whose grid computes "calculated" as the bundled database does.
const char* const kSweepText = R"(format = "towdb-sweep-1"
description = "cli_audit_test basis"

[defaults]
days = 3
sea_resistance = "strip-theory-head"
base_seed = 1
hull_margin = 0.10
propeller = "locked"
mean_tension_wind = "head"

[[grid]]
label = "test"
tugs = ["T-ATF 166"]
tows = ["LHA 1"]
speeds_kt = [5.0]
winds_kt = [20.0]
headings_deg = [60.0]
towlines = [{ line = "wire", length_ft = 1000.0 }]
mean_tensions = [{ label = "calculated", basis = "calculated", factor = 1.0 }]
)";

// Records a completed build of `sweep` (path as written) with the file's SHA-256.
void record_build(const std::filesystem::path& db_path, const std::filesystem::path& sweep) {
  auto db = store::Database::open(db_path, store::Database::Mode::kReadWrite);
  db.prepare(
        "INSERT INTO builds (code_version, command_line, sweep_file, sweep_sha256, host, threads, started_utc, "
        "finished_utc, status) VALUES ('test', 'towdb build', ?, ?, 'test', 1, '2026-01-01T00:00:00Z', "
        "'2026-01-01T00:01:00Z', 'completed')")
      .bind(1, sweep.string())
      .bind(2, io::sha256_hex(read_text(sweep)))
      .run();
}

std::string meta_value(const std::filesystem::path& db_path, const std::string& key) {
  auto db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  auto st = db.prepare("SELECT value FROM meta WHERE key = ?");
  st.bind(1, key);
  return st.step() ? st.column_text(0) : std::string();
}

class CliAudit : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("towdb-cli-audit");
    db_ = dir_ / "two.towdb";
    write_two_group_db(db_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string audit(const std::filesystem::path& db, const std::string& more) const {
    return "audit --db '" + db.string() + "' --days 3 --seed 3 " + more;
  }
  std::filesystem::path dir_, db_;
};

// Whether a question of the FFG 7 group avoids the missing node: only on a face of
// the cell away from it (a drawn value rounded onto the cell's lower edge) is every
// node it needs stored.
bool avoids_missing_node(const json& q) {
  return q.at("speed_kt").get<double>() == 5.0 || q.at("wind_kt").get<double>() == 20.0 ||
         q.at("heading_deg").get<double>() == 60.0 || q.at("length_ft").get<double>() == 1000.0;
}

TEST_F(CliAudit, EveryQuestionIsAnsweredOrRefusedSameForAnyThreadCount) {  // cli-audit-1, cli-audit-3
  const CommandResult r = run_towdb(audit(db_, "--draws 2 --threads 2 --json --no-store"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const json& s = j.at("summary");
  for (const char* key : {"draws", "seed", "days", "mean_tension", "answered", "not_answered", "simulation_failed",
                          "dynamic_999", "extreme_tension", "uncertainty_covers_error", "extrapolated_dynamic_999"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  EXPECT_EQ(s.at("mean_tension"), "uniform_in_stored_span");  // no build recorded: no basis
  EXPECT_NE(r.err.find("warning: the questions' mean tensions are drawn uniformly in the stored span"),
            std::string::npos)
      << r.err;  // said even with --json
  EXPECT_EQ(s.at("days"), 3);
  ASSERT_EQ(j.at("questions").size(), 2u);
  int answered = 0, lha = 0;
  for (const json& q : j.at("questions")) {
    const bool complete_group = q.at("tow") == "LHA 1";
    lha += complete_group ? 1 : 0;
    EXPECT_EQ(q.at("answered").get<bool>(), complete_group || avoids_missing_node(q)) << q.dump();
    EXPECT_TRUE(q.at("simulated").get<bool>()) << q.dump();
    EXPECT_GT(q.at("simulated_999_kips").get<double>(), 0.0);
    EXPECT_GE(q.at("speed_kt").get<double>(), 5.0);
    EXPECT_LE(q.at("speed_kt").get<double>(), 6.0);
    EXPECT_GE(q.at("mean_tension_lbf").get<double>(), 42000.0);  // 0.6 x 70,000
    EXPECT_LE(q.at("mean_tension_lbf").get<double>(), 80500.0);  // 1.15 x 70,000
    if (q.at("answered").get<bool>()) {
      ++answered;
      EXPECT_TRUE(q.at("rel_error_999").is_number()) << q.dump();
      EXPECT_TRUE(q.at("covered").is_boolean()) << q.dump();
    } else {
      EXPECT_NE(q.at("refusal").get<std::string>().find("incomplete"), std::string::npos) << q.dump();
      EXPECT_TRUE(q.at("rel_error_999").is_null()) << q.dump();
      EXPECT_TRUE(q.at("rel_error_extrapolated_999").is_number()) << q.dump();
    }
  }
  EXPECT_EQ(lha, 1);  // seed 3 draws LHA 1, then FFG 7 (RandomStream(3, i), i = 0, 1)
  EXPECT_EQ(s.at("answered").get<int>(), answered);
  EXPECT_EQ(s.at("not_answered").get<int>(), 2 - answered);
  EXPECT_EQ(s.at("dynamic_999").at("samples").get<int>(), answered);
  EXPECT_LE(s.at("dynamic_999").at("median_rel_error").get<double>(),
            s.at("dynamic_999").at("max_rel_error").get<double>());
  EXPECT_LE(s.at("uncertainty_covers_error").at("covered").get<int>(), answered);

  const CommandResult one = run_towdb(audit(db_, "--draws 2 --threads 1 --json --no-store"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, r.out);
  EXPECT_EQ(meta_value(db_, "last_audit"), "");  // --no-store
}

// SQLite header byte 18: 1 for a rollback journal, 2 for WAL (sqlite.org/fileformat2.html).
int journal_format_byte(const std::filesystem::path& db_path) {
  const std::string text = read_text(db_path);
  return text.size() > 18 ? static_cast<int>(text[18]) : -1;
}

TEST_F(CliAudit, SummaryIsStoredAndStatusShowsIt) {  // cli-audit-2
  EXPECT_EQ(meta_value(db_, "last_audit"), "");
  {
    // A database shipped with a rollback journal (as db/towdb.sqlite) keeps it.
    auto db = store::Database::open(db_, store::Database::Mode::kReadWrite);
    db.exec("PRAGMA journal_mode = DELETE");
  }
  ASSERT_EQ(journal_format_byte(db_), 1);
  const CommandResult r = run_towdb(audit(db_, "--draws 1 --threads 2"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(journal_format_byte(db_), 1) << "the audit switched the file to WAL";
  EXPECT_NE(r.out.find("answered without extrapolation"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("summary stored in"), std::string::npos) << r.out;
  const json stored = json::parse(meta_value(db_, "last_audit"));
  EXPECT_EQ(stored.at("draws"), 1);
  EXPECT_EQ(stored.at("seed"), 3);
  EXPECT_TRUE(stored.contains("utc"));
  EXPECT_TRUE(stored.contains("code_version"));
  EXPECT_EQ(stored.at("answered").get<int>() + stored.at("not_answered").get<int>(), 1);
  const CommandResult status = run_towdb("status --db '" + db_.string() + "' --json");
  ASSERT_EQ(status.exit_code, 0) << status.err;
  EXPECT_EQ(json::parse(status.out).at("last_audit"), stored);
  const CommandResult text = run_towdb("status --db '" + db_.string() + "'");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("last audit"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(std::to_string(stored.at("answered").get<int>()) + " of 1"), std::string::npos) << text.out;
}

TEST_F(CliAudit, BadInputExitsTwoAndStoresNothing) {  // cli-audit-4
  const std::string db = "--db '" + db_.string() + "' ";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"audit " + db + "--draws 0", {"--draws", "0", "1 to 100000"}},
      {"audit " + db + "--draws 100001", {"--draws", "100001", "1 to 100000"}},
      {"audit " + db + "--draws 2 --days 1", {"--days", "1", "3 to 1000000"}},
      {"audit " + db + "--draws 2 --threads=-1", {"--threads", "-1", "0 to 1024"}},
      {"audit " + db + "--draws 2 --seed=-3", {"--seed", "-3", "whole number"}},
      {"audit " + db + "--draws two", {"--draws", "two"}},
      {"audit " + db, {"--draws", "required"}},
      {"audit --db '" + (dir_ / "none.towdb").string() + "' --draws 2", {"--db", "none.towdb", "no such"}},
      {"audit " + db + "--draws 2 --plot '" + (dir_ / "nodir" / "a.png").string() + "'", {"--plot", "does not exist"}},
  };
  for (const auto& [args, needles] : cases) {
    const CommandResult r = run_towdb(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    for (const std::string& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(meta_value(db_, "last_audit"), "");

  // A database whose stored value the query library refuses on open (a
  // negative Gumbel scale): bad input, exit 2, naming the flag and the value.
  const auto lying = dir_ / "lying.towdb";
  std::filesystem::copy_file(db_, lying);
  {
    auto writable = store::Database::open(lying, store::Database::Mode::kReadWrite);
    writable.exec(
        "PRAGMA ignore_check_constraints = ON; UPDATE results SET gumbel_alpha_per_kip = -0.2 WHERE case_id = 2");
  }
  const CommandResult r = run_towdb(audit(lying, "--draws 2"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--db = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("gumbel_alpha_per_kip = -0.2"), std::string::npos) << r.err;
  EXPECT_EQ(meta_value(lying, "last_audit"), "");
}

TEST_F(CliAudit, ReadOnlyDatabaseIsRefusedBeforeAnyWork) {  // cli-audit-5
  if (geteuid() == 0) GTEST_SKIP() << "root writes read-only files; the check cannot be seen as root";
  ASSERT_EQ(chmod(db_.c_str(), 0444), 0);
  const CommandResult r = run_towdb(audit(db_, "--draws 2"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("read-only"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--no-store"), std::string::npos) << r.err;
  chmod(db_.c_str(), 0644);
}

TEST_F(CliAudit, ShipFilesEditedSinceTheBuildAreNamed) {  // cli-audit-10
  // The synthetic database records no ship files: nothing to compare, nothing named.
  const CommandResult plain = run_towdb(audit(db_, "--draws 1 --json --no-store"));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_TRUE(json::parse(plain.out).at("summary").at("ship_files_changed_since_build").empty());
  // The LHA 1 recorded with another file's hash: the ships/ file is not the one the build used.
  {
    auto db = store::Database::open(db_, store::Database::Mode::kReadWrite);
    db.exec("INSERT INTO vessels (name, role, file_path, content_sha256, file_text) "
            "VALUES ('LHA 1', 'tow', 'ships/lha-1.toml', 'another-hash', '')");
  }
  const CommandResult r = run_towdb(audit(db_, "--draws 1 --json --no-store"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out).at("summary").at("ship_files_changed_since_build"), json::array({"LHA 1"}));
  EXPECT_NE(r.err.find("the ship files of LHA 1 are not the ones the database was built with"), std::string::npos)
      << r.err;
}

// Marks every case of `db_path` as computed by build `build_id` (a builds row is added).
void assign_cases_to_new_build(const std::filesystem::path& db_path, std::int64_t build_id) {
  auto db = store::Database::open(db_path, store::Database::Mode::kReadWrite);
  db.prepare("INSERT INTO builds (build_id, code_version, command_line, sweep_file, sweep_sha256, host, threads, "
             "started_utc, status) VALUES (?, 'test', 'towdb build', 'x.toml', 'x', 'test', 1, "
             "'2026-01-01T00:00:00Z', 'completed')")
      .bind(1, build_id)
      .run();
  db.prepare("UPDATE cases SET build_id = ? WHERE case_id = (SELECT min(case_id) FROM cases)").bind(1, build_id).run();
}

TEST_F(CliAudit, TheSummaryNamesTheContentItMeasured) {  // cli-audit-11
  const std::string status_text = "status --db '" + db_.string() + "'";
  // An audit stored before the record existed.
  {
    auto db = store::Database::open(db_, store::Database::Mode::kReadWrite);
    db.exec("INSERT INTO meta (key, value) VALUES ('last_audit', '{\"draws\": 1, \"days\": 3}')");
  }
  const CommandResult old_audit = run_towdb(status_text);
  ASSERT_EQ(old_audit.exit_code, 0) << old_audit.err;
  EXPECT_NE(old_audit.out.find("audited content: not recorded"), std::string::npos) << old_audit.out;

  assign_cases_to_new_build(db_, 7);
  ASSERT_EQ(run_towdb(audit(db_, "--draws 1")).exit_code, 0);
  const json stored = json::parse(meta_value(db_, "last_audit"));
  EXPECT_EQ(stored.at("content_build_id"), 7);
  EXPECT_EQ(stored.at("cases_done").get<std::int64_t>(), json::parse(run_towdb(status_text + " --json").out)
                                                              .at("cases_by_status")
                                                              .at("done")
                                                              .get<std::int64_t>());
  const CommandResult current = run_towdb(status_text);
  EXPECT_NE(current.out.find("audited content: build 7"), std::string::npos) << current.out;
  EXPECT_EQ(current.out.find("warning: the audit"), std::string::npos) << current.out;

  // A later build computes a case: the stored audit no longer describes the database.
  assign_cases_to_new_build(db_, 8);
  const CommandResult stale = run_towdb(status_text);
  ASSERT_EQ(stale.exit_code, 0) << stale.err;
  EXPECT_NE(stale.out.find("warning: the audit measured the database as of build 7"), std::string::npos)
      << stale.out;
  EXPECT_NE(stale.out.find("build 8 has computed cases or profiles since"), std::string::npos) << stale.out;
  EXPECT_EQ(json::parse(run_towdb(status_text + " --json").out).at("content_build_id"), 8);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

TEST_F(CliAudit, ReplayAnswersAnEarlierAuditsQuestionsAgain) {  // cli-audit-12
  const CommandResult first = run_towdb(audit(db_, "--draws 2 --json --no-store"));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  json earlier = json::parse(first.out);
  const auto file = dir_ / "earlier.json";
  write_text(file, earlier.dump(2));
  const std::string replay = "audit --db '" + db_.string() + "' --replay '" + file.string() + "'";

  // Same database, same code: the same answers and errors.
  const CommandResult same = run_towdb(replay + " --json");
  ASSERT_EQ(same.exit_code, 0) << same.err;
  const json again = json::parse(same.out);
  EXPECT_EQ(again.at("replay_of"), file.string());
  EXPECT_EQ(again.at("summary").at("mean_tension"), "replayed");
  ASSERT_EQ(again.at("questions").size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const json& a = earlier.at("questions")[i];
    const json& b = again.at("questions")[i];
    for (const char* key : {"answered", "answer_999_kips", "uncertainty_kips", "simulated_999_kips",
                            "extrapolated_999_kips", "rel_error_999", "covered"})
      EXPECT_EQ(a.at(key), b.at(key)) << key << " of question " << i;
    if (a.at("rel_error_extreme").is_number())  // the simulated extreme rebuilt as mean + 1,000 x kips
      EXPECT_NEAR(a.at("rel_error_extreme").get<double>(), b.at("rel_error_extreme").get<double>(), kSameCodeRelTol);
  }
  EXPECT_EQ(earlier.at("summary").at("dynamic_999"), again.at("summary").at("dynamic_999"));
  EXPECT_EQ(meta_value(db_, "last_audit"), "");  // a replay stores nothing

  // Errors are recomputed against the file's simulations: double one of them.
  const json q0 = earlier.at("questions")[0];
  ASSERT_TRUE(q0.at("answered").get<bool>()) << q0.dump();  // seed 3: LHA 1, a complete group
  const double doubled_kips = 2.0 * q0.at("simulated_999_kips").get<double>();
  earlier["questions"][0]["simulated_999_kips"] = doubled_kips;
  write_text(file, earlier.dump(2));
  const json edited = json::parse(run_towdb(replay + " --json").out);
  const double answer_kips = edited.at("questions")[0].at("answer_999_kips").get<double>();
  EXPECT_NEAR(edited.at("questions")[0].at("rel_error_999").get<double>(),
              std::abs(answer_kips - doubled_kips) / doubled_kips, kSameCodeRelTol);

  // Another database: LHA 1 only, so the FFG 7 question is refused with the library's reason.
  const auto lha_only = dir_ / "lha.towdb";
  write_synthetic_db(lha_only, group("LHA 1", 70000.0));
  const CommandResult other = run_towdb("audit --db '" + lha_only.string() + "' --replay '" + file.string() + "'");
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.out.find("question 1: refused"), std::string::npos) << other.out;
  EXPECT_NE(other.out.find("FFG"), std::string::npos) << other.out;
  EXPECT_NE(other.out.find("nothing simulated, nothing stored"), std::string::npos) << other.out;

  // A bad replay file or flags that do not go with it: exit 2, the field named.
  json missing = earlier;
  missing["questions"][1].erase("speed_kt");
  const auto missing_file = dir_ / "missing.json";
  write_text(missing_file, missing.dump());
  json rope = earlier;
  rope["questions"][0]["line"] = "rope";
  const auto rope_file = dir_ / "rope.json";
  write_text(rope_file, rope.dump());
  const auto text_file = dir_ / "text.json";
  write_text(text_file, "not json");
  const std::string db = "audit --db '" + db_.string() + "' ";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {db + "--replay '" + missing_file.string() + "'", {"questions[1].speed_kt", "missing"}},
      {db + "--replay '" + rope_file.string() + "'", {"questions[0].line", "rope", "wire or fiber"}},
      {db + "--replay '" + text_file.string() + "'", {"--replay", "not a JSON object"}},
      {db + "--replay '" + (dir_ / "none.json").string() + "'", {"--replay", "none.json"}},
      {db + "--replay '" + file.string() + "' --draws 2", {"--replay", "--draws"}},
      {db + "--replay '" + file.string() + "' --seed 2", {"--replay", "--seed"}},
  };
  for (const auto& [args, needles] : cases) {
    const CommandResult r = run_towdb(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    for (const std::string& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << args << "\n" << r.err;
  }
}

class CliQueryDefaultMean : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("towdb-cli-default-mean");
    db_ = dir_ / "basis.towdb";
    // Nodes store 0.6 to 1.15 of 150,000 lbf: 90,000 to 172,500 lbf, around the
    // calculated value of LHA 1 at 5 kt in 20 kt of wind.
    write_synthetic_db(db_, group("LHA 1", 150000.0));
    sweep_ = dir_ / "basis.toml";
    std::ofstream(sweep_) << kSweepText;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string query(const std::string& more) const {
    return "query --db '" + db_.string() +
           "' --tug T-ATF --tow LHA1 --line wire --speed-kt 5 --wind-kt 20 --heading-deg 90 --length-ft 1500 " + more;
  }
  double mean_tension_command_lbf() const {
    // The sweep's basis: wind from ahead and strip-theory sea resistance in head seas.
    const CommandResult m = run_towdb(
        "mean-tension --tow LHA1 --speed-kt 5 --wind-kt 20 --heading-deg 180 --sea-resistance strip-theory-head "
        "--json");
    EXPECT_EQ(m.exit_code, 0) << m.err;
    return json::parse(m.out).at("total_lbf").get<double>();
  }
  std::filesystem::path dir_, db_, sweep_;
};

TEST_F(CliQueryDefaultMean, CalculatedOnTheDatabasesBasis) {  // cli-audit-6
  const CommandResult none = run_towdb(query("--json"));
  ASSERT_EQ(none.exit_code, 3) << none.err;  // answered at 172,500 lbf: the mean check (BS/3) fails
  const json n = json::parse(none.out);
  EXPECT_EQ(n.at("mean_tension_default").at("method"), "node_highest_stored");
  EXPECT_NE(n.at("mean_tension_default").at("reason").get<std::string>().find("no completed build"), std::string::npos);

  record_build(db_, sweep_);
  const CommandResult r = run_towdb(query("--json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const json& d = j.at("mean_tension_default");
  ASSERT_EQ(d.at("method"), "calculated") << d.dump();
  EXPECT_EQ(d.at("basis").at("sea_resistance"), "strip-theory-head");
  EXPECT_EQ(d.at("basis").at("mean_tension_wind"), "head");
  const double expected = mean_tension_command_lbf();
  EXPECT_REL_CLOSE(j.at("mean_tension_lbf").get<double>(), expected, kSameCodeRelTol);
  const json& b = d.at("breakdown");
  EXPECT_REL_CLOSE(b.at("total_lbf").get<double>(), expected, kSameCodeRelTol);
  EXPECT_GT(b.at("sea_lbf").get<double>(), 0.0);
  EXPECT_REL_CLOSE(b.at("hull_lbf").get<double>() + b.at("propeller_lbf").get<double>() +
                       b.at("wind_lbf").get<double>() + b.at("sea_lbf").get<double>(),
                   b.at("tow_resistance_lbf").get<double>(), kSameCodeRelTol);
  EXPECT_TRUE(d.contains("note"));  // the synthetic database stores no ship files

  const CommandResult text = run_towdb(query(""));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("calculated mean tension of this speed, wind and heading"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("propeller"), std::string::npos) << text.out;

  // A given mean tension is used as given, with no default reported.
  const CommandResult given = run_towdb(query("--mean-tension-lbf 100000 --json"));
  ASSERT_EQ(given.exit_code, 0) << given.err;
  EXPECT_FALSE(json::parse(given.out).contains("mean_tension_default"));

  // The sweep file changed since the build: no basis, and the reason says so.
  std::ofstream(sweep_, std::ios::app) << "# edited\n";
  const CommandResult changed = run_towdb(query("--json"));
  ASSERT_EQ(changed.exit_code, 3) << changed.err;  // the nodes' highest, 172,500 lbf: mean check fails
  const json c = json::parse(changed.out).at("mean_tension_default");
  EXPECT_EQ(c.at("method"), "node_highest_stored");
  EXPECT_NE(c.at("reason").get<std::string>().find("changed"), std::string::npos) << c.dump();
}

TEST_F(CliQueryDefaultMean, CalculatedAtTheNodesWhenTheDatabaseStoresIt) {  // cli-audit-8
  // query.h EQ-QUERY-9: nodes that store T_calc give the default without strip theory: T_calc at the
  // question (geometric over the cell; here 150,000 lbf at every node), factor 1, and the basis of a
  // recorded build is not needed.
  std::vector<SyntheticCase> cases = group("LHA 1", 150000.0);
  for (SyntheticCase& c : cases) c.calculated_mean_tension_lbf = 150000.0;
  const auto path = dir_ / "at-nodes.towdb";
  write_synthetic_db(path, cases);
  const std::string base = "query --db '" + path.string() +
                           "' --tug T-ATF --tow LHA1 --line wire --wind-kt 22 --heading-deg 90 --length-ft 1500";
  const std::string q = base + " --speed-kt 5.5";
  const CommandResult r = run_towdb(q + " --json");
  ASSERT_EQ(r.exit_code, 3) << r.err;  // 150,000 lbf > BS/3: answered, the mean check fails
  const json j = json::parse(r.out);
  EXPECT_EQ(j.at("mean_tension_default").at("method"), "calculated_at_nodes") << j.dump();
  EXPECT_REL_CLOSE(j.at("mean_tension_lbf").get<double>(), 150000.0, kSameCodeRelTol);
  EXPECT_REL_CLOSE(j.at("calculated_mean_tension_lbf").get<double>(), 150000.0, kSameCodeRelTol);
  EXPECT_EQ(j.at("mean_tension_factor").get<double>(), 1.0);
  // 150,000 lbf is above the tugs' 125,000 lbf (thesis ch. 5): answered, with the warning named.
  ASSERT_FALSE(j.at("warnings").empty());
  EXPECT_EQ(j.at("warnings").back().at("kind"), "above_tug_capacity");
  const CommandResult text = run_towdb(q);
  ASSERT_EQ(text.exit_code, 3) << text.err;
  EXPECT_NE(text.out.find("interpolated from the values stored at the grid nodes"), std::string::npos) << text.out;
  // A question outside the stored span is refused as it is with a mean tension.
  const CommandResult out = run_towdb(base + " --speed-kt 9");
  EXPECT_EQ(out.exit_code, 2);
  EXPECT_NE(out.err.find("speed_kt = 9"), std::string::npos) << out.err;
}

TEST_F(CliQueryDefaultMean, AuditDrawsTheCalculatedMeanTension) {  // cli-audit-7
  record_build(db_, sweep_);
  const CommandResult r = run_towdb("audit --db '" + db_.string() + "' --draws 1 --days 3 --json --no-store");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j.at("summary").at("mean_tension"), "calculated");
  for (const json& q : j.at("questions")) {
    const CommandResult m =
        run_towdb("mean-tension --tow LHA1 --speed-kt " + q.at("speed_kt").dump() + " --wind-kt " +
                  q.at("wind_kt").dump() + " --heading-deg 180 --sea-resistance strip-theory-head --json");
    ASSERT_EQ(m.exit_code, 0) << m.err;
    EXPECT_REL_CLOSE(q.at("mean_tension_lbf").get<double>(), json::parse(m.out).at("total_lbf").get<double>(),
                     kSameCodeRelTol);
  }
}

TEST_F(CliQueryDefaultMean, AnEditedSweepFileIsStillTheBasisIfItReproducesTheStore) {  // cli-audit-9
  // The first case (LHA 1, 5 kt, 20 kt) stores the calculated mean tension of the sweep's basis, as a build
  // records it (`towdb mean-tension` in head seas with strip-theory sea resistance).
  std::vector<SyntheticCase> cases = group("LHA 1", 150000.0);
  const double calculated_lbf = mean_tension_command_lbf();
  for (SyntheticCase& c : cases) c.calculated_mean_tension_lbf = calculated_lbf;
  const auto path = dir_ / "stores-calculated.towdb";
  write_synthetic_db(path, cases);
  record_build(path, sweep_);
  const std::string audit = "audit --db '" + path.string() + "' --draws 1 --days 3 --json --no-store";

  std::ofstream(sweep_, std::ios::app) << "# a comment added after the build\n";
  const CommandResult edited = run_towdb(audit);
  ASSERT_EQ(edited.exit_code, 0) << edited.err;
  const json e = json::parse(edited.out);
  EXPECT_EQ(e.at("summary").at("mean_tension"), "calculated") << edited.err;
  EXPECT_NE(e.at("mean_tension_basis").at("source").get<std::string>().find("reproduces"), std::string::npos)
      << e.at("mean_tension_basis").dump();

  // Another hull margin is another model: its calculated tension is not the stored one.
  std::string text = kSweepText;
  text.replace(text.find("hull_margin = 0.10"), 18, "hull_margin = 0.25");
  std::ofstream(sweep_, std::ios::trunc) << text;
  const CommandResult other = run_towdb(audit);
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_EQ(json::parse(other.out).at("summary").at("mean_tension"), "uniform_in_stored_span");
  EXPECT_NE(other.err.find("its model gives"), std::string::npos) << other.err;
}

}  // namespace
}  // namespace towdb::test
