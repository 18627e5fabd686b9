#include "test_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <sys/wait.h>

#include "common/error.hpp"

namespace towdb::test {

namespace {
std::string num(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}
}  // namespace

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}

::testing::AssertionResult RelClose(double actual, double expected, RelTol tol) {
  const double scale = std::max(std::abs(actual), std::abs(expected));
  const double diff = std::abs(actual - expected);
  if (std::isfinite(actual) && diff <= tol.value * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "actual " << num(actual) << " vs expected " << num(expected) << ": relative difference "
         << (scale > 0 ? diff / scale : diff) << " > tolerance " << tol.value;
}

::testing::AssertionResult AbsClose(double actual, double expected, AbsTol tol) {
  const double diff = std::abs(actual - expected);
  if (std::isfinite(actual) && diff <= tol.value) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual " << num(actual) << " vs expected " << num(expected)
                                       << ": difference " << diff << " > tolerance " << tol.value;
}

std::filesystem::path source_dir() {
  if (const char* s = std::getenv("TOWDB_SOURCE_DIR")) return s;
  return std::filesystem::current_path();
}

std::filesystem::path towdb_exe() {
  if (const char* s = std::getenv("TOWDB_EXE")) return s;
  return {};
}

std::filesystem::path make_temp_dir(const std::string& prefix) {
  std::random_device rd;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto p = std::filesystem::temp_directory_path() /
                   (prefix + "-" + std::to_string(rd()) + std::to_string(attempt));
    if (std::filesystem::create_directory(p)) return p;
  }
  throw std::runtime_error("cannot create a temporary directory");
}

void expect_input_error(const std::function<void()>& fn, const std::string& needle) {
  try {
    fn();
    ADD_FAILURE() << "no InputError; expected one naming '" << needle << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

CommandResult run_towdb(const std::string& args, const std::string& stdin_text) {
  const auto dir = make_temp_dir("towdb-cli");
  const auto in = dir / "stdin", out = dir / "stdout", err = dir / "stderr";
  { std::ofstream(in, std::ios::binary) << stdin_text; }
  const std::string cmd = "'" + towdb_exe().string() + "' " + args + " <'" + in.string() + "' >'" +
                          out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  std::filesystem::remove_all(dir);
  return r;
}

std::vector<std::vector<std::string>> read_csv_rows(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open test data file " + path.string());
  std::vector<std::vector<std::string>> rows;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    rows.push_back(std::move(cells));
  }
  return rows;
}

}  // namespace towdb::test
