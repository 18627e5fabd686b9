// Tests of the SQLite layer (generator/store): schema creation and migration
// from an empty file, refusal of foreign, corrupt, newer or locked files, a
// bit-exact round trip of doubles through REAL columns (after SQLite
// test/atof1.test), and migration 4's packing of daily_maxima into case_days.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "common/error.hpp"
#include "store/database.hpp"
#include "store/key_bytes.hpp"
#include "store/packed_days.hpp"
#include "test_support.hpp"

namespace towdb::store {
namespace {

class StoreTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_temp_dir("towdb-store"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

void expect_input_error(const std::function<void()>& fn, const std::string& pattern) {
  try {
    fn();
    ADD_FAILURE() << "no error; expected /" << pattern << "/";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what();
  }
}

TEST_F(StoreTest, CreatesEveryTableFromAnEmptyFile) {
  const auto path = dir_ / "new.db";
  { std::ofstream(path).flush(); }  // an empty file is a new database
  Database db = Database::open(path, Database::Mode::kCreate);
  EXPECT_EQ(db.schema_version(), latest_schema_version());
  EXPECT_GE(latest_schema_version(), 1);
  for (const char* table : {"meta", "vessels", "towline_components", "builds", "towline_fits", "cases", "results",
                            "case_days"}) {
    Statement s = db.prepare("SELECT count(*) FROM sqlite_schema WHERE type = 'table' AND name = ?1");
    s.bind(1, table);
    ASSERT_TRUE(s.step());
    EXPECT_EQ(s.column_int(0), 1) << table;
  }
}

TEST_F(StoreTest, ReopeningMigratesNothingTwice) {
  const auto path = dir_ / "a.db";
  { Database db = Database::open(path, Database::Mode::kCreate); }
  Database db = Database::open(path, Database::Mode::kReadWrite);
  EXPECT_EQ(db.schema_version(), latest_schema_version());
  Database ro = Database::open(path, Database::Mode::kReadOnly);
  EXPECT_EQ(ro.schema_version(), latest_schema_version());
}

TEST_F(StoreTest, ReadOnlyHandleRefusesWrites) {
  const auto path = dir_ / "a.db";
  { Database db = Database::open(path, Database::Mode::kCreate); }
  Database ro = Database::open(path, Database::Mode::kReadOnly);
  EXPECT_ANY_THROW(ro.exec("INSERT INTO meta (key, value) VALUES ('x', 'y')"));
}

TEST_F(StoreTest, MissingDatabaseIsNamed) {
  expect_input_error([&] { Database::open(dir_ / "none.db", Database::Mode::kReadOnly); },
                     "none.db: database does not exist");
}

TEST_F(StoreTest, ForeignSqliteFileIsRefused) {
  const auto path = dir_ / "other.db";
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  sqlite3_exec(raw, "CREATE TABLE t (x)", nullptr, nullptr, nullptr);
  sqlite3_close(raw);
  expect_input_error([&] { Database::open(path, Database::Mode::kReadWrite); }, "other.db: not a towdb database");
}

TEST_F(StoreTest, CorruptFileIsRefused) {
  const auto path = dir_ / "corrupt.db";
  { std::ofstream(path) << std::string(4096, 'x'); }
  expect_input_error([&] { Database::open(path, Database::Mode::kReadOnly); },
                     "corrupt.db: .*not a valid towdb database|corrupt.db: .*not a database");
}

TEST_F(StoreTest, NewerSchemaIsRefused) {
  const auto path = dir_ / "future.db";
  {
    Database db = Database::open(path, Database::Mode::kCreate);
    db.exec("PRAGMA user_version = 999");
  }
  expect_input_error([&] { Database::open(path, Database::Mode::kReadOnly); },
                     "schema version 999 is newer than this towdb understands");
}

TEST_F(StoreTest, LockedDatabaseIsNamedNotDamaged) {
  const auto path = dir_ / "locked.db";
  { Database db = Database::open(path, Database::Mode::kCreate); }
  Database holder = Database::open(path, Database::Mode::kReadWrite);
  holder.exec("BEGIN EXCLUSIVE");
  holder.exec("INSERT INTO meta (key, value) VALUES ('k', 'v')");
  // A second writer times out on the lock with a named error.
  Database other = Database::open(path, Database::Mode::kReadWrite);
  sqlite3_busy_timeout(other.handle(), 50);
  expect_input_error([&] { other.exec("INSERT INTO meta (key, value) VALUES ('k2', 'v2')"); },
                     "locked.db: .*another process holds a lock");
  holder.exec("COMMIT");
  Statement s = other.prepare("SELECT count(*) FROM meta");
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.column_int(0), 1);
}

TEST_F(StoreTest, DoublesRoundTripBitExactly) {
  Database db = Database::open(dir_ / "bits.db", Database::Mode::kCreate);
  db.exec("CREATE TEMP TABLE v (i INTEGER PRIMARY KEY, x REAL NOT NULL)");
  std::mt19937_64 rng(20261123);
  constexpr int kValues = 20000;
  std::vector<double> values;
  db.transaction([&] {
    Statement ins = db.prepare("INSERT INTO v (i, x) VALUES (?1, ?2)");
    for (int i = 0; i < kValues; ++i) {
      double x;
      do {
        x = std::bit_cast<double>(rng());
      } while (!std::isfinite(x));
      values.push_back(x);
      ins.bind(1, i).bind(2, x).run();
    }
  });
  Statement sel = db.prepare("SELECT x FROM v ORDER BY i");
  for (int i = 0; i < kValues; ++i) {
    ASSERT_TRUE(sel.step());
    const double y = sel.column_double(0);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(y), std::bit_cast<std::uint64_t>(values[static_cast<std::size_t>(i)]))
        << "value " << i;
  }
}

TEST_F(StoreTest, FailedTransactionLeavesNothing) {
  Database db = Database::open(dir_ / "tx.db", Database::Mode::kCreate);
  EXPECT_THROW(db.transaction([&] {
    db.exec("INSERT INTO meta (key, value) VALUES ('a', 'b')");
    throw std::runtime_error("simulated failure");
  }),
               std::runtime_error);
  Statement s = db.prepare("SELECT count(*) FROM meta");
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.column_int(0), 0);
}

// A database of schema version 3 (daily_maxima, one row per day), made from a
// new one by undoing migrations 7, 6, 5 and 4 as 001_initial.sql, 004_case_days.sql,
// 005_coverage_notes.sql, 006_catenary_lowest_point.sql, 007_day_records.sql and
// 008_maxima_binary16.sql define them (dropping case_days undoes 8, 7 and 4).
void make_version_3(const std::filesystem::path& path) {
  { Database db = Database::open(path, Database::Mode::kCreate); }
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  const char* sql =
      "DROP TABLE case_days;"
      "DROP TABLE speed_profiles;"  // migration 11 adds it again
      "ALTER TABLE cases DROP COLUMN speed_profile_id;"
      "DROP TABLE heading_profiles;"  // migration 10 adds it again
      "ALTER TABLE cases DROP COLUMN profile_id;"
      "DROP TABLE coverage_notes;"  // migration 5 adds it again
      "ALTER TABLE towline_fits DROP COLUMN lowest_elevation_ft;"  // migration 6 adds it again
      "CREATE TABLE daily_maxima (case_id INTEGER NOT NULL REFERENCES cases (case_id) ON DELETE CASCADE,"
      " day INTEGER NOT NULL CHECK (day >= 0), max_dynamic_kips REAL NOT NULL, slack_time_s REAL NOT NULL,"
      " snatch_events INTEGER NOT NULL, PRIMARY KEY (case_id, day)) WITHOUT ROWID;"
      "INSERT INTO cases (case_id, case_key, inputs_sha256, tug_name, tow_name, speed_kt, spectrum, heading_deg,"
      " line_type, length_ft, mean_tension_lbf, days, seed) VALUES"
      " (7, 'k7', 'h7', 'T-ATF 166', 'FFG 7', 9, 'pierson-moskowitz', 0, 'wire', 2000, 79000, 3, 1),"
      " (9, 'k9', 'h9', 'T-ATF 166', 'FFG 7', 9, 'pierson-moskowitz', 90, 'wire', 2000, 79000, 2, 1);"
      "INSERT INTO daily_maxima VALUES (7, 0, 101.25, 0, 0), (7, 1, 173.875, 12.5, 3), (7, 2, 99.0, 0, 0),"
      " (9, 0, 20.5, 0, 0), (9, 1, 21.0, 0, 0);"
      "PRAGMA user_version = 3;";
  char* err = nullptr;
  EXPECT_EQ(sqlite3_exec(raw, sql, nullptr, nullptr, &err), SQLITE_OK) << (err ? err : "");
  sqlite3_free(err);
  sqlite3_close(raw);
}

TEST_F(StoreTest, MigrationFourPacksEveryDayIntoOneRowPerCase) {
  // EVIDENCE-OF: schema/004_case_days.sql (values exact in binary32 survive unchanged)
  const auto path = dir_ / "v3.db";
  make_version_3(path);
  expect_input_error([&] { Database::open(path, Database::Mode::kReadOnly); }, "schema version 3 is older");
  Database db = Database::open(path, Database::Mode::kReadWrite);  // migrates
  EXPECT_EQ(db.schema_version(), latest_schema_version());
  Statement gone = db.prepare("SELECT count(*) FROM sqlite_schema WHERE name = 'daily_maxima'");
  ASSERT_TRUE(gone.step());
  EXPECT_EQ(gone.column_int(0), 0);
  const CaseDays a = read_case_days(db, 7);
  EXPECT_EQ(a.max_dynamic_kips, (std::vector<double>{101.25, 173.875, 99.0}));
  EXPECT_EQ(a.slack_time_s, (std::vector<double>{0.0, 12.5, 0.0}));
  EXPECT_EQ(a.snatch_events, (std::vector<std::int64_t>{0, 3, 0}));
  EXPECT_EQ(a.maxima_bytes, 4);  // migration 8 keeps every stored row binary32
  const CaseDays b = read_case_days(db, 9);
  EXPECT_EQ(b.max_dynamic_kips, (std::vector<double>{20.5, 21.0}));
  EXPECT_EQ(b.slack_time_s, (std::vector<double>{0.0, 0.0}));
  Statement nulls = db.prepare("SELECT slack_time_s IS NULL, snatch_events IS NULL FROM case_days WHERE case_id = 9");
  ASSERT_TRUE(nulls.step());
  EXPECT_EQ(nulls.column_int(0), 1);  // never slack: no array stored
  EXPECT_EQ(nulls.column_int(1), 1);
}

TEST_F(StoreTest, PackedDaysAreLittleEndianBinary32AndCheckedOnRead) {
  // IEEE-754 binary32 of 1.0 is 0x3F800000, stored low byte first.
  EXPECT_EQ(pack_float32({1.0}), std::string("\x00\x00\x80\x3f", 4));
  EXPECT_EQ(pack_uint32({258}), std::string("\x02\x01\x00\x00", 4));
  EXPECT_EQ(unpack_float32(pack_float32({0.1}), 1, "x")[0], static_cast<double>(0.1f));
  expect_input_error([&] { unpack_float32(std::string(7, '\0'), 2, "case_days.max_dynamic_kips"); },
                     "case_days.max_dynamic_kips: 7 bytes, expected 4 x 2 days");
  expect_input_error([&] { pack_uint32({-1}); }, "snatch_events = -1");
  Database db = Database::open(dir_ / "w.db", Database::Mode::kCreate);
  db.exec("INSERT INTO cases (case_id, case_key, inputs_sha256, tug_name, tow_name, speed_kt, spectrum, heading_deg,"
          " line_type, length_ft, mean_tension_lbf, days, seed) VALUES (1, 'k', 'h', 'A', 'B', 5, 'pierson-moskowitz',"
          " 0, 'fiber', 800, 1000, 2, 1)");
  expect_input_error([&] { write_case_days(db, 1, CaseDays{{1.0, 2.0}, {0.0}, {0, 0}}); }, "must be the same");
  // The table's CHECK refuses an array that does not hold `days` values.
  EXPECT_THROW(db.exec("INSERT INTO case_days (case_id, days, max_dynamic_kips) VALUES (1, 2, x'0000803f')"),
               std::exception);
}

TEST_F(StoreTest, MaximaOnlyDaysKeepTheMaximaAndSayTheRestWasNotStored) {
  // EVIDENCE-OF: schema/007_day_records.sql (slack_snatch_stored = 0: both per-day columns NULL)
  Database db = Database::open(dir_ / "m.db", Database::Mode::kCreate);
  db.exec("INSERT INTO cases (case_id, case_key, inputs_sha256, tug_name, tow_name, speed_kt, spectrum, heading_deg,"
          " line_type, length_ft, mean_tension_lbf, days, seed) VALUES (1, 'k1', 'h', 'A', 'B', 5,"
          " 'pierson-moskowitz', 0, 'fiber', 800, 1000, 2, 1), (2, 'k2', 'h', 'A', 'B', 5, 'pierson-moskowitz', 30,"
          " 'fiber', 800, 1000, 2, 1), (3, 'k3', 'h', 'A', 'B', 5, 'pierson-moskowitz', 60, 'fiber', 800, 1000, 2, 1)");
  CaseDays maxima_only{{1.5, 2.5}, {}, {}, false};
  write_case_days(db, 1, maxima_only);
  write_case_days(db, 2, CaseDays{{3.5, 4.5}, {10.0, 0.0}, {2, 0}});
  write_case_days(db, 3, CaseDays{{5.5, 6.5}, {0.0, 0.0}, {0, 0}});
  const CaseDays a = read_case_days(db, 1);
  EXPECT_FALSE(a.slack_snatch_stored);
  EXPECT_EQ(a.max_dynamic_kips, (std::vector<double>{1.5, 2.5}));
  EXPECT_TRUE(a.slack_time_s.empty());
  EXPECT_TRUE(a.snatch_events.empty());
  EXPECT_TRUE(read_case_days(db, 3).slack_snatch_stored);  // stored, all zero: not the same as "not stored"
  // Per-day values given although the row says they are not stored: refused.
  expect_input_error([&] { write_case_days(db, 1, CaseDays{{1.5, 2.5}, {0.0, 0.0}, {0, 0}, false}); },
                     "not stored");
  // The table refuses a row that says "not stored" and holds them anyway.
  EXPECT_THROW(db.exec("UPDATE case_days SET slack_snatch_stored = 0 WHERE case_id = 2"), std::exception);

  // Dropping keeps every maximum, counts the rows it changed, and is idempotent.
  EXPECT_EQ(drop_slack_snatch_days(db), 2);
  EXPECT_EQ(drop_slack_snatch_days(db), 0);
  const CaseDays b = read_case_days(db, 2);
  EXPECT_FALSE(b.slack_snatch_stored);
  EXPECT_EQ(b.max_dynamic_kips, (std::vector<double>{3.5, 4.5}));
  EXPECT_TRUE(b.slack_time_s.empty());
}

TEST_F(StoreTest, Binary16MaximaAreTheNearestHalfAndRepackedOnlyWhereTheyFit) {
  // EVIDENCE-OF: schema/008_maxima_binary16.sql. IEEE 754-2008 binary16: 1.0 is 0x3C00 (stored
  // low byte first); 11 significant bits, so in [512, 1024) the spacing is 0.5 and in [2048, 4096)
  // it is 2; 65,504 is the largest finite value.
  std::string h;
  ASSERT_TRUE(pack_float16({1.0}, &h));
  EXPECT_EQ(h, std::string("\x00\x3c", 2));
  ASSERT_TRUE(pack_float16({1000.3, 2049.0, 2051.0, 65504.0, 0.890570456810014}, &h));
  const std::vector<double> r = unpack_float16(h, 5, "x");
  EXPECT_EQ(r[0], 1000.5);  // nearest: 0.2 away, 1000.0 is 0.3 away
  EXPECT_EQ(r[1], 2048.0);  // a tie goes to the even significand
  EXPECT_EQ(r[2], 2052.0);
  EXPECT_EQ(r[3], 65504.0);
  EXPECT_NEAR(r[4], 0.890570456810014, 0.890570456810014 * std::ldexp(1.0, -11));  // the smallest stored maximum
  h = "unchanged";
  EXPECT_FALSE(pack_float16({1.0, 65520.0}, &h));  // rounds to infinity in binary16
  EXPECT_FALSE(pack_float16({std::nan("")}, &h));
  EXPECT_EQ(h, "unchanged");
  expect_input_error([&] { unpack_float16(std::string(3, '\0'), 2, "case_days.max_dynamic_kips"); },
                     "case_days.max_dynamic_kips: 3 bytes, expected 2 x 2 days");

  Database db = Database::open(dir_ / "h.db", Database::Mode::kCreate);
  db.exec("INSERT INTO cases (case_id, case_key, inputs_sha256, tug_name, tow_name, speed_kt, spectrum, heading_deg,"
          " line_type, length_ft, mean_tension_lbf, days, seed) VALUES (1, 'k1', 'h', 'A', 'B', 5,"
          " 'pierson-moskowitz', 0, 'fiber', 800, 1000, 2, 1), (2, 'k2', 'h', 'A', 'B', 5, 'pierson-moskowitz', 30,"
          " 'fiber', 800, 1000, 2, 1), (3, 'k3', 'h', 'A', 'B', 5, 'pierson-moskowitz', 60, 'fiber', 800, 1000, 2, 1)");
  CaseDays half{{1000.3, 2.5}, {}, {}, false, 2};
  write_case_days(db, 1, half);
  const CaseDays a = read_case_days(db, 1);
  EXPECT_EQ(a.maxima_bytes, 2);
  EXPECT_EQ(a.max_dynamic_kips, (std::vector<double>{1000.5, 2.5}));
  CaseDays too_large{{70000.0, 2.5}, {}, {}, false, 2};
  write_case_days(db, 2, too_large);  // does not fit: stored binary32
  EXPECT_EQ(read_case_days(db, 2).maxima_bytes, 4);
  EXPECT_EQ(read_case_days(db, 2).max_dynamic_kips, (std::vector<double>{70000.0, 2.5}));
  write_case_days(db, 3, CaseDays{{1000.3, 7.0}, {}, {}, false});
  expect_input_error([&] { write_case_days(db, 3, CaseDays{{1.0, 2.0}, {}, {}, false, 3}); }, "maxima_bytes = 3");
  // The table's CHECK holds the blob to maxima_bytes x days.
  EXPECT_THROW(db.exec("UPDATE case_days SET maxima_bytes = 2 WHERE case_id = 3"), std::exception);

  // Repacking changes the binary32 cases that fit, counts them, and is idempotent.
  EXPECT_EQ(pack_maxima_binary16(db), 1);
  EXPECT_EQ(pack_maxima_binary16(db), 0);
  const CaseDays c = read_case_days(db, 3);
  EXPECT_EQ(c.maxima_bytes, 2);
  EXPECT_EQ(c.max_dynamic_kips, (std::vector<double>{1000.5, 7.0}));
  EXPECT_EQ(read_case_days(db, 2).maxima_bytes, 4);
}

TEST_F(StoreTest, MigrationNineStoresTheCaseKeysAsTheirThirtyTwoBytes) {
  // EVIDENCE-OF: schema/009_key_bytes.sql (hex TEXT keys -> 32-byte BLOBs; other values left as they are)
  const std::string hex = "053d96ac44b6bf61ffcb33c84f1fbe40ae35f738068b85319262fffe939fd7a8";
  const std::string bytes = key_bytes(hex, "case_key");
  ASSERT_EQ(bytes.size(), 32u);
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x05);
  EXPECT_EQ(static_cast<unsigned char>(bytes[31]), 0xa8);
  EXPECT_EQ(key_bytes("053D96AC44B6BF61FFCB33C84F1FBE40AE35F738068B85319262FFFE939FD7A8", "x"), bytes);
  expect_input_error([] { key_bytes("k7", "case_key"); }, "case_key = 'k7': must be a SHA-256 as 64 hexadecimal");
  expect_input_error([&] { key_bytes(hex.substr(0, 63) + "g", "condition_key"); }, "condition_key = '");

  const auto path = dir_ / "v8.db";
  {
    Database db = Database::open(path, Database::Mode::kCreate);
    db.exec("INSERT INTO cases (case_id, case_key, inputs_sha256, condition_key, tug_name, tow_name, speed_kt, spectrum,"
            " heading_deg, line_type, length_ft, mean_tension_lbf, days, seed) VALUES (1, '" + hex + "', '" + hex +
            "', '" + hex + "', 'A', 'B', 5, 'pierson-moskowitz', 0, 'fiber', 800, 1000, 2, 1), (2, 'k2', 'h2', NULL,"
            " 'A', 'B', 5, 'pierson-moskowitz', 30, 'fiber', 800, 1000, 2, 1)");
    db.exec("DROP TABLE speed_profiles; ALTER TABLE cases DROP COLUMN speed_profile_id");  // migration 11 adds them
    db.exec("DROP TABLE heading_profiles; ALTER TABLE cases DROP COLUMN profile_id");  // migration 10 adds them
    db.exec("PRAGMA user_version = 8");
  }
  Database db = Database::open(path, Database::Mode::kReadWrite);  // migrates
  EXPECT_EQ(db.schema_version(), latest_schema_version());
  Statement a = db.prepare("SELECT typeof(case_key), case_key = ?1, inputs_sha256 = ?1, condition_key = ?1 "
                           "FROM cases WHERE case_id = 1");
  a.bind_blob(1, bytes);
  ASSERT_TRUE(a.step());
  EXPECT_EQ(a.column_text(0), "blob");
  EXPECT_EQ(a.column_int(1), 1);
  EXPECT_EQ(a.column_int(2), 1);
  EXPECT_EQ(a.column_int(3), 1);
  Statement b = db.prepare("SELECT case_key, typeof(condition_key) FROM cases WHERE case_id = 2");
  ASSERT_TRUE(b.step());
  EXPECT_EQ(b.column_text(0), "k2");  // not a SHA-256: left as it was
  EXPECT_EQ(b.column_text(1), "null");
}

TEST_F(StoreTest, MigrationElevenAddsSpeedProfilesAndDropsTheConditionIndex) {
  // EVIDENCE-OF: schema/011_speed_profiles.sql (the profile's CHECKs, the index it drops)
  const auto path = dir_ / "v10.db";
  {
    Database db = Database::open(path, Database::Mode::kCreate);
    db.exec("DROP TABLE speed_profiles; ALTER TABLE cases DROP COLUMN speed_profile_id");
    db.exec("CREATE INDEX cases_by_condition ON cases (tug_name, tow_name, line_type, speed_kt, heading_deg)");
    db.exec("PRAGMA user_version = 10");
  }
  Database db = Database::open(path, Database::Mode::kReadWrite);  // migrates
  EXPECT_EQ(db.schema_version(), latest_schema_version());
  Statement index = db.prepare("SELECT count(*) FROM sqlite_schema WHERE name = 'cases_by_condition'");
  ASSERT_TRUE(index.step());
  EXPECT_EQ(index.column_int(0), 0);
  const std::string key(32, 'k');
  auto insert = [&](double step_kt, std::int64_t speeds, const std::string& sigma) {
    Statement st = db.prepare(
        "INSERT INTO speed_profiles (profile_key, speed_first_kt, speed_step_kt, speeds, sigma_kips_f16) "
        "VALUES (?, 5, ?, ?, ?)");
    st.bind_blob(1, key).bind(2, step_kt).bind(3, speeds).bind_blob(4, sigma);
    st.run();
  };
  insert(0.25, 2, std::string(4, '\0'));
  EXPECT_THROW(insert(0.25, 2, std::string(8, '\0')), std::exception);  // 2 bytes a speed
  EXPECT_THROW(insert(0.0, 2, std::string(4, '\0')), std::exception);   // step > 0
  EXPECT_THROW(insert(0.25, 1, std::string(2, '\0')), std::exception);  // two speeds at least
  db.exec("UPDATE cases SET speed_profile_id = NULL");  // the column exists
}

}  // namespace
}  // namespace towdb::store
