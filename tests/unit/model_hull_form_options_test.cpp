// Options and particulars validation of the station-table generator
// (generator/model/hull_form.hpp), and its edge cases.
// Test plan:
//   hfu-1  every invalid particular or option throws InputError naming the field
//   hfu-2  unreachable inputs (LCB, fullness for the station count) throw InputError
//          with the reachable range or the remedy
//   hfu-3  deterministic: the same inputs give bit-identical tables
#include <cmath>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "model/hull_form.hpp"
#include "test_support.hpp"

namespace towdb::model {
namespace {

HullFormParticulars valid() {
  HullFormParticulars p;
  p.length_pp_m = 120.0;
  p.beam_m = 14.0;
  p.draft_m = 4.5;
  p.block_coefficient = 0.55;
  p.midship_coefficient = 0.85;
  p.lcb_m = -2.0;
  return p;
}

template <typename F>
void expect_input_error(F&& f, const std::string& pattern) {
  try {
    f();
    ADD_FAILURE() << "no error; expected /" << pattern << "/";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << "message: " << e.what()
                                                                   << "\nexpected /" << pattern << "/";
  }
}

// hfu-1
TEST(HullFormValidation, EachParticularIsChecked) {
  EXPECT_NO_THROW(valid().validate());
  struct Case {
    void (*mutate)(HullFormParticulars&);
    const char* pattern;
  };
  const Case cases[] = {
      {[](HullFormParticulars& p) { p.length_pp_m = 0.0; }, "length_pp_m = 0: must be a finite number > 0"},
      {[](HullFormParticulars& p) { p.beam_m = -1.0; }, "beam_m = -1: must be a finite number > 0"},
      {[](HullFormParticulars& p) { p.draft_m = std::nan(""); }, "draft_m = nan"},
      {[](HullFormParticulars& p) { p.block_coefficient = 1.2; }, R"(block_coefficient = 1.2: must be in \(0, 1\])"},
      {[](HullFormParticulars& p) { p.midship_coefficient = 0.5; },
       R"(midship_coefficient = 0.5: must be in \[block_coefficient, 1\])"},
      {[](HullFormParticulars& p) { p.lcb_m = 40.0; }, R"(lcb_m = 40: must satisfy \|lcb_m\| < length_pp_m / 4 = 30)"},
      {[](HullFormParticulars& p) { p.waterplane_coefficient = 0.6; },
       R"(waterplane_coefficient = 0.6: must be 0 \(estimate\) or in \[C_p, 1\])"},
      {[](HullFormParticulars& p) { p.waterplane_coefficient = 1.0; },
       "waterplane_coefficient = 1: may be 1 only for a prism"},
      {[](HullFormParticulars& p) {
         p.block_coefficient = 0.9;
         p.midship_coefficient = 0.9;
       },
       "lcb_m = -2: must be 0 when block_coefficient = midship_coefficient"},
  };
  for (const Case& c : cases) {
    HullFormParticulars p = valid();
    c.mutate(p);
    expect_input_error([&] { p.validate(); }, c.pattern);
    expect_input_error([&] { generate_hull_form(p); }, c.pattern);  // generate validates first
  }
}

TEST(HullFormValidation, EachOptionIsChecked) {
  EXPECT_NO_THROW(HullFormOptions{}.validate());
  HullFormOptions o;
  o.station_count = 4;
  expect_input_error([&] { o.validate(); }, "station_count = 4: must be an integer from 5 to 1001");
  o = HullFormOptions{};
  o.relative_tolerance = 0.1;
  expect_input_error([&] { o.validate(); }, "relative_tolerance = 0.1: must be between 1e-15 and 0.001");
  o = HullFormOptions{};
  o.max_iterations = 3;
  expect_input_error([&] { o.validate(); }, "max_iterations = 3: must be an integer from 10 to 10000");
  expect_input_error([&] { generate_hull_form(valid(), o); }, "max_iterations = 3");
}

// hfu-2
TEST(HullFormValidation, UnreachableLcbNamesTheReachableRange) {
  // C_p = 0.647: even n_a -> 0 cannot move the centroid 24 % of L forward.
  HullFormParticulars p = valid();
  p.lcb_m = 29.0;
  expect_input_error([&] { generate_hull_form(p); },
                     R"(lcb_m = 29: with prismatic coefficient .* can place the LCB only between -?[0-9.]+ and [0-9.]+ m)");
}

TEST(HullFormValidation, TooFullForTheStationCountAsksForMoreStations) {
  // Pointed ends: each half of a 5-station table holds at most 1 - 1/4 = 0.75.
  HullFormParticulars p = valid();
  p.block_coefficient = 0.8;
  p.midship_coefficient = 0.98;  // C_p = 0.816
  p.lcb_m = 0.0;
  HullFormOptions o;
  o.station_count = 5;
  expect_input_error([&] { generate_hull_form(p, o); }, "cannot reach it on 5 stations.*use more stations");
  o.station_count = 21;  // 0.95 per half: now reachable
  EXPECT_NO_THROW(generate_hull_form(p, o));
  p.waterplane_coefficient = 0.99;  // a waterline half of 0.99 > 0.95
  expect_input_error([&] { generate_hull_form(p, o); }, "waterplane_coefficient = 0.99: too full for pointed ends");
}

// hfu-3
TEST(HullFormValidation, SameInputsGiveBitIdenticalTables) {
  const HullForm a = generate_hull_form(valid());
  const HullForm b = generate_hull_form(valid());
  ASSERT_EQ(a.stations.size(), b.stations.size());
  for (std::size_t i = 0; i < a.stations.size(); ++i) {
    EXPECT_EQ(a.stations[i].x_m, b.stations[i].x_m);
    EXPECT_EQ(a.stations[i].beam_m, b.stations[i].beam_m);
    EXPECT_EQ(a.stations[i].draft_m, b.stations[i].draft_m);
    EXPECT_EQ(a.stations[i].area_coefficient, b.stations[i].area_coefficient);
  }
}

}  // namespace
}  // namespace towdb::model
