// Runs the C checks of c_api_test.c (compiled as C) on a database written here.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "synthetic_db.hpp"
#include "test_support.hpp"

extern "C" int towdb_c_api_checks(const char* good_path, const char* missing_path, double expected_999_kips,
                                  char* log, std::size_t size);

namespace towdb::test {
namespace {

TEST(QueryCApi, EveryEntryPointReturnsACodeAndAMessage) {
  const auto dir = make_temp_dir("towdb-capi");
  // Two speeds (5 and 7 kt), two lengths: the C checks query the 5 kt / 2000 ft node.
  std::vector<SyntheticCase> cases;
  for (double s : {5.0, 7.0}) {
    for (double l : {1000.0, 2000.0}) {
      SyntheticCase c;
      c.speed_kt = s;
      c.length_ft = l;
      c.u_kips = 30.0 + 2.0 * s - 0.01 * l;
      cases.push_back(c);
    }
  }
  write_synthetic_db(dir / "good.towdb", cases);
  const double expected = 30.0 + 10.0 - 20.0 + reduced_variate_999() / cases[0].alpha_per_kip;
  std::vector<char> log(16384, '\0');
  const int failures = towdb_c_api_checks((dir / "good.towdb").c_str(), (dir / "missing.towdb").c_str(), expected,
                                          log.data(), log.size());
  EXPECT_EQ(failures, 0) << log.data();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace towdb::test
