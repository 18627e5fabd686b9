// Shared test helpers: named tolerances and paths (one copy, after Ceres
// test_util). A tolerance states its kind (relative / absolute with unit) and,
// where it is declared, why it has that size.
#ifndef TOWDB_TESTS_SUPPORT_TEST_SUPPORT_HPP
#define TOWDB_TESTS_SUPPORT_TEST_SUPPORT_HPP

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace towdb::test {

struct RelTol {
  double value;  // |a - b| <= value * max(|a|, |b|)
};
struct AbsTol {
  double value;  // |a - b| <= value, in the unit of the quantity
};

::testing::AssertionResult RelClose(double actual, double expected, RelTol tol);
::testing::AssertionResult AbsClose(double actual, double expected, AbsTol tol);

// The project source root (tests run from it; TOWDB_SOURCE_DIR overrides).
std::filesystem::path source_dir();
// The towdb executable under test (TOWDB_EXE), or "" when not set.
std::filesystem::path towdb_exe();
// A fresh, empty temporary directory for one test, removed by the caller.
std::filesystem::path make_temp_dir(const std::string& prefix);

// Runs fn and expects a towdb::InputError whose message contains `needle`
// (the field name, usually); any other outcome is a test failure.
void expect_input_error(const std::function<void()>& fn, const std::string& needle);

// The whole content of a file, byte for byte ("" when it cannot be read).
std::string read_text(const std::filesystem::path& path);

// The environment variable `name`, or `fallback` when it is unset or empty.
std::string env_or(const char* name, const std::string& fallback);

// The comma-separated cells of each row of a test data file after its header
// row; empty lines and lines starting with '#' (provenance notes) are skipped.
// Throws std::runtime_error when the file cannot be opened.
std::vector<std::vector<std::string>> read_csv_rows(const std::filesystem::path& path);

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};
// Runs `towdb <args>` (args already shell-quoted) with optional stdin text.
CommandResult run_towdb(const std::string& args, const std::string& stdin_text = "");

}  // namespace towdb::test

#define EXPECT_REL_CLOSE(actual, expected, rel) \
  EXPECT_TRUE(::towdb::test::RelClose((actual), (expected), ::towdb::test::RelTol{rel}))
#define EXPECT_ABS_CLOSE(actual, expected, abs) \
  EXPECT_TRUE(::towdb::test::AbsClose((actual), (expected), ::towdb::test::AbsTol{abs}))

#endif  // TOWDB_TESTS_SUPPORT_TEST_SUPPORT_HPP
