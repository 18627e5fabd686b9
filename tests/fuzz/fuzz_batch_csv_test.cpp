// Fuzzer of `towdb query --batch`: mutated CSV on stdin (seeded from
// tests/fuzz/corpus/batch), answered from the fuzz database (fuzz_db.hpp) by
// the built towdb executable, in CSV and in JSON. Properties (issue 20 items
// 2-3; docs/hardening.md; README "Exit codes"):
//   - the exit code is 0 (every row answered) or 2 (bad input); never 1,
//     never a crash;
//   - with exit 2 every "towdb: error:" line on stderr names a line of stdin
//     (or the missing header) and a column or request field; with exit 0
//     there is none;
//   - nothing is written partly: either stdout is empty (the whole input was
//     refused: no header row, an unknown or repeated column) or it holds one
//     answer or error row per data row (CSV: a header and one line per row;
//     JSON: an array with one element per row).
// Test plan:
//   fuzz-batch-1  the corpus files keep the properties (the good ones exit 0)
//   fuzz-batch-2  the kept regression inputs (tests/fuzz/regressions/batch) keep the properties
//   fuzz-batch-3  seeded mutations keep the properties, in CSV and JSON output
#include <chrono>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fuzz_checks.hpp"
#include "fuzz_db.hpp"
#include "fuzz_support.hpp"
#include "test_support.hpp"

namespace towdb::fuzz {
namespace {

const std::vector<std::string> kColumns = {"tug",         "tow",       "line",     "spectrum",    "speed_kt",
                                           "wind_kt",     "hs_ft",     "tp_s",     "heading_deg", "length_ft",
                                           "mean_tension_lbf", "probability", "tow_days", "extrapolate", "brake"};

// Data rows after the header, as run_batch counts them (blank lines skipped);
// -1 when there is no header row.
int data_rows(const std::string& input) {
  std::istringstream is(input);
  bool header = false;
  int rows = 0;
  for (std::string line; std::getline(is, line);) {
    const bool blank = line.find_first_not_of(" \r") == std::string::npos;
    if (!header) {
      header = !blank;
    } else if (!blank) {
      ++rows;
    }
  }
  return header ? rows : -1;
}

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// Checks one run; "" when every property holds.
std::string check_input(const std::string& db, const std::string& input, bool json, Tally& tally) {
  ++tally.executions;
  const test::CommandResult r = test::run_towdb("query --db '" + db + "' --batch" + (json ? " --json" : ""), input);
  const std::string where = " (exit " + std::to_string(r.exit_code) + ")\nstderr: " + r.err.substr(0, 600);
  if (r.exit_code != 0 && r.exit_code != 2) return "exit code is neither 0 nor 2" + where;
  std::istringstream err(r.err);
  int error_lines = 0;
  for (std::string line; std::getline(err, line);) {
    if (line.rfind("towdb: error:", 0) != 0) continue;
    ++error_lines;
    tally.distinct_messages.insert(line.substr(0, 60));
    if (line.find("line ") == std::string::npos && line.find("header") == std::string::npos) {
      return "an error names neither a line of stdin nor the header: " + line;
    }
    bool named = line.find("column") != std::string::npos || line.find("cells") != std::string::npos ||
                 line.find("no stored case at") != std::string::npos;
    for (const std::string& c : kColumns) named = named || has_word(line, c);
    if (!named) return "an error names no column or field: " + line;
  }
  if (r.exit_code == 0) {
    ++tally.accepted;
    if (error_lines > 0) return "exit 0 with an error on stderr" + where;
  } else {
    ++tally.refused;
    if (error_lines == 0) return "exit 2 without a 'towdb: error:' line" + where;
  }
  if (r.out.empty()) {
    return r.exit_code == 2 ? "" : "exit 0 with no output";
  }
  const int rows = data_rows(input);
  if (json) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(r.out);
    } catch (const std::exception& e) {
      return std::string("the JSON output does not parse: ") + e.what() + where;
    }
    if (!j.is_array() || static_cast<int>(j.size()) != rows) {
      return "JSON output has " + std::to_string(j.size()) + " elements for " + std::to_string(rows) + " rows" + where;
    }
  } else if (count_lines(r.out) != rows + 1) {
    return "CSV output has " + std::to_string(count_lines(r.out)) + " lines for " + std::to_string(rows) +
           " rows and a header (partly written?)" + where + "\nstdout: " + r.out.substr(0, 600);
  }
  return "";
}

class FuzzBatchCsv : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(test::make_temp_dir("towdb-fuzz-batch"));
    write_fuzz_db(*dir_ / "fuzz.towdb", false);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }
  static std::string db() { return (*dir_ / "fuzz.towdb").string(); }
  static std::filesystem::path* dir_;
};
std::filesystem::path* FuzzBatchCsv::dir_ = nullptr;

TEST_F(FuzzBatchCsv, CorpusKeepsTheProperties) {  // fuzz-batch-1
  ASSERT_FALSE(test::towdb_exe().empty()) << "TOWDB_EXE is not set";
  const auto corpus = load_dir("corpus/batch");
  ASSERT_FALSE(corpus.empty()) << "no inputs under tests/fuzz/corpus/batch";
  for (const Input& in : corpus) {
    for (bool json : {false, true}) {
      Tally tally;
      EXPECT_EQ(check_input(db(), in.text, json, tally), "") << in.name;
      if (in.name.rfind("bad_", 0) != 0) {
        EXPECT_EQ(tally.accepted, 1) << in.name << " is not answered in full";
      }
    }
  }
}

TEST_F(FuzzBatchCsv, RegressionInputsKeepTheProperties) {  // fuzz-batch-2
  ASSERT_FALSE(test::towdb_exe().empty()) << "TOWDB_EXE is not set";
  const auto kept = load_dir("regressions/batch");
  ASSERT_FALSE(kept.empty()) << "no inputs under tests/fuzz/regressions/batch";
  for (const Input& in : kept) {
    for (bool json : {false, true}) {
      Tally tally;
      EXPECT_EQ(check_input(db(), in.text, json, tally), "") << in.name << (json ? " (json)" : "");
    }
  }
}

TEST_F(FuzzBatchCsv, MutatedBatchInput) {  // fuzz-batch-3
  ASSERT_FALSE(test::towdb_exe().empty()) << "TOWDB_EXE is not set";
  const auto corpus = load_dir("corpus/batch");
  ASSERT_FALSE(corpus.empty());
  std::vector<std::string> words = kColumns;
  for (const char* w : {"T-ATF 166", "ARS 50", "LHA 1", "FFG 7", "wire", "fiber", "jonswap"}) words.push_back(w);
  const Mutator mutator(corpus, words);
  Findings findings("batch");
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t s = seed(20007);
  const int n = iterations(400);
  for (int i = 0; i < n; ++i) {
    RandomStream rng(s, static_cast<std::uint64_t>(i));
    const Input& base = corpus[below(rng, corpus.size())];
    const std::string text = mutator.mutate(rng, base.text);
    const bool json = chance(rng, 0.25);
    const std::string problem = check_input(db(), text, json, tally);
    if (!problem.empty() &&
        !findings.report("seed" + std::to_string(s) + "-iter" + std::to_string(i) + (json ? "-json-" : "-") + base.name,
                         text, problem)) {
      break;
    }
  }
  tally.print("batch", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.refused, 0);
}

}  // namespace
}  // namespace towdb::fuzz
