// Tests of the strict ship/towline file parser (generator/io): the bundled
// files load, and bad input of every kind gets its specific message.
// Test plan:
//   io-1  a valid vessel file parses; SI conversion of every kind of unit
//   io-2  names normalise (case, spaces, hyphens)
//   io-3.x bad input: each mutation of the valid file gives its own message
//   io-4  towline component files: valid and invalid
//   io-5  the bundled ships/ directory: every file loads, tugs find their lines
//   io-6  same_toml_content: comments, layout and key order aside; values, types and bad TOML count
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "test_support.hpp"

namespace towdb::io {
namespace {

std::string barge_text() { return test::read_text(test::source_dir() / "tests/data/io/box-barge.toml"); }

// Replaces the first occurrence of `from` by `to`; fails the test when absent.
std::string mutate(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << "fixture does not contain: " << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

// Expects parse_vessel to throw InputError whose message matches `pattern`.
void expect_vessel_error(const std::string& text, const std::string& pattern) {
  try {
    parse_vessel(text, "barge.toml");
    ADD_FAILURE() << "no error; expected /" << pattern << "/";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << "message: " << e.what()
                                                                   << "\nexpected /" << pattern << "/";
  }
}

// A unit conversion through ft is exact to rounding: 1e-12 relative.
constexpr double kConversionRelTol = 1e-12;

TEST(ShipFile, ValidVesselParsesIntoSi) {  // io-1
  const VesselFile vf = parse_vessel(barge_text(), "barge.toml");
  const model::Vessel& v = vf.vessel;
  EXPECT_EQ(v.name, "Test Barge");
  EXPECT_EQ(v.role, model::VesselRole::kTow);
  EXPECT_REL_CLOSE(v.hull.beam_m, 40.0 * 0.3048, kConversionRelTol);
  EXPECT_REL_CLOSE(v.hull.displacement_kg, 571.43 * 2240.0 * 0.45359237, kConversionRelTol);
  EXPECT_REL_CLOSE(v.hull.wetted_surface_m2, 5000.0 * 0.3048 * 0.3048, kConversionRelTol);
  EXPECT_REL_CLOSE(v.drag.speed_m_s[1], 6.0 * 1852.0 / 3600.0, kConversionRelTol);
  EXPECT_EQ(v.hull.stations.size(), 5u);
  EXPECT_FALSE(v.propellers.has_value());
  // Box: C_b = 571.43 LT * 35 ft^3/LT / (100 * 40 * 5) = 0.99998 (35.0 ft^3/LT is 64.0 lb/ft^3).
  EXPECT_ABS_CLOSE(v.hull.block_coefficient(), 1.0, 0.002);
  EXPECT_EQ(v.content_sha256.size(), 64u);
  // Every sourced scalar is recorded with its provenance (16 hull + 2 tow point) plus 2 tables.
  EXPECT_EQ(vf.provenance.size(), 20u);
}

TEST(ShipFile, NamesNormalise) {  // io-2
  EXPECT_EQ(normalize_name("T-ATF 166"), "tatf166");
  EXPECT_EQ(normalize_name("ffg-7"), normalize_name("FFG7"));
  EXPECT_EQ(normalize_name("ARS 50"), normalize_name("ars50"));
}

TEST(ShipFile, Sha256OfKnownString) {
  // FIPS 180-2 example: SHA-256("abc").
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

// io-3.x: one test per kind of bad input, each asserting its own message.
TEST(ShipFileBadInput, MissingKey) {
  expect_vessel_error(mutate(barge_text(), "gm_ft = { value = 20.0, status = \"E\", source = \"test\" }\n", ""),
                      R"(\[hull\]: missing key 'gm_ft')");
}
TEST(ShipFileBadInput, UnknownKey) {
  expect_vessel_error(mutate(barge_text(), "[tow_point]\n", "[tow_point]\ncolour = \"red\"\n"),
                      R"(barge.toml:\d+: tow_point.colour: unknown key)");
}
TEST(ShipFileBadInput, WrongUnitSuffix) {
  expect_vessel_error(mutate(barge_text(), "beam_ft = { value = 40.0", "beam_m = { value = 40.0"),
                      R"(hull.beam_m: wrong unit suffix; expected 'beam_ft')");
}
TEST(ShipFileBadInput, NegativeValue) {
  expect_vessel_error(mutate(barge_text(), "draft_ft = { value = 5.0", "draft_ft = { value = -5.0"),
                      R"(hull.draft_ft: value = -5: must be a finite number between 0.5 and 60)");
}
TEST(ShipFileBadInput, NaNValue) {
  expect_vessel_error(mutate(barge_text(), "kg_ft = { value = 8.0", "kg_ft = { value = nan"),
                      R"(hull.kg_ft: value = nan: must be a finite number)");
}
TEST(ShipFileBadInput, OutOfRange) {
  expect_vessel_error(mutate(barge_text(), "beam_ft = { value = 40.0", "beam_ft = { value = 400.0"),
                      R"(hull.beam_ft: value = 400: must be a finite number between 5 and 200)");
}
TEST(ShipFileBadInput, MalformedToml) {
  expect_vessel_error(mutate(barge_text(), "[hull]\n", "[hull\n"), R"(barge.toml:\d+:\d+: malformed TOML)");
}
TEST(ShipFileBadInput, EmptyFile) { expect_vessel_error("  \n\n", R"(barge.toml: the file is empty)"); }
TEST(ShipFileBadInput, WrongFormatTag) {
  expect_vessel_error(mutate(barge_text(), "towdb-vessel-1", "towdb-vessel-9"),
                      R"(format: "towdb-vessel-9" is not allowed; expected one of "towdb-vessel-1")");
}
TEST(ShipFileBadInput, BareNumberWithoutProvenance) {
  expect_vessel_error(mutate(barge_text(), "kg_ft = { value = 8.0, status = \"E\", source = \"test\" }", "kg_ft = 8.0"),
                      R"(hull.kg_ft: is a number, expected \{ value = \.\.\., status)");
}
TEST(ShipFileBadInput, BadStatusCode) {
  expect_vessel_error(mutate(barge_text(), "kg_ft = { value = 8.0, status = \"E\"", "kg_ft = { value = 8.0, status = \"X\""),
                      R"(hull.kg_ft.status: "X" is not allowed)");
}
TEST(ShipFileBadInput, EmptySource) {
  expect_vessel_error(mutate(barge_text(), "kg_ft = { value = 8.0, status = \"E\", source = \"test\" }",
                             "kg_ft = { value = 8.0, status = \"E\", source = \" \" }"),
                      R"(hull.kg_ft: source is empty)");
}
TEST(ShipFileBadInput, StringWhereNumberExpected) {
  expect_vessel_error(mutate(barge_text(), "gm_ft = { value = 20.0", "gm_ft = { value = \"twenty\""),
                      R"(hull.gm_ft: value is a string, expected a number)");
}
TEST(ShipFileBadInput, BadRole) {
  expect_vessel_error(mutate(barge_text(), "role = \"tow\"", "role = \"barge\""),
                      R"(vessel.role: "barge" is not allowed; expected one of "tow", "tug")");
}
TEST(ShipFileBadInput, BlockCoefficientDisagreesWithDisplacement) {
  expect_vessel_error(mutate(barge_text(), "block_coefficient = { value = 1.0", "block_coefficient = { value = 0.9"),
                      R"(hull.block_coefficient = 0.9 disagrees with displacement / \(rho L B T\) = 0.99)");
}
TEST(ShipFileBadInput, StationArraysOfDifferentLength) {
  expect_vessel_error(mutate(barge_text(), "draft_ft = [5.0, 5.0, 5.0, 5.0, 5.0]", "draft_ft = [5.0, 5.0, 5.0, 5.0]"),
                      R"(must have the same length \(5, 5, 4, 5\))");
}
TEST(ShipFileBadInput, StationVolumeDisagrees) {
  expect_vessel_error(
      mutate(barge_text(), "area_coefficient = [1.0, 1.0, 1.0, 1.0, 1.0]", "area_coefficient = [0.8, 0.8, 0.8, 0.8, 0.8]"),
      R"(hull.stations: volume integral .* differs from the displacement volume)");
}
TEST(ShipFileBadInput, StationsOutOfOrder) {
  expect_vessel_error(mutate(barge_text(), "x_ft = [-50.0, -25.0, 0.0, 25.0, 50.0]", "x_ft = [-50.0, 0.0, -25.0, 25.0, 50.0]"),
                      R"(station 3 x = .*: stations must be ordered aft to forward)");
}
TEST(ShipFileBadInput, DragSpeedsNotIncreasing) {
  expect_vessel_error(mutate(barge_text(), "speed_kt = [2.0, 6.0, 10.0]", "speed_kt = [2.0, 10.0, 6.0]"),
                      R"(barge.toml:\d+: drag.speed_kt: speed_kt\[2\] = 6: the speeds must increase)");
}
TEST(ShipFileBadInput, TowlinesOnATow) {
  expect_vessel_error(barge_text() + "\n[towlines]\nwire_hawser = \"a\"\nfiber_hawser = \"b\"\npendant = \"c\"\n",
                      R"(\[towlines\] is only allowed for role = "tug")");
}
TEST(ShipFileBadInput, TugWithoutPropellers) {
  expect_vessel_error(mutate(mutate(barge_text(), "role = \"tow\"", "role = \"tug\""), "x_ft = { value = 50.0",
                             "x_ft = { value = -50.0") +
                          "\n[towlines]\nwire_hawser = \"a\"\nfiber_hawser = \"b\"\npendant = \"c\"\n",
                      R"(a tug needs a \[propellers\] table)");
}
TEST(ShipFileBadInput, TowPointOnTheWrongSide) {  // docs/ship-files.md: tug aft (< 0), tow bow (> 0)
  expect_vessel_error(mutate(barge_text(), "x_ft = { value = 50.0", "x_ft = { value = -50.0"),
                      R"(barge.toml:\d+: tow_point.x_ft: x_ft = -50: a tow's towing fitting is forward of midships)");
  expect_vessel_error(mutate(barge_text(), "role = \"tow\"", "role = \"tug\""),
                      R"(tow_point.x_ft: x_ft = 50: a tug's tow point is aft of midships)");
}
TEST(ShipFileBadInput, MissingFile) {
  EXPECT_THROW(load_vessel("/nonexistent/ship.toml"), InputError);
  try {
    load_vessel("/nonexistent/ship.toml");
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).find("/nonexistent/ship.toml: cannot open the file") != std::string::npos);
  }
}

const char* kWire = R"(format = "towdb-towline-1"
[component]
name = "Test wire"
kind = "wire"
[properties]
ea_lbf = { value = 2.07e7, status = "F", source = "thesis" }
hydrodynamic_diameter_ft = { value = 0.188, status = "F", source = "thesis" }
weight_in_air_lb_per_ft = { value = 7.76, status = "D", source = "test" }
weight_in_water_lb_per_ft = { value = 6.744, status = "F", source = "thesis" }
breaking_strength_lbf = { value = 360000, status = "S", source = "Navy" }
drag_coefficient_normal = { value = 1.2, status = "E", source = "cylinder" }
added_mass_coefficient = { value = 1.0, status = "E", source = "cylinder" }
)";

TEST(TowlineFile, ValidComponentParses) {  // io-4
  const TowlineFile tf = parse_towline_component(kWire, "wire.toml");
  EXPECT_EQ(tf.component.kind, model::LineKind::kWire);
  EXPECT_REL_CLOSE(tf.component.ea_n, 2.07e7 * kNewtonsPerPoundForce, kConversionRelTol);
  EXPECT_REL_CLOSE(tf.component.weight_in_water_n_m, 6.744 * kNewtonsPerPoundForce / kMetersPerFoot, kConversionRelTol);
  EXPECT_EQ(tf.component.fixed_length_m, 0.0);
}

TEST(TowlineFile, WaterWeightAboveAirWeightIsRejected) {
  std::string text = kWire;
  text = mutate(text, "weight_in_air_lb_per_ft = { value = 7.76", "weight_in_air_lb_per_ft = { value = 5.0");
  try {
    parse_towline_component(text, "wire.toml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).find("must not exceed weight_in_air_lb_per_ft = 5") != std::string::npos)
        << e.what();
  }
}

// io-5: the bundled ship files.
TEST(BundledShips, EveryFileLoadsAndTugsFindTheirLines) {
  const ShipCatalog cat = ShipCatalog::load(test::source_dir() / "ships");
  EXPECT_EQ(cat.vessels().size(), 7u);
  EXPECT_EQ(cat.components().size(), 4u);
  for (const char* name : {"T-ATF", "tatf", "ARS50", "FFG7", "ffg-7", "LHA-1", "AE 26", "CG47", "yrbm"}) {
    EXPECT_NO_THROW(cat.vessel(name)) << name;
  }
  for (const char* tug : {"T-ATF 166", "ARS 50"}) {
    const model::Vessel& v = cat.vessel(tug).vessel;
    ASSERT_EQ(v.role, model::VesselRole::kTug) << tug;
    for (model::LineKind kind : {model::LineKind::kWire, model::LineKind::kFiber}) {
      const model::Towline t = cat.towline(v, kind, units::ft_to_m(1500.0));
      ASSERT_EQ(t.segments.size(), 2u);
      EXPECT_EQ(t.segments[0].component.kind, kind);
      EXPECT_EQ(t.segments[1].component.kind, model::LineKind::kChain);
      // The pendant is the thesis's 90 ft shot of chain (Appendix A, t-atf.win).
      EXPECT_REL_CLOSE(units::m_to_ft(t.segments[1].length_m), 90.0, kConversionRelTol);
    }
  }
}

TEST(BundledShips, UnknownVesselNamesTheKnownOnes) {
  const ShipCatalog cat = ShipCatalog::load(test::source_dir() / "ships");
  try {
    cat.vessel("Titanic");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex("vessel 'Titanic' is not known; known: .*T-ATF 166")))
        << e.what();
  }
}

TEST(BundledShips, DuplicateVesselIsRejected) {
  const auto dir = test::make_temp_dir("towdb-dup");
  std::filesystem::copy_file(test::source_dir() / "tests/data/io/box-barge.toml", dir / "a.toml");
  std::filesystem::copy_file(test::source_dir() / "tests/data/io/box-barge.toml", dir / "b.toml");
  try {
    ShipCatalog::load(dir);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex("b.toml: vessel name or alias 'Test Barge' is already used by "
                                                       ".*a.toml \\(duplicate vessel\\)")))
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(SameTomlContent, IgnoresCommentsLayoutAndKeyOrderOnly) {  // io-6
  const std::string a = "# header\nformat = \"x\"\n[hull]\nbeam_ft = 42.0\nname = \"A\"  # trailing\n";
  EXPECT_TRUE(same_toml_content(a, a));
  EXPECT_TRUE(same_toml_content(a, "format=\"x\"\n\n[hull]\n  name = \"A\"\n  beam_ft = 42.0\n"));
  EXPECT_FALSE(same_toml_content(a, "format = \"x\"\n[hull]\nbeam_ft = 42.5\nname = \"A\"\n"));  // a value
  EXPECT_FALSE(same_toml_content(a, "format = \"x\"\n[hull]\nbeam_ft = 42\nname = \"A\"\n"));    // a type
  EXPECT_FALSE(same_toml_content(a, "format = \"x\"\n[hull]\nbeam_ft = 42.0\n"));                  // a key
  EXPECT_FALSE(same_toml_content(a, "format = \"x\"\n[hull\n"));                                      // not TOML
}

}  // namespace
}  // namespace towdb::io
