// CLI tests for `towdb simulate` (issue "Long-time towing simulation", item 6).
// Test plan:
//   cli-simulate-1  --json has the documented keys, and they agree: the extreme
//                   tension is the mean plus the F = 0.999 dynamic tension, which
//                   is the Type I quantile of the fitted u and alpha (thesis eq.
//                   4.5-4.6) inside its confidence interval; 1 and 2 threads give
//                   the same digits; the line's extension lies around its mean
//                   and is flagged where it left the polynomial's fitted range
//   cli-simulate-2  bad input -> exit 2 with a message naming the flag, before
//                   any computation, and no plot file written
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace towdb::test {
namespace {

using nlohmann::json;

const std::string kCase =
    "simulate --tug T-ATF --tow FFG7 --speed-kt 9 --heading-deg 0 --line wire --length-ft 2000 "
    "--mean-tension-lbf 50000 ";

TEST(CliSimulate, JsonKeysAgreeWithEachOther) {  // cli-simulate-1
  const CommandResult one = run_towdb(kCase + "--wind-kt 20 --days 4 --threads 1 --json");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const json j = json::parse(one.out);
  for (const char* key : {"dynamic_tension_kips", "extreme_tension_lbf", "gumbel_u_kips", "gumbel_alpha_per_kip",
                          "daily_max_mean_kips", "daily_max_variance_kips2", "ci_low_kips", "ci_high_kips", "days",
                          "seed", "slack_fraction", "runtime_s"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j.at("days").get<int>(), 4);
  EXPECT_EQ(j.at("seed").get<int>(), 1);
  const double dyn = j.at("dynamic_tension_kips").get<double>();
  constexpr double kRoundOffRelTol = 1e-12;
  EXPECT_REL_CLOSE(j.at("extreme_tension_lbf").get<double>(), 50000.0 + 1000.0 * dyn, kRoundOffRelTol);
  const double u = j.at("gumbel_u_kips").get<double>(), alpha = j.at("gumbel_alpha_per_kip").get<double>();
  EXPECT_REL_CLOSE(dyn, u - std::log(-std::log(0.999)) / alpha, kRoundOffRelTol);
  // The line's extension against the polynomial's fitted range (ft).
  const json& e = j.at("extension_ft");
  EXPECT_LT(e.at("fit_min").get<double>(), 0.0);
  EXPECT_GT(e.at("fit_max").get<double>(), 0.0);
  EXPECT_LT(e.at("min").get<double>(), e.at("mean").get<double>());
  EXPECT_GT(e.at("max").get<double>(), e.at("mean").get<double>());
  EXPECT_GT(e.at("sd").get<double>(), 0.0);
  const bool left = e.at("min").get<double>() < e.at("fit_min").get<double>() ||
                    e.at("max").get<double>() > e.at("fit_max").get<double>();
  EXPECT_EQ(e.at("days_outside_fit").get<int>() > 0, left);
  EXPECT_LE(j.at("ci_low_kips").get<double>(), dyn);
  EXPECT_GE(j.at("ci_high_kips").get<double>(), dyn);
  const CommandResult two = run_towdb(kCase + "--wind-kt 20 --days 4 --threads 2 --json");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(json::parse(two.out).at("dynamic_tension_kips").get<double>(), dyn);  // bit-identical
}

TEST(CliSimulate, BadInputExitsTwoBeforeAnyWork) {  // cli-simulate-2
  const auto dir = make_temp_dir("towdb-cli-simulate");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--wind-kt nan", "--wind-kt: 'nan' is not a finite number"},
      {"--wind-kt 20 --hs-ft 10 --tp-s 8", "--wind-kt 20 with --hs-ft/--tp-s: give one sea"},
      {"--hs-ft 10", "--hs-ft and --tp-s must be given together"},
      {"--wind-kt 20 --gamma 3", "--gamma 3: only a JONSWAP sea"},
      {"--wind-kt 20 --spectrum jonswap", "--spectrum jonswap: needs --hs-ft and --tp-s"},
      {"--wind-kt 20 --swell-tp-s 10", "need --swell-hs-ft"},
      {"--wind-kt 20 --swell-hs-ft nan --swell-tp-s 10", "--swell-hs-ft: 'nan' is not a finite number"},
      {"--wind-kt 20 --seed -1", "--seed: '-1' is not a whole number"},
      {"--wind-kt 20 --days 2", "--days"},
      {"--wind-kt 20 --plot '" + (dir / "no" / "plot.png").string() + "'", "the directory"},
      {"--wind-kt 20 --plot '" + dir.string() + "'", "is a directory, expected a file name"},
  };
  for (const auto& [flags, message] : cases) {
    const CommandResult r = run_towdb(kCase + flags);
    EXPECT_EQ(r.exit_code, 2) << flags << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << flags << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << flags;
  }
  const CommandResult tow_is_tug = run_towdb(
      "simulate --tug T-ATF --tow ARS50 --speed-kt 9 --heading-deg 0 --line wire --length-ft 2000 "
      "--mean-tension-lbf 50000 --wind-kt 20");
  EXPECT_EQ(tow_is_tug.exit_code, 2);
  EXPECT_NE(tow_is_tug.err.find("is not a tow"), std::string::npos) << tow_is_tug.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace towdb::test
