// CLI tests for `towdb plan` (issue 18 item 2) on the bundled database.
// Test plan:
//   cli-plan-1  --json: each curve's points are the answers `towdb query --json` gives
//               at those points (same library: exact), the band is the answer's
//               uncertainty_kips, the fastest passing speed is `towdb max-speed`'s and
//               the shortest passing length `towdb min-length`'s
//   cli-plan-2  the polar curve is symmetric: heading h and 360 - h answer the same
//               (EQ-QUERY-6 folds headings), and it covers 0-360 deg every 5 deg
//   cli-plan-3  --out-dir writes three PNGs of the documented sizes
//   cli-plan-4  bad input exits 2 naming the flag, the value and what is allowed, and
//               writes nothing: speed 0, heading 400, a curve heading 400, an unknown
//               tug, a speed outside the stored data, no --out-dir
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace towdb::test {
namespace {

using nlohmann::json;

const std::string kQuestion =
    "--db db/towdb.sqlite --tug T-ATF --tow FFG7 --line fiber --wind-kt 30 --heading-deg 150 ";

json run_json(const std::string& args, int expected_exit = 0) {
  const CommandResult r = run_towdb(args);
  EXPECT_EQ(r.exit_code, expected_exit) << args << "\n" << r.err;
  return json::parse(r.out);
}

// PNG width and height from the IHDR chunk (bytes 16-23, big-endian).
std::pair<std::uint32_t, std::uint32_t> png_size(const std::filesystem::path& file) {
  std::ifstream f(file, std::ios::binary);
  unsigned char b[24] = {};
  f.read(reinterpret_cast<char*>(b), sizeof b);
  EXPECT_EQ(std::string(reinterpret_cast<char*>(b) + 1, 3), "PNG") << file;
  auto be = [&](int i) {
    return (std::uint32_t{b[i]} << 24) | (std::uint32_t{b[i + 1]} << 16) | (std::uint32_t{b[i + 2]} << 8) | b[i + 3];
  };
  return {be(16), be(20)};
}

class CliPlan : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    plan_ = new json(run_json("plan " + kQuestion + "--speed-kt 7 --length-ft 1200 --curve-headings-deg 0,150 --json"));
  }
  static void TearDownTestSuite() { delete plan_; }
  static json* plan_;
};
json* CliPlan::plan_ = nullptr;

TEST_F(CliPlan, CurvesAreTheLibrarysAnswers) {  // cli-plan-1
  const json& p = *plan_;
  ASSERT_EQ(p.at("tension_vs_speed").size(), 2u);
  const json& curve = p.at("tension_vs_speed")[1];
  EXPECT_EQ(curve.at("heading_deg").get<double>(), 150.0);
  ASSERT_GE(curve.at("points").size(), 41u);
  const json& pt = curve.at("points")[20];
  const std::string speed = nlohmann::json(pt.at("speed_kt").get<double>()).dump();
  const json q = run_json("query " + kQuestion + "--length-ft 1200 --json --speed-kt " + speed, pt.at("passed") ? 0 : 3);
  EXPECT_EQ(pt.at("extreme_tension_kips").get<double>(), q.at("extreme_tension_lbf").get<double>() / 1000.0);
  EXPECT_EQ(pt.at("uncertainty_kips").get<double>(), q.at("uncertainty_kips").get<double>());
  EXPECT_EQ(p.at("extreme_limit_kips").get<double>(), q.at("checks")[0].at("limit_lbf").get<double>() / 1000.0);

  const json s = run_json("max-speed " + kQuestion + "--length-ft 1200 --json");
  ASSERT_TRUE(s.at("found").get<bool>());
  EXPECT_EQ(curve.at("fastest_passing_speed_kt").get<double>(), s.at("max_speed_kt").get<double>());
  const json l = run_json("min-length " + kQuestion + "--speed-kt 7 --json");
  ASSERT_TRUE(l.at("found").get<bool>());
  EXPECT_EQ(p.at("tension_vs_length").at("shortest_passing_length_ft").get<double>(),
            l.at("min_length_ft").get<double>());
  // The chosen point's answer is `towdb query --json`'s.
  const json chosen = run_json("query " + kQuestion + "--speed-kt 7 --length-ft 1200 --json");
  EXPECT_EQ(p.at("answer").at("extreme_tension_lbf").get<double>(), chosen.at("extreme_tension_lbf").get<double>());
}

TEST_F(CliPlan, PolarCurveIsSymmetric) {  // cli-plan-2
  const json& pts = plan_->at("tension_vs_heading").at("points");
  ASSERT_EQ(pts.size(), 73u);  // 0, 5, ..., 360 (150 is one of them)
  EXPECT_EQ(pts.front().at("heading_deg").get<double>(), 0.0);
  EXPECT_EQ(pts.back().at("heading_deg").get<double>(), 360.0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(pts[i].at("extreme_tension_kips").get<double>(),
              pts[pts.size() - 1 - i].at("extreme_tension_kips").get<double>())
        << pts[i].at("heading_deg");
  }
}

TEST(CliPlanFiles, WritesThreePngs) {  // cli-plan-3
  const auto dir = make_temp_dir("towdb-cli-plan");
  const CommandResult r = run_towdb("plan " + kQuestion + "--speed-kt 7 --length-ft 1200 --out-dir '" +
                                    (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fastest passing speed"), std::string::npos) << r.out;
  EXPECT_EQ(png_size(dir / "out" / "tension-vs-speed.png"), std::make_pair(1000u, 650u));
  EXPECT_EQ(png_size(dir / "out" / "tension-vs-heading.png"), std::make_pair(800u, 800u));
  EXPECT_EQ(png_size(dir / "out" / "tension-vs-length.png"), std::make_pair(1000u, 650u));
  std::filesystem::remove_all(dir);
}

TEST(CliPlanFiles, BadInputExits2AndWritesNothing) {  // cli-plan-4
  const auto dir = make_temp_dir("towdb-cli-plan-bad");
  const std::string out = "--out-dir '" + (dir / "out").string() + "' ";
  const std::string base = "plan --db db/towdb.sqlite --tug T-ATF --tow FFG7 --line fiber --wind-kt 30 " + out;
  const struct {
    std::string args, needles[3];
  } cases[] = {
      {base + "--speed-kt 0 --heading-deg 150 --length-ft 1200", {"--speed-kt", "0", "(0, 100]"}},
      {base + "--speed-kt 7 --heading-deg 400 --length-ft 1200", {"--heading-deg", "400", "[0, 360]"}},
      {base + "--speed-kt 7 --heading-deg 150 --length-ft 1200 --curve-headings-deg 0,400",
       {"--curve-headings-deg", "400", "[0, 360]"}},
      {base + "--speed-kt 30 --heading-deg 150 --length-ft 1200", {"speed_kt", "30", "stored range [5, 9]"}},
      {"plan --db db/towdb.sqlite --tug Hercules --tow FFG7 --line fiber --wind-kt 30 " + out +
           "--speed-kt 7 --heading-deg 150 --length-ft 1200",
       {"tug", "Hercules", "known: "}},
      {"plan --db db/towdb.sqlite --tug T-ATF --tow FFG7 --line fiber --wind-kt 30 --speed-kt 7 --heading-deg 150 "
       "--length-ft 1200",
       {"--out-dir", "required", "--json"}},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_towdb(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    for (const auto& n : c.needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << " in " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << c.args;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace towdb::test
