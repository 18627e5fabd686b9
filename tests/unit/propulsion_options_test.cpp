// Options validation and edge cases of towdb::propulsion: every bad input
// throws InputError naming the field; the thrust-capacity and low-pitch
// branches of the thesis 3.6 procedure behave as documented.
#include <string>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/units.hpp"
#include "propulsion/propulsion.hpp"
#include "propulsion_vessels.hpp"
#include "test_support.hpp"

namespace towdb::propulsion {
namespace {

using test::expect_input_error;

TEST(PropulsionOptions, DefaultsAreValidAndFollowTheThesis) {
  EXPECT_NO_THROW(HullDampingOptions{}.validate());
  EXPECT_NO_THROW(TugPropellerDampingOptions{}.validate());
  EXPECT_NO_THROW(TowPropellerOptions{}.validate());
  EXPECT_NO_THROW(MeanTensionOptions{}.validate());
  const TugPropellerDampingOptions t;
  EXPECT_EQ(t.rpm_fraction, 0.8);                                // thesis 3.6 step 1
  EXPECT_EQ(t.share, PropellerDampingShare::kOnePropeller);      // thesis: one propeller
  EXPECT_EQ(t.speed_step_m_s, units::ft_s_to_m_s(1.0));          // thesis step 8
  const MeanTensionOptions m;
  EXPECT_EQ(m.hull_margin, 0.10);           // thesis ch. 2
  EXPECT_EQ(m.towline_drag_fraction, 0.10);  // Towing Manual
}

TEST(PropulsionOptions, ValidateNamesTheField) {
  HullDampingOptions h;
  h.speed_step_m_s = -1.0;
  expect_input_error([&] { h.validate(); }, "HullDampingOptions.speed_step_m_s");
  TugPropellerDampingOptions t;
  t.rpm_fraction = 0.0;
  expect_input_error([&] { t.validate(); }, "TugPropellerDampingOptions.rpm_fraction");
  t = {};
  t.pitch_ratio_min = 1.2;
  t.pitch_ratio_max = 1.0;
  expect_input_error([&] { t.validate(); }, "TugPropellerDampingOptions.pitch_ratio_min");
  t = {};
  t.pitch_ratio_max = 1.6;  // outside the series
  expect_input_error([&] { t.validate(); }, "TugPropellerDampingOptions.pitch_ratio_max");
  TowPropellerOptions p;
  p.free_spinning_fraction = 1.5;
  expect_input_error([&] { p.validate(); }, "TowPropellerOptions.free_spinning_fraction");
  MeanTensionOptions m;
  m.hull_margin = -0.1;
  expect_input_error([&] { m.validate(); }, "MeanTensionOptions.hull_margin");
  m = {};
  m.wind.wind_coefficient = 2.0;
  expect_input_error([&] { m.validate(); }, "WindDragOptions.wind_coefficient");
}

TEST(PropulsionOptions, BadVesselsAndConditionsAreRejected) {
  auto tug = test::make_tatf166();
  tug.propellers->blades = 8;  // B-series covers 2 to 7
  expect_input_error([&] { tug_propeller_damping(tug, 3.0, 1e5); }, "B-series blades");
  tug = test::make_tatf166();
  tug.propellers->expanded_area_ratio = 1.2;
  expect_input_error([&] { tug_propeller_damping(tug, 3.0, 1e5); }, "expanded_area_ratio");
  tug = test::make_tatf166();
  tug.propellers.reset();
  expect_input_error([&] { tug_propeller_damping(tug, 3.0, 1e5); }, "propellers");
  tug = test::make_tatf166();
  expect_input_error([&] { tug_propeller_damping(tug, -1.0, 1e5); }, "speed_m_s");
  expect_input_error([&] { tug_propeller_damping(tug, 3.0, -5.0); }, "mean_tension_n");
  expect_input_error([&] { hull_damping_n_s_m(tug, -0.5); }, "speed_m_s");
  MeanTensionConditions c;  // tow speed 0
  expect_input_error([&] { mean_tension(tug, c); }, "tow_speed_m_s");
  c.tow_speed_m_s = 3.0;
  c.towline_drag_n = -1.0;
  expect_input_error([&] { mean_tension(tug, c); }, "towline_drag_n");
}

TEST(PropulsionBSeriesSolve, TargetOutsideBracketIsAnInputError) {
  const BSeriesBlades b{4, 0.55};
  const double above = bseries_kt(b, 0.3, kBSeriesPitchRatioMax) + 0.01;
  expect_input_error([&] { solve_bseries_pitch_ratio(b, 0.3, above); }, "target K_T");
}

TEST(PropulsionTugPropeller, ThrustBeyondCapacityGivesTheFloor) {
  // EVIDENCE-OF: EQ-PROPULSION-6
  // Thesis 3.6: above ~140,000 lbf the asked thrust exceeds the tug and the
  // damping went negative; towdb returns the floor. 400,000 lbf is far
  // beyond two 9 ft propellers at 182 rpm (P/D = 1.4 gives ~95,000 lbf each).
  const auto tug = test::make_tatf166();
  TugPropellerDampingOptions o;
  const auto r = tug_propeller_damping(tug, units::kt_to_m_s(6.0), units::lbf_to_n(400000.0), o);
  EXPECT_EQ(r.status, PropellerSolveStatus::kThrustExceedsCapacity);
  EXPECT_TRUE(r.floored);
  EXPECT_EQ(r.damping_n_s_m, o.damping_floor_n_s_m);
  EXPECT_EQ(r.pitch_ratio, kBSeriesPitchRatioMax);
  EXPECT_LT(r.max_thrust_per_propeller_n, r.required_thrust_per_propeller_n);
  EXPECT_STREQ(to_string(r.status), "thrust_exceeds_capacity");
}

TEST(PropulsionTugPropeller, TinyThrustHoldsPitchAtSeriesMinimum) {
  // EVIDENCE-OF: EQ-PROPULSION-5
  // A light tow at speed: even P/D = 0.5 gives more thrust than asked; P/D
  // is held at 0.5 and flagged, and the damping is still positive.
  const auto tug = test::make_tatf166();
  const auto r = tug_propeller_damping(tug, units::kt_to_m_s(8.0), 0.0);
  EXPECT_EQ(r.status, PropellerSolveStatus::kPitchBelowSeriesRange);
  EXPECT_EQ(r.pitch_ratio, kBSeriesPitchRatioMin);
  EXPECT_GT(r.thrust_per_propeller_n, r.required_thrust_per_propeller_n);
  EXPECT_GT(r.damping_n_s_m, 0.0);
}

TEST(PropulsionTugPropeller, FloorAppliesToSmallComputedDamping) {
  // EVIDENCE-OF: EQ-PROPULSION-6
  // A floor above any physical value forces the floored branch.
  const auto tug = test::make_tatf166();
  TugPropellerDampingOptions o;
  o.damping_floor_n_s_m = 5e6;
  const auto r = tug_propeller_damping(tug, units::kt_to_m_s(6.0), units::lbf_to_n(50000.0), o);
  EXPECT_EQ(r.status, PropellerSolveStatus::kSolved);
  EXPECT_TRUE(r.floored);
  EXPECT_EQ(r.damping_n_s_m, 5e6);
}

TEST(PropulsionTowPropeller, VesselWithoutPropellersHasNoPropellerDrag) {
  // EVIDENCE-OF: EQ-PROPULSION-9
  const auto barge = test::make_tow("YRBM (test)", 7500.0, 1200.0, test::ittc57_drag_curve(46.1, 1.0));
  EXPECT_EQ(tow_propeller_drag_n(barge, 3.0), 0.0);
  EXPECT_EQ(tow_propeller_damping_n_s_m(barge, 3.0), 0.0);
  EXPECT_EQ(propeller_projected_area_m2(barge), 0.0);
}

TEST(PropulsionDeterminism, RepeatedCallsAreBitIdentical) {
  const auto tug = test::make_tatf166();
  const auto a = tug_propeller_damping(tug, 3.1, 3e5);
  const auto b = tug_propeller_damping(tug, 3.1, 3e5);
  EXPECT_EQ(a.pitch_ratio, b.pitch_ratio);
  EXPECT_EQ(a.damping_n_s_m, b.damping_n_s_m);
}

}  // namespace
}  // namespace towdb::propulsion
