// CLI tests for `towdb ships` and the exit-code contract (0 ok, 2 bad input).
// Test plan:
//   cli-ships-1  ships list --json: seven vessels and four towline components
//   cli-ships-2  ships show accepts every spelling of a name
//   cli-ships-3  unknown vessel, unknown option, missing subcommand -> 2 with a named message
//   cli-ships-4  a bad ship file in --ships-dir -> 2, message names file, line and key
//   cli-ships-5  --help and --version -> 0
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace towdb::test {
namespace {

TEST(CliShips, ListJsonHasEveryVesselAndComponent) {  // cli-ships-1
  const CommandResult r = run_towdb("ships list --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::set<std::string> names;
  for (const auto& v : j.at("vessels")) names.insert(v.at("name").get<std::string>());
  EXPECT_EQ(names, (std::set<std::string>{"T-ATF 166", "ARS 50", "LHA 1", "AE 26", "CG 47", "FFG 7", "YRBM"}));
  EXPECT_EQ(j.at("towline_components").size(), 4u);
  for (const auto& v : j.at("vessels")) {
    EXPECT_GT(v.at("displacement_lt").get<double>(), 0.0);
    EXPECT_EQ(v.at("sha256").get<std::string>().size(), 64u);
  }
}

TEST(CliShips, ShowAcceptsEverySpelling) {  // cli-ships-2
  for (const char* name : {"T-ATF", "tatf", "ARS50", "FFG7", "ffg-7", "\"LHA 1\""}) {
    const CommandResult r = run_towdb(std::string("ships show ") + name + " --json");
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_FALSE(j.at("particulars").empty()) << name;
    EXPECT_GE(j.at("stations").size(), 5u) << name;
  }
  const CommandResult text = run_towdb("ships show ffg7");
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("hull.beam_ft"), std::string::npos);
}

TEST(CliShips, BadInputExitsTwoWithANamedMessage) {  // cli-ships-3
  const CommandResult unknown = run_towdb("ships show Titanic");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("vessel 'Titanic' is not known; known: "), std::string::npos) << unknown.err;
  EXPECT_TRUE(unknown.out.empty());

  const CommandResult option = run_towdb("ships list --colour");
  EXPECT_EQ(option.exit_code, 2);
  EXPECT_NE(option.err.find("--colour"), std::string::npos) << option.err;

  const CommandResult none = run_towdb("");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("subcommand"), std::string::npos) << none.err;

  const CommandResult missing_dir = run_towdb("--ships-dir /nonexistent ships list");
  EXPECT_EQ(missing_dir.exit_code, 2);
  EXPECT_NE(missing_dir.err.find("ships directory '/nonexistent' does not exist"), std::string::npos);

  const std::string readme = (source_dir() / "README.md").string();
  const CommandResult file_dir = run_towdb("--ships-dir '" + readme + "' ships list");
  EXPECT_EQ(file_dir.exit_code, 2);
  EXPECT_NE(file_dir.err.find("is not a directory"), std::string::npos) << file_dir.err;

  const CommandResult word = run_towdb("colour");
  EXPECT_EQ(word.exit_code, 2);
  EXPECT_NE(word.err.find("unknown command 'colour'; the commands are: ships, build"), std::string::npos) << word.err;

  const CommandResult db_dir = run_towdb("status --db '" + source_dir().string() + "'");
  EXPECT_EQ(db_dir.exit_code, 2);
  EXPECT_NE(db_dir.err.find("is a directory, expected a towdb database file"), std::string::npos) << db_dir.err;
}

TEST(CliShips, BadShipFileNamesFileLineAndKey) {  // cli-ships-4
  const auto dir = make_temp_dir("towdb-cli-ships");
  std::ifstream in(source_dir() / "tests/data/io/box-barge.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "gm_ft = { value = 20.0";
  text.replace(text.find(from), from.size(), "gm_ft = { value = -3.0");
  { std::ofstream(dir / "barge.toml") << text; }
  const CommandResult r = run_towdb("--ships-dir '" + dir.string() + "' ships list");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("barge.toml:20: hull.gm_ft: value = -3: must be a finite number between 0.1 and 100"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty());
  std::filesystem::remove_all(dir);
}

TEST(CliShips, HelpAndVersionExitZero) {  // cli-ships-5
  const CommandResult help = run_towdb("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("ships"), std::string::npos);
  const CommandResult version = run_towdb("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("towdb "), std::string::npos);
  EXPECT_NE(version.out.find("numerics fingerprint "), std::string::npos) << version.out;
}

}  // namespace
}  // namespace towdb::test
