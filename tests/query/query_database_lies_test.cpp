// A database that lies (issue 20 item 4): consistent SQL, wrong numbers. Each
// is refused on open with TOWDB_QUERY_DATABASE naming the file, the case,
// table.column and the value, or answered with a warning; never silently.
// The lies are written with SQL into a good synthetic database, CHECK
// constraints off (a careless or hostile writer; docs/hardening.md).
// Test plan:
//   query-lies-1  bad stored values: alpha <= 0 (negative Gumbel scale) or subnormal (infinite scale), NULL (NaN),
//                 inf, text, out-of-range
//                 level, fraction, heading, speed, days, calculated mean tension, sag, a heading profile's
//                 sigma (0, NaN), step or length (EQ-QUERY-11), a speed profile's sigma, first speed or length
//                 (EQ-QUERY-12) -> refused, named
//   query-lies-2  contradictions between columns: dynamic_999 != u + beta y_999 (EQ-QUERY-3), ci_low > ci_high,
//                 a sea with neither wind nor Hs, an Hs without Tp -> refused, named
//   query-lies-3  a schema version from the future -> refused naming both versions
//   query-lies-4  a case missing inside a grid cell (its results row gone) -> the query naming the node is
//                 refused (TOWDB_QUERY_RANGE), or answered with the incomplete_grid warning when extrapolating
//   query-lies-5  a value just inside every bound still opens (the checks refuse lies, not odd truths)
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "synthetic_db.hpp"
#include "test_support.hpp"
#include "towdb/query.hpp"

namespace towdb::test {
namespace {

using query::Database;
using query::QueryError;
using query::QueryRequest;

class DatabaseLies : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("towdb-query-lies");
    // Speeds 5 and 7 kt x lengths 1000 and 2000 ft: case ids 1-4.
    for (double s : {5.0, 7.0}) {
      for (double l : {1000.0, 2000.0}) {
        SyntheticCase c;
        c.speed_kt = s;
        c.length_ft = l;
        c.u_kips = 30.0 + 2.0 * s - 0.01 * l;
        c.sag_ft = 12.0;
        cases_.push_back(c);
      }
    }
    good_ = dir_ / "good.towdb";
    write_synthetic_db(good_, cases_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A copy of the good database with `sql` applied, CHECK constraints off.
  std::string lie(const std::string& sql) {
    const auto path = dir_ / ("lie" + std::to_string(++count_) + ".towdb");
    std::filesystem::copy_file(good_, path);
    sqlite3* raw = nullptr;
    EXPECT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
    char* err = nullptr;
    const std::string all = "PRAGMA ignore_check_constraints = ON; " + sql;
    EXPECT_EQ(sqlite3_exec(raw, all.c_str(), nullptr, nullptr, &err), SQLITE_OK) << (err ? err : "") << " in " << sql;
    sqlite3_free(err);
    sqlite3_close(raw);
    return path.string();
  }

  // Expects opening `path` to be refused with TOWDB_QUERY_DATABASE and a
  // message that starts with the path and contains every one of `needles`.
  void expect_refused(const std::string& path, const std::vector<std::string>& needles) {
    try {
      Database db(path);
      ADD_FAILURE() << "opened a lying database; expected a refusal naming " << needles.front();
    } catch (const QueryError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(e.code(), TOWDB_QUERY_DATABASE) << msg;
      EXPECT_EQ(msg.rfind(path, 0), 0u) << "the message does not start with the file: " << msg;
      for (const std::string& n : needles) EXPECT_NE(msg.find(n), std::string::npos) << "no '" << n << "' in: " << msg;
    }
  }

  static QueryRequest request(double speed_kt, double length_ft) {
    QueryRequest r;
    r.tug = "T-ATF 166";
    r.tow = "LHA 1";
    r.line = "wire";
    r.values.speed_kt = speed_kt;
    r.values.wind_kt = 20.0;
    r.values.heading_deg = 0.0;
    r.values.length_ft = length_ft;
    r.values.mean_tension_lbf = 60000.0;
    return r;
  }

  std::filesystem::path dir_, good_;
  std::vector<SyntheticCase> cases_;
  int count_ = 0;
};

TEST_F(DatabaseLies, BadStoredValuesAreRefusedAndNamed) {  // query-lies-1
  struct Lie {
    std::string sql;
    std::vector<std::string> needles;
  };
  const std::vector<Lie> lies = {
      {"UPDATE results SET gumbel_alpha_per_kip = -0.2 WHERE case_id = 2",
       {"case 2", "results.gumbel_alpha_per_kip = -0.2", "Gumbel scale"}},
      {"UPDATE results SET gumbel_alpha_per_kip = 0 WHERE case_id = 3", {"case 3", "results.gumbel_alpha_per_kip = 0"}},
      // Finite and > 0, but the scale 1/alpha overflows (tests/fuzz/regressions/database).
      {"UPDATE results SET gumbel_alpha_per_kip = 4.9e-324 WHERE case_id = 3",
       {"case 3", "results.gumbel_alpha_per_kip = 4.94065645841247e-324 gives the Gumbel scale 1/alpha = inf"}},
      {"UPDATE results SET gumbel_u_kips = 9e999 WHERE case_id = 2", {"case 2", "results.gumbel_u_kips = inf"}},
      {"UPDATE results SET dynamic_999_kips = -9e999 WHERE case_id = 4", {"case 4", "results.dynamic_999_kips = -inf"}},
      // A writer that made its own table without NOT NULL, and stored a NaN (SQLite keeps it as NULL).
      {"CREATE TABLE r2 AS SELECT * FROM results; DROP TABLE results; ALTER TABLE r2 RENAME TO results;"
       "UPDATE results SET gumbel_u_kips = NULL WHERE case_id = 1",
       {"case 1", "results.gumbel_u_kips is NULL", "NaN"}},
      {"UPDATE results SET gumbel_u_kips = 'fifty' WHERE case_id = 2", {"case 2", "gumbel_u_kips = 'fifty' (text)"}},
      {"UPDATE results SET ci_level = 1.5 WHERE case_id = 2", {"case 2", "results.ci_level = 1.5", "(0, 1)"}},
      {"UPDATE results SET slack_fraction = -0.1 WHERE case_id = 2", {"case 2", "results.slack_fraction = -0.1"}},
      {"UPDATE results SET breaking_strength_lbf = 0 WHERE case_id = 2", {"case 2", "breaking_strength_lbf = 0"}},
      {"UPDATE results SET above_breaking_strength = 7 WHERE case_id = 2", {"case 2", "above_breaking_strength = 7"}},
      {"UPDATE cases SET heading_deg = 400 WHERE case_id = 2", {"case 2", "cases.heading_deg = 400", "[0, 360]"}},
      {"UPDATE cases SET speed_kt = -5 WHERE case_id = 2", {"case 2", "cases.speed_kt = -5"}},
      {"UPDATE cases SET length_ft = 9e999 WHERE case_id = 2", {"case 2", "cases.length_ft = inf"}},
      {"UPDATE cases SET days = 0 WHERE case_id = 2", {"case 2", "cases.days = 0"}},
      {"UPDATE cases SET days = 2.5 WHERE case_id = 2", {"case 2", "cases.days = 2.5", "whole number"}},
      {"UPDATE cases SET calculated_mean_tension_lbf = -1 WHERE case_id = 2",
       {"case 2", "cases.calculated_mean_tension_lbf = -1"}},
      {"UPDATE towline_fits SET sag_ft = -3 WHERE fit_id = 1", {"case 1", "towline_fits.sag_ft = -3"}},
      {"UPDATE towline_fits SET lowest_elevation_ft = 'deep' WHERE fit_id = 1",
       {"case 1", "towline_fits.lowest_elevation_ft = 'deep' (text)"}},
      {"UPDATE towline_fits SET lowest_elevation_ft = -9e999 WHERE fit_id = 1",
       {"case 1", "towline_fits.lowest_elevation_ft = -inf", "finite elevation"}},
      // Heading profiles (schema 10): 1.0f is X'0000803F', 0.0f X'00000000', NaN X'0000C07F'.
      {"INSERT INTO heading_profiles VALUES (1, X'01', 60000, 0, 2.5, 2, X'0000803F00000000', NULL)",
       {"heading_profiles.sigma_kips_f32 of profile_id 1 holds 0 kips", "finite and > 0"}},
      {"INSERT INTO heading_profiles VALUES (1, X'01', 60000, 0, 2.5, 2, X'0000C07F0000803F', NULL)",
       {"heading_profiles.sigma_kips_f32 of profile_id 1 holds nan kips"}},
      {"INSERT INTO heading_profiles VALUES (7, X'01', 60000, 0, 0, 2, X'0000803F0000803F', NULL)",
       {"heading_profiles row 7 has first heading 0 deg, step 0 deg", "allowed: first in [0, 180], a finite step > 0"}},
      {"INSERT INTO heading_profiles VALUES (7, X'01', 60000, 0, 2.5, 3, X'0000803F0000803F', NULL)",
       {"heading_profiles row 7: sigma_kips_f32 holds 8 bytes; expected 4 x 3 headings"}},
      {"INSERT INTO speed_profiles VALUES (1, X'01', 5, 0.25, 2, X'003C0000', NULL)",
       {"speed_profiles.sigma_kips_f16 of speed_profile_id 1 holds 0 kips", "finite and > 0"}},
      {"INSERT INTO speed_profiles VALUES (7, X'01', 0, 0.25, 2, X'003C003C', NULL)",
       {"speed_profiles row 7 has first speed 0 kt, step 0.25 kt", "allowed: first in (0, 100], a finite step > 0"}},
      {"INSERT INTO speed_profiles VALUES (7, X'01', 5, 0.25, 3, X'003C003C', NULL)",
       {"speed_profiles row 7: sigma_kips_f16 holds 4 bytes; expected 2 x 3 speeds"}},
  };
  for (const Lie& l : lies) {
    SCOPED_TRACE(l.sql);
    expect_refused(lie(l.sql), l.needles);
  }
}

TEST_F(DatabaseLies, ContradictionsBetweenColumnsAreRefusedAndNamed) {  // query-lies-2
  // EVIDENCE-OF: EQ-QUERY-3. The stored planning value must be the stored fit's quantile.
  expect_refused(lie("UPDATE results SET dynamic_999_kips = dynamic_999_kips * 1.01 WHERE case_id = 3"),
                 {"case 3", "results.dynamic_999_kips = ", "disagrees with gumbel_u_kips"});
  expect_refused(lie("UPDATE results SET gumbel_u_kips = gumbel_u_kips + 1 WHERE case_id = 4"),
                 {"case 4", "results.dynamic_999_kips", "disagrees"});
  expect_refused(lie("UPDATE results SET ci_low_kips = ci_high_kips + 1 WHERE case_id = 2"),
                 {"case 2", "results.ci_low_kips = ", "exceeds ci_high_kips"});
  expect_refused(lie("UPDATE cases SET wind_kt = NULL WHERE case_id = 2"),
                 {"case 2", "cases.wind_kt and cases.hs_ft are both NULL"});
  expect_refused(lie("UPDATE cases SET wind_kt = NULL, hs_ft = 12, spectrum = 'jonswap' WHERE case_id = 2"),
                 {"case 2", "cases.tp_s is NULL beside hs_ft = 12"});
}

TEST_F(DatabaseLies, SchemaVersionFromTheFutureIsRefused) {  // query-lies-3
  const int future = store::latest_schema_version() + 1;
  const std::string path = lie("PRAGMA user_version = " + std::to_string(future));
  expect_refused(path, {"database schema version " + std::to_string(future) + " is newer than this towdb understands (" +
                        std::to_string(store::latest_schema_version()) + ")"});
}

TEST_F(DatabaseLies, CaseMissingInsideAGridCellIsNamedOrWarned) {  // query-lies-4
  // Case 4 (7 kt, 2000 ft) says 'done' but its results row is gone: the JOIN
  // leaves a hole in the 2 x 2 grid, inside the cell of every mid-cell query.
  const std::string path = lie("DELETE FROM results WHERE case_id = 4");
  Database db(path);
  EXPECT_EQ(db.case_count(), 3);
  try {
    db.query(request(6.0, 1500.0));
    ADD_FAILURE() << "answered from a cell with a missing corner";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE);
    EXPECT_NE(std::string(e.what()).find("no stored case at T-ATF 166 / LHA 1 / wire at speed 7 kt"),
              std::string::npos)
        << e.what();
  }
  QueryRequest rq = request(6.0, 1500.0);
  rq.values.extrapolate = 1;
  const query::QueryResult r = db.query(rq);
  bool warned = false;
  for (const auto& w : r.warnings) warned = warned || w.kind == TOWDB_QUERY_WARN_INCOMPLETE_GRID;
  EXPECT_TRUE(warned) << "answered over a hole without the incomplete_grid warning";
  // A query at a stored node away from the hole is still answered exactly.
  EXPECT_NO_THROW(db.query(request(5.0, 1000.0)));
}

TEST_F(DatabaseLies, ValuesJustInsideTheBoundsStillOpen) {  // query-lies-5
  // Heading 360 (= 0 by symmetry), slack fraction 1, a zero sag, a dynamic_999
  // off by 1e-9 relative (rounding of another writer): odd, not lies.
  const std::string path = lie(
      "UPDATE cases SET heading_deg = 360 WHERE case_id = 1; UPDATE results SET slack_fraction = 1 WHERE case_id = 1;"
      "UPDATE towline_fits SET sag_ft = 0 WHERE fit_id = 2;"
      "UPDATE results SET dynamic_999_kips = dynamic_999_kips * (1 + 1e-9) WHERE case_id = 3;");
  Database db(path);
  EXPECT_EQ(db.case_count(), 4);
  EXPECT_NO_THROW(db.query(request(6.0, 1500.0)));
}

}  // namespace
}  // namespace towdb::test
