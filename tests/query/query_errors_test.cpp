// Bad queries and bad databases: each gives a named error with a code, never
// a crash (towdb/query.h "ERRORS AND OWNERSHIP").
// Test plan:
//   query-err-1  unknown tug / tow / line, ambiguous prefix -> TOWDB_QUERY_INPUT naming the value and the known ones
//   query-err-2  NaN, negative length, heading 400, probability 0 and 1, tow_days < 1, two seas -> INPUT
//   query-err-3  missing, corrupt, truncated, non-towdb, empty databases -> TOWDB_QUERY_DATABASE
//   query-err-4  forced log space on data with u <= 0 -> INPUT; name matching ignores case, spaces, hyphens
//   query-err-5  a question outside the stored data names the builds' coverage notes of its tug and tow (schema 5)
//                and their skipped condition nearest the question; other tugs' notes are not named
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "common/error.hpp"
#include "synthetic_db.hpp"
#include "test_support.hpp"
#include "towdb/query.hpp"

namespace towdb::test {
namespace {

using query::Database;
using query::QueryError;
using query::QueryRequest;

class QueryErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("towdb-query-err");
    SyntheticCase a, b;
    b.speed_kt = 7.0;
    SyntheticCase other_tug = a;
    other_tug.tug = "ARS 50";
    SyntheticCase other_tug2 = a;
    other_tug2.tug = "ARS 38";
    good_ = (dir_ / "good.towdb").string();
    write_synthetic_db(good_, {a, b, other_tug, other_tug2});
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static QueryRequest valid() {
    QueryRequest r;
    r.tug = "T-ATF 166";
    r.tow = "LHA 1";
    r.line = "wire";
    r.values.speed_kt = 6.0;
    r.values.wind_kt = 20.0;
    r.values.heading_deg = 0.0;
    r.values.length_ft = 2000.0;
    r.values.mean_tension_lbf = 60000.0;
    return r;
  }

  // Expects `rq` to fail with `code` and a message containing `text`.
  void expect_error(const QueryRequest& rq, int code, const std::string& text) {
    Database db(good_);
    try {
      db.query(rq);
      ADD_FAILURE() << "no error; expected: " << text;
    } catch (const QueryError& e) {
      EXPECT_EQ(e.code(), code) << e.what();
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  }

  void expect_open_error(const std::string& path, const std::string& text) {
    try {
      Database db(path);
      ADD_FAILURE() << "opened " << path;
    } catch (const QueryError& e) {
      EXPECT_EQ(e.code(), TOWDB_QUERY_DATABASE) << e.what();
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  }

  std::filesystem::path dir_;
  std::string good_;
};

TEST_F(QueryErrors, UnknownNamesAreNamedWithTheKnownOnes) {  // query-err-1
  QueryRequest r = valid();
  r.tug = "Titanic";
  expect_error(r, TOWDB_QUERY_INPUT, "tug 'Titanic' is not in the database; known: ARS 38, ARS 50, T-ATF 166");
  r = valid();
  r.tow = "QE2";
  expect_error(r, TOWDB_QUERY_INPUT, "tow (towed by T-ATF 166) 'QE2' is not in the database; known: LHA 1");
  r = valid();
  r.line = "fiber";
  expect_error(r, TOWDB_QUERY_INPUT, "no fiber towline cases for T-ATF 166 towing LHA 1; stored: wire");
  r = valid();
  r.line = "rope";
  expect_error(r, TOWDB_QUERY_INPUT, "line = 'rope': must be 'wire' or 'fiber'");
  r = valid();
  r.tug = "ARS";
  expect_error(r, TOWDB_QUERY_INPUT, "tug 'ARS' is ambiguous; it matches: ARS 38, ARS 50");
}

TEST_F(QueryErrors, BadNumbersAreNamed) {  // query-err-2
  const double nan = std::numeric_limits<double>::quiet_NaN();
  QueryRequest r = valid();
  r.values.speed_kt = nan;
  expect_error(r, TOWDB_QUERY_INPUT, "speed_kt = nan: must be a finite number > 0");
  r = valid();
  r.values.length_ft = -100.0;
  expect_error(r, TOWDB_QUERY_INPUT, "length_ft = -100: must be a finite number > 0");
  r = valid();
  r.values.heading_deg = 400.0;
  expect_error(r, TOWDB_QUERY_INPUT, "heading_deg = 400: must be between 0 and 360");
  for (double p : {0.0, 1.0, nan, -0.5}) {
    r = valid();
    r.values.probability = p;
    expect_error(r, TOWDB_QUERY_INPUT, "probability = " + format_value(p) + ": must be strictly between 0 and 1");
  }
  r = valid();
  r.values.tow_days = 0.5;
  expect_error(r, TOWDB_QUERY_INPUT, "tow_days = 0.5: must be a finite number of days >= 1");
  r = valid();
  r.values.hs_ft = 10.0;
  expect_error(r, TOWDB_QUERY_INPUT, "wind_kt and hs_ft: give one sea, not both");
  r = valid();
  r.values.wind_kt = nan;
  expect_error(r, TOWDB_QUERY_INPUT, "wind_kt: a sea is required");
  r = valid();
  r.values.mean_tension_lbf = -1.0;
  expect_error(r, TOWDB_QUERY_INPUT, "mean_tension_lbf = -1: must be a finite number > 0");
  r = valid();
  r.values.wind_kt = 25.0;  // one stored wind (20 kt): outside the data
  expect_error(r, TOWDB_QUERY_RANGE, "wind_kt = 25 is outside the stored range [20, 20] kt");
}

TEST_F(QueryErrors, BadDatabasesAreNamed) {  // query-err-3
  expect_open_error((dir_ / "missing.towdb").string(), "database does not exist");
  {
    std::ofstream(dir_ / "garbage.towdb", std::ios::binary) << std::string(8192, 'x');
  }
  expect_open_error((dir_ / "garbage.towdb").string(), "garbage.towdb");
  {
    // A valid SQLite file that is not a towdb database.
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open((dir_ / "other.sqlite").c_str(), &raw), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(raw, "CREATE TABLE t (x); INSERT INTO t VALUES (1);", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(raw);
  }
  expect_open_error((dir_ / "other.sqlite").string(), "not a towdb database");
  {
    // A towdb database cut in half: the header survives, the pages do not.
    const auto bytes = std::filesystem::file_size(good_);
    std::filesystem::copy_file(good_, dir_ / "cut.towdb");
    std::filesystem::resize_file(dir_ / "cut.towdb", bytes / 2);
  }
  expect_open_error((dir_ / "cut.towdb").string(), "cut.towdb");
  {
    SyntheticCase pending;
    pending.status = "pending";
    write_synthetic_db(dir_ / "empty.towdb", {pending});
  }
  expect_open_error((dir_ / "empty.towdb").string(), "no finished cases");
}

TEST_F(QueryErrors, LogSpaceNeedsPositiveLocationsAndNamesAreNormalised) {  // query-err-4
  SyntheticCase a;
  a.u_kips = -2.0;
  write_synthetic_db(dir_ / "neg.towdb", {a});
  try {
    Database db((dir_ / "neg.towdb").string(), TOWDB_QUERY_SPACE_LOG);
    ADD_FAILURE() << "log space opened with u <= 0";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_INPUT);
    EXPECT_NE(std::string(e.what()).find("space = log"), std::string::npos) << e.what();
  }
  Database db((dir_ / "neg.towdb").string());
  EXPECT_EQ(db.space(), TOWDB_QUERY_SPACE_LINEAR);
  Database good(good_);
  for (const char* tug : {"tatf166", "T-ATF", "t atf 166", "T-ATF-166"}) {
    QueryRequest r = valid();
    r.tug = tug;
    EXPECT_NO_THROW(good.query(r)) << tug;
  }
}


TEST_F(QueryErrors, RefusalsNameTheBuildsCoverageNotes) {  // query-err-5
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(good_.c_str(), &raw), SQLITE_OK);
  const char* sql =
      "INSERT INTO builds (build_id, code_version, command_line, sweep_file, sweep_sha256, host, threads, "
      "started_utc, status) VALUES (1, 'test', 'test', 's.toml', 'x', 'h', 1, '2026-01-01T00:00:00Z', "
      "'completed');"
      "INSERT INTO coverage_notes (build_id, kind, sweep_label, tug_name, tow_name, note) VALUES "
      "(1, 'grid_note', 'g', 'T-ATF 166', 'LHA 1', 'LHA 1 at 5 and 7 kt only: the tugs cannot hold more'),"
      "(1, 'grid_note', 'g', 'ARS 50', 'LHA 1', 'a note of another tug');"
      "INSERT INTO coverage_notes (build_id, kind, sweep_label, tug_name, tow_name, nominal_speed_kt, sea, "
      "heading_deg, note) VALUES "
      "(1, 'skipped', 'g', 'T-ATF 166', 'LHA 1', 9, 'wind_kt=20', 0, 'T_calc above the limit down to 3 kt'),"
      "(1, 'skipped', 'g', 'T-ATF 166', 'LHA 1', 11, 'wind_kt=20', 0, 'a farther condition');";
  ASSERT_EQ(sqlite3_exec(raw, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(raw);
  sqlite3_close(raw);
  QueryRequest rq = valid();
  rq.values.speed_kt = 9.5;
  expect_error(rq, TOWDB_QUERY_RANGE,
               "speed_kt = 9.5 is outside the stored range [5, 7] kt of T-ATF 166 / LHA 1 / wire; pass extrapolate "
               "(--extrapolate) to extrapolate; the database's build says of T-ATF 166 / LHA 1 (grid 'g'): LHA 1 at 5 "
               "and 7 kt only: the tugs cannot hold more; the build could not tow 2 conditions of T-ATF 166 / LHA 1 "
               "(EQ-SWEEP-3), nearest: 9 kt, wind_kt=20, heading 0 deg: T_calc above the limit down to 3 kt");
  Database db(good_);
  try {
    db.query(rq);
  } catch (const QueryError& e) {
    EXPECT_EQ(std::string(e.what()).find("another tug"), std::string::npos) << e.what();
  }
  // An answered question carries no note.
  rq.values.speed_kt = 6.0;
  EXPECT_NO_THROW(db.query(rq));
}

}  // namespace
}  // namespace towdb::test
