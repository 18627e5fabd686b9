// Fuzzer of database files handed over by someone else: the small fuzz
// database (fuzz_db.hpp) with random bytes changed, or with random stored
// values replaced through SQL (CHECK constraints off, as a careless writer
// would) by NULL, text, blobs, inf, -inf, 0, -1, 1e308 and the like.
// Properties (issue 20 items 2-4; docs/hardening.md):
//   - towdb_query_open returns TOWDB_QUERY_OK or TOWDB_QUERY_DATABASE with a
//     message that starts with the file's path; never a crash, never another
//     code;
//   - a database that opens answers valid requests (one per group) with
//     TOWDB_QUERY_OK, _INPUT or _RANGE, and every answer is finite and
//     self-consistent (fuzz_query_checks.hpp): a changed value is either
//     refused on open or harmless, never a NaN or a wrong sign in an answer.
// Test plan:
//   fuzz-db-1  the unchanged fuzz database opens and answers
//   fuzz-db-2  the kept regression edits (tests/fuzz/regressions/database) keep the properties
//   fuzz-db-3  seeded byte edits keep the properties
//   fuzz-db-4  seeded SQL value edits keep the properties
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include "fuzz_checks.hpp"
#include "fuzz_db.hpp"
#include "fuzz_query_checks.hpp"
#include "fuzz_support.hpp"
#include "test_support.hpp"
#include "towdb/query.h"

namespace towdb::fuzz {
namespace {

// One valid request per group of the fuzz database (nodes and mid-cell).
std::vector<towdb_query_request> valid_requests() {
  std::vector<towdb_query_request> out;
  auto add = [&](const char* tug, const char* tow, const char* line, double speed, double wind, double hs, double tp,
                 double heading, double length, double mean) {
    towdb_query_request r;
    towdb_query_request_init(&r);
    r.tug = tug;
    r.tow = tow;
    r.line = line;
    r.speed_kt = speed;
    r.wind_kt = wind;
    r.hs_ft = hs;
    r.tp_s = tp;
    r.heading_deg = heading;
    r.length_ft = length;
    r.mean_tension_lbf = mean;
    out.push_back(r);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  add("T-ATF 166", "LHA 1", "wire", 6.0, 25.0, nan, nan, 90.0, 1500.0, nan);
  add("T-ATF 166", "LHA 1", "wire", 5.0, 20.0, nan, nan, 0.0, 1000.0, nan);
  add("ARS 50", "FFG 7", "fiber", 7.0, 30.0, nan, nan, 45.0, 800.0, nan);
  add("ARS 50", "LHA 1", "wire", 5.0, nan, 10.0, 9.0, 100.0, 1500.0, 60000.0);
  return out;
}

// An edit of the file: bytes at offsets, or SQL statements.
struct Edit {
  std::vector<std::pair<std::size_t, unsigned char>> bytes;
  std::string sql;
};

// Regression file format: "# bytes" then "<offset> <hex byte>" lines (the
// byte written at that offset of the fuzz database's file), or
// "# sql" then SQL statements (run with CHECK constraints off).
std::string serialize(const Edit& e) {
  std::ostringstream os;
  if (!e.sql.empty()) {
    os << "# sql\n" << e.sql << "\n";
    return os.str();
  }
  os << "# bytes\n";
  for (const auto& [off, b] : e.bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%zu %02x\n", off, b);
    os << buf;
  }
  return os.str();
}

Edit deserialize(const std::string& text) {
  Edit e;
  if (text.rfind("# sql", 0) == 0) {
    e.sql = text.substr(text.find('\n') + 1);
    return e;
  }
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::size_t off = 0;
    unsigned int b = 0;
    if (std::sscanf(line.c_str(), "%zu %x", &off, &b) == 2) e.bytes.emplace_back(off, static_cast<unsigned char>(b));
  }
  return e;
}

// The big-endian bytes of a double, as SQLite stores a REAL in a record.
std::vector<unsigned char> be_bytes(double v) {
  std::uint64_t u = 0;
  std::memcpy(&u, &v, sizeof u);
  std::vector<unsigned char> out(8);
  for (int i = 0; i < 8; ++i) out[static_cast<std::size_t>(i)] = static_cast<unsigned char>(u >> (56 - 8 * i));
  return out;
}

Edit random_byte_edit(RandomStream& rng, const std::string& base) {
  const std::size_t size = base.size();
  Edit e;
  const std::size_t n = 1 + below(rng, 8);
  for (std::size_t k = 0; k < n; ++k) {
    // Mostly past the 100-byte file header: the pages hold the data.
    const std::size_t off = chance(rng, 0.05) ? below(rng, 100) : 100 + below(rng, size - 100);
    if (chance(rng, 0.3)) {  // an odd double written over 8 bytes (a REAL in a record)
      const auto bytes = be_bytes(odd_doubles()[below(rng, odd_doubles().size())]);
      for (std::size_t i = 0; i < 8 && off + i < size; ++i) e.bytes.emplace_back(off + i, bytes[i]);
    } else if (chance(rng, 0.5)) {
      e.bytes.emplace_back(off, static_cast<unsigned char>(below(rng, 256)));
    } else {
      e.bytes.emplace_back(off, static_cast<unsigned char>(static_cast<unsigned char>(base[off]) ^ (1u << below(rng, 8))));
    }
  }
  return e;
}

// The columns Engine::open reads, by table, and odd SQL values for them.
Edit random_sql_edit(RandomStream& rng, int case_count) {
  static const std::vector<std::pair<const char*, std::vector<const char*>>> kColumns = {
      {"cases", {"speed_kt", "spectrum", "wind_kt", "hs_ft", "tp_s", "gamma", "heading_deg", "length_ft",
                 "mean_tension_lbf", "days", "calculated_mean_tension_lbf", "tug_name", "line_type", "status",
                 "swell_hs_ft", "fit_id"}},
      {"results", {"gumbel_u_kips", "gumbel_alpha_per_kip", "dynamic_999_kips", "ci_level", "ci_low_kips",
                   "ci_high_kips", "breaking_strength_lbf", "above_breaking_strength", "slack_fraction"}},
      {"towline_fits", {"sag_ft"}}};
  static const char* const kValues[] = {"NULL", "'abc'", "''", "X'00ff'", "9e999", "-9e999", "0", "-0.0", "-1",
                                        "1e308", "-1e308", "4.9e-324", "1e-300", "2.5", "1000000", "-50",
                                        "9223372036854775807", "'5'", "0.5", "2"};
  const auto& [table, cols] = kColumns[below(rng, kColumns.size())];
  const char* col = cols[below(rng, cols.size())];
  const char* key = std::strcmp(table, "towline_fits") == 0 ? "fit_id" : "case_id";
  std::ostringstream os;
  const std::size_t n = 1 + below(rng, 2);
  for (std::size_t k = 0; k < n; ++k) {
    const char* value = kValues[below(rng, std::size(kValues))];
    os << "UPDATE " << table << " SET " << col << " = " << value << " WHERE " << key << " = "
       << 1 + below(rng, static_cast<std::size_t>(case_count)) << ";\n";
  }
  Edit e;
  e.sql = os.str();
  return e;
}

class FuzzDatabase : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(test::make_temp_dir("towdb-fuzz-db"));
    write_fuzz_db(*dir_ / "base.towdb", true);
    base_ = new std::string(test::read_text(*dir_ / "base.towdb"));
    case_count_ = static_cast<int>(fuzz_db_cases(true).size());
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
    delete base_;
  }

  // Writes the edited file; "" or the problem with applying a SQL edit.
  static std::string apply(const Edit& e, const std::filesystem::path& path) {
    std::string bytes = *base_;
    for (const auto& [off, b] : e.bytes) {
      if (off < bytes.size()) bytes[off] = static_cast<char>(b);
    }
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (e.sql.empty()) return "";
    sqlite3* raw = nullptr;
    std::string problem;
    if (sqlite3_open(path.c_str(), &raw) != SQLITE_OK) problem = "cannot open the copy";
    // No fsync: the copy is scratch (keeps the budget on the code under test).
    const std::string sql =
        "PRAGMA ignore_check_constraints = ON; PRAGMA foreign_keys = OFF; PRAGMA synchronous = OFF; "
        "PRAGMA journal_mode = MEMORY; " + e.sql;
    char* err = nullptr;
    if (problem.empty() && sqlite3_exec(raw, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
      // A UNIQUE or NOT NULL violation: the edit is not possible, the file is unchanged.
      sqlite3_free(err);
    }
    sqlite3_close(raw);
    return problem;
  }

  // Opens the edited file and checks every property; "" when they hold.
  static std::string check(const Edit& e, Tally& tally) {
    ++tally.executions;
    const auto path = *dir_ / "fuzz.towdb";
    if (std::string p = apply(e, path); !p.empty()) return p;
    towdb_query_db* db = nullptr;
    const int code = towdb_query_open(path.c_str(), TOWDB_QUERY_SPACE_AUTO, &db);
    const std::string msg = towdb_query_errmsg(db);
    std::string problem;
    if (code == TOWDB_QUERY_DATABASE) {
      ++tally.refused;
      tally.distinct_messages.insert(msg.substr(path.string().size(), 60));
      if (msg.rfind(path.string(), 0) != 0) problem = "the refusal does not start with the file's path: " + msg;
    } else if (code != TOWDB_QUERY_OK) {
      problem = "open gave code " + std::to_string(code) + ": " + msg;
    } else {
      ++tally.accepted;
      for (const towdb_query_request& r : valid_requests()) {
        towdb_query_result a{};
        const int rc = towdb_query_run(db, &r, &a);
        if (rc == TOWDB_QUERY_OK) problem = check_answer(db, r, a);
        if (rc != TOWDB_QUERY_OK && rc != TOWDB_QUERY_INPUT && rc != TOWDB_QUERY_RANGE) {
          problem = "a valid request gave code " + std::to_string(rc) + ": " + towdb_query_errmsg(db);
        }
        if (!problem.empty()) {
          problem = std::string("request ") + r.tug + " / " + r.tow + ": " + problem;
          break;
        }
      }
    }
    towdb_query_close(db);
    return problem;
  }

  template <typename Draw>
  void run(const std::string& name, std::uint64_t fixed_seed, int base_iterations, Draw draw) {
    Findings findings(name);
    Tally tally;
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t s = seed(fixed_seed);
    const int n = iterations(base_iterations);
    for (int i = 0; i < n; ++i) {
      RandomStream rng(s, static_cast<std::uint64_t>(i));
      const Edit e = draw(rng);
      const std::string problem = check(e, tally);
      if (!problem.empty() &&
          !findings.report("seed" + std::to_string(s) + "-iter" + std::to_string(i) + ".txt", serialize(e), problem)) {
        break;
      }
    }
    tally.print(name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    EXPECT_GT(tally.accepted, 0);
    EXPECT_GT(tally.refused, 0);
  }

  static std::filesystem::path* dir_;
  static std::string* base_;
  static int case_count_;
};
std::filesystem::path* FuzzDatabase::dir_ = nullptr;
std::string* FuzzDatabase::base_ = nullptr;
int FuzzDatabase::case_count_ = 0;

TEST_F(FuzzDatabase, UnchangedDatabaseOpensAndAnswers) {  // fuzz-db-1
  Tally tally;
  EXPECT_EQ(check(Edit{}, tally), "");
  EXPECT_EQ(tally.accepted, 1);
  towdb_query_db* db = nullptr;
  ASSERT_EQ(towdb_query_open((*dir_ / "fuzz.towdb").c_str(), TOWDB_QUERY_SPACE_AUTO, &db), TOWDB_QUERY_OK);
  for (const towdb_query_request& r : valid_requests()) {
    towdb_query_result a{};
    EXPECT_EQ(towdb_query_run(db, &r, &a), TOWDB_QUERY_OK) << r.tug << " / " << r.tow << ": " << towdb_query_errmsg(db);
  }
  towdb_query_close(db);
}

TEST_F(FuzzDatabase, RegressionEditsKeepTheProperties) {  // fuzz-db-2
  const auto kept = load_dir("regressions/database");
  ASSERT_FALSE(kept.empty()) << "no inputs under tests/fuzz/regressions/database";
  Tally tally;
  for (const Input& in : kept) EXPECT_EQ(check(deserialize(in.text), tally), "") << in.name;
}

TEST_F(FuzzDatabase, RandomBytesChanged) {  // fuzz-db-3
  const std::string& base = *base_;
  run("database_bytes", 20005, 2000, [&base](RandomStream& rng) { return random_byte_edit(rng, base); });
}

TEST_F(FuzzDatabase, RandomValuesChanged) {  // fuzz-db-4
  const int cases = case_count_;
  run("database_values", 20006, 2000, [cases](RandomStream& rng) { return random_sql_edit(rng, cases); });
}

}  // namespace
}  // namespace towdb::fuzz
