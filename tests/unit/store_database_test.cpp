// Tests of the SQLite layer (generator/store): schema creation and migration
// from an empty file, refusal of foreign, corrupt, newer or locked files, and a
// bit-exact round trip of doubles through REAL columns (after SQLite
// test/atof1.test).
#include <bit>
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
                            "daily_maxima"}) {
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

}  // namespace
}  // namespace towdb::store
