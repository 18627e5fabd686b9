// CLI tests for `towdb refine` (cli/refine.hpp: nodes where the query's
// interpolation error estimate, EQ-QUERY-7, is largest), on a database built
// with the closed-form test runner (tests/support/sweep_test_runner.hpp),
// whose location u = 0.2 T (1 + U/40) (1 + |cos mu|) has a kink at beam seas.
// Test plan:
//   cli-refine-1  the cells are scored (every heading, length, wind and speed cell of every
//                 group); chosen cells exceed the threshold, are the highest-scoring ones,
//                 one axis per group, within --max-cases; the printed TOML parses as grids
//                 of the chosen midpoints times the group's stored values
//   cli-refine-2  --append adds exactly those grids to the sweep file; the next build
//                 computes exactly the planned cases; the refined group's grid is complete
//                 (a question at the new node is answered) and the new node's cell scores lower
//   cli-refine-3  bad input (threshold, budget, axis, --append with --toml, a sweep without
//                 the database's groups, a stored value the query library refuses): exit 2
//                 naming the field; the sweep file unchanged
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "store/database.hpp"
#include "sweep/sweep.hpp"
#include "sweep_test_runner.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// Headings every 45 deg around the kink at 90 deg, two lengths, two speeds, two winds.
const char* kRefineSweep = R"(format = "towdb-sweep-1"
description = "refine test sweep"

[defaults]
days = 30
base_seed = 11

[[grid]]
label = "base"
tugs = ["T-ATF 166"]
tows = ["FFG 7"]
speeds_kt = [5.0, 7.0]
winds_kt = [20.0, 30.0]
headings_deg = [0.0, 45.0, 90.0, 135.0, 180.0]
towlines = [ { line = "wire", length_ft = 1000.0 }, { line = "wire", length_ft = 2000.0 } ]
mean_tensions = [
  { label = "calculated-15%", basis = "calculated", factor = 0.85 },
  { label = "calculated+15%", basis = "calculated", factor = 1.15 },
]
)";

class CliRefine : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("towdb-cli-refine");
    sweep_ = dir_ / "refine.toml";
    db_ = dir_ / "refine.sqlite";
    { std::ofstream(sweep_) << kRefineSweep; }
    build();
  }
  void TearDown() override { fs::remove_all(dir_); }

  sweep::BuildSummary build() {
    const io::ShipCatalog catalog = io::ShipCatalog::load(source_dir() / "ships");
    const sweep::SweepFile file = sweep::load_sweep(sweep_);
    sweep::BuildOptions o;
    o.progress = false;
    return sweep::run_build(db_, file, sweep::expand_sweep(file, catalog).cases, catalog, make_test_runner(), o);
  }
  std::string args(const std::string& extra) const {
    return "refine --db '" + db_.string() + "' --sweep '" + sweep_.string() + "' " + extra;
  }

  fs::path dir_, sweep_, db_;
};

TEST_F(CliRefine, CellsAreScoredAndTheBestChosen) {  // cli-refine-1
  const CommandResult r = run_towdb(args("--threshold 0.02 --max-cases 40 --json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const json& cells = j.at("cells");
  // 4 heading cells, 1 length, 1 wind, 1 speed cell for the one group.
  ASSERT_EQ(cells.size(), 7u);
  double previous = 1e300;
  std::string axis;
  int cases = 0;
  bool skipped_above = false;
  for (const json& c : cells) {
    const double score = c.at("score").get<double>();
    EXPECT_LE(score, previous);  // highest first
    previous = score;
    EXPECT_GT(c.at("questions").get<int>(), 0);
    if (c.at("chosen").get<bool>()) {
      EXPECT_GT(score, 0.02);
      EXPECT_FALSE(skipped_above) << "a lower cell was chosen over a higher one that fitted";
      if (axis.empty()) axis = c.at("axis").get<std::string>();
      EXPECT_EQ(c.at("axis").get<std::string>(), axis);  // one axis per group
      cases += c.at("cases").get<int>();
    } else if (score > 0.02 && c.at("axis").get<std::string>() == axis &&
               cases + c.at("cases").get<int>() <= 40) {
      skipped_above = true;
    }
  }
  ASSERT_FALSE(axis.empty()) << r.out;
  EXPECT_EQ(axis, "heading");  // the kink at beam seas
  EXPECT_EQ(j.at("new_cases").get<int>(), cases);
  EXPECT_LE(cases, 40);
  // A heading node costs 2 speeds x 2 winds x 2 lengths x 2 factors = 16 cases.
  EXPECT_EQ(cases % 16, 0);
  const sweep::SweepFile grids = sweep::parse_sweep(
      "format = \"towdb-sweep-1\"\ndescription = \"x\"\n" + j.at("toml").get<std::string>(), "refine.toml");
  ASSERT_EQ(grids.grids.size(), 1u);
  const sweep::GridEntry& g = grids.grids.front();
  EXPECT_EQ(g.speeds_kt, (std::vector<double>{5.0, 7.0}));
  EXPECT_EQ(g.headings_deg.size(), static_cast<std::size_t>(cases / 16));
  for (double h : g.headings_deg) EXPECT_EQ(std::fmod(h, 45.0), 22.5) << h;
  EXPECT_EQ(g.days, 30);
  EXPECT_EQ(g.base_seed, 11);
  EXPECT_EQ(g.mean_tensions.size(), 2u);
}

TEST_F(CliRefine, AppendedNodesAreBuiltAndLowerTheEstimate) {  // cli-refine-2
  const CommandResult before = run_towdb(args("--threshold 0.02 --max-cases 16 --json"));
  ASSERT_EQ(before.exit_code, 0) << before.err;
  const json plan = json::parse(before.out);
  json chosen;
  for (const json& c : plan.at("cells")) {
    if (c.at("chosen").get<bool>()) chosen = c;
  }
  ASSERT_FALSE(chosen.is_null()) << before.out;
  const std::string original = read_text(sweep_);
  const CommandResult app = run_towdb(args("--threshold 0.02 --max-cases 16 --append"));
  ASSERT_EQ(app.exit_code, 0) << app.err;
  EXPECT_EQ(read_text(sweep_), original + plan.at("toml").get<std::string>());
  const sweep::BuildSummary s = build();
  EXPECT_EQ(s.done, 16);
  EXPECT_EQ(s.up_to_date, 80);
  // The new node is a node of a complete grid: asked there, the answer has no interpolation error
  // along heading, and the two half-cells score below the cell they split.
  const double node = chosen.at("new_node").get<double>();
  const CommandResult q = run_towdb("query --db '" + db_.string() + "' --tug T-ATF --tow FFG7 --line wire "
                                    "--speed-kt 6 --wind-kt 25 --length-ft 1500 --json --heading-deg " +
                                    std::to_string(node));
  EXPECT_EQ(q.exit_code, 0) << q.err;
  const CommandResult after = run_towdb(args("--threshold 0.02 --max-cases 16 --json"));
  ASSERT_EQ(after.exit_code, 0) << after.err;
  int halves = 0;
  const json rescored = json::parse(after.out);
  for (const json& c : rescored.at("cells")) {
    if (c.at("axis").get<std::string>() != "heading") continue;
    if (c.at("low").get<double>() == node || c.at("high").get<double>() == node) {
      ++halves;
      EXPECT_LT(c.at("score").get<double>(), chosen.at("score").get<double>()) << c.dump();
    }
  }
  EXPECT_EQ(halves, 2) << after.out;
}

TEST_F(CliRefine, BadInputExitsTwoAndLeavesTheSweepAlone) {  // cli-refine-3
  const std::string original = read_text(sweep_);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"--threshold 0", "--threshold"},
      {"--threshold 1.5", "--threshold"},
      {"--max-cases 0", "--max-cases"},
      {"--axes heading,depth --append", "\"depth\" is not an axis"},
      {"--axes heading,heading --append", "axes names an axis twice"},
      {"--append --toml", "--append and --toml"},
  };
  for (const auto& [flags, needle] : bad) {
    const CommandResult r = run_towdb(args(flags));
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_NE(r.err.find(needle), std::string::npos) << flags << ": " << r.err;
    EXPECT_EQ(read_text(sweep_), original) << flags;
  }
  // A sweep that holds none of the database's groups.
  const fs::path other = dir_ / "other.toml";
  std::string text = kRefineSweep;
  text.replace(text.find("\"FFG 7\""), 7, "\"YRBM\"");
  { std::ofstream(other) << text; }
  const CommandResult r = run_towdb("refine --db '" + db_.string() + "' --sweep '" + other.string() + "' --append");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no group of"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(other), text);
  // A stored value the query library refuses on open (a negative Gumbel scale).
  {
    auto db = store::Database::open(db_, store::Database::Mode::kReadWrite);
    db.exec(
        "PRAGMA ignore_check_constraints = ON; UPDATE results SET gumbel_alpha_per_kip = -0.2 "
        "WHERE case_id = (SELECT MIN(case_id) FROM results)");
  }
  const CommandResult lying = run_towdb(args("--append"));
  EXPECT_EQ(lying.exit_code, 2) << lying.err;
  EXPECT_NE(lying.err.find("--db = "), std::string::npos) << lying.err;
  EXPECT_NE(lying.err.find("gumbel_alpha_per_kip = -0.2"), std::string::npos) << lying.err;
  EXPECT_EQ(read_text(sweep_), original);
}

}  // namespace
}  // namespace towdb::test
