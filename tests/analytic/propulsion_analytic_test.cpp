// Closed-form limits and manufactured solutions for towdb::propulsion.
// Each test names the equation it checks (propulsion/propulsion.hpp).
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "common/units.hpp"
#include "propulsion/propulsion.hpp"
#include "propulsion_vessels.hpp"
#include "test_support.hpp"

namespace towdb::propulsion {
namespace {

// Pure floating-point identities (a few operations): 1e-12 relative.
constexpr double kRoundoffRelTol = 1e-12;

model::Vessel vessel_with_table(std::vector<double> speeds_m_s, std::vector<double> c_t, double wetted_m2 = 1000.0) {
  model::Vessel v;
  v.name = "manufactured";
  v.hull.wetted_surface_m2 = wetted_m2;
  v.drag.speed_m_s = std::move(speeds_m_s);
  v.drag.total_resistance_coefficient = std::move(c_t);
  return v;
}

// ---- EQ-PROPULSION-1, -2: hull resistance and damping ---------------------

TEST(PropulsionHullDamping, ConstantCoefficientGivesTwiceResistanceOverSpeed) {
  // EVIDENCE-OF: EQ-PROPULSION-2
  // C_T constant => R = c V^2, dR/dV = 2 R / V exactly.
  const auto v = vessel_with_table({1.0, 10.0}, {3e-3, 3e-3});
  const double speed = 5.0;
  EXPECT_REL_CLOSE(hull_damping_n_s_m(v, speed), 2.0 * hull_resistance_n(v, speed) / speed, kRoundoffRelTol);
  // R itself: (1/2) rho S V^2 C_T (EQ-PROPULSION-1).
  // EVIDENCE-OF: EQ-PROPULSION-1
  EXPECT_REL_CLOSE(hull_resistance_n(v, speed), 0.5 * kRhoSeawater_kg_m3 * 1000.0 * 25.0 * 3e-3, kRoundoffRelTol);
}

TEST(PropulsionHullDamping, LinearCoefficientMatchesClosedFormDerivative) {
  // EVIDENCE-OF: EQ-PROPULSION-2
  // C_T = a + b V  =>  R = (1/2) rho S (a V^2 + b V^3),
  // dR/dV = (1/2) rho S (2 a V + 3 b V^2).
  const double a = 2.5e-3;
  const double b = 1.0e-4;  // per m/s
  const auto v = vessel_with_table({1.0, 8.0}, {a + b * 1.0, a + b * 8.0});
  for (double speed : {1.7, 3.0, 6.25}) {
    const double expected = 0.5 * kRhoSeawater_kg_m3 * 1000.0 * (2.0 * a * speed + 3.0 * b * speed * speed);
    EXPECT_REL_CLOSE(hull_damping_n_s_m(v, speed), expected, kRoundoffRelTol);
  }
}

TEST(PropulsionHullDamping, KinkRulesPickOneSidedSlopesAndTheirMean) {
  // EVIDENCE-OF: EQ-PROPULSION-2
  // Segment slopes 1e-4 and 3e-4 per m/s meet at V = 4 m/s; outside the
  // table C_T is held, slope 0.
  const auto v = vessel_with_table({2.0, 4.0, 6.0}, {3.0e-3, 3.2e-3, 3.8e-3});
  constexpr double kSlopeAbsTol = 1e-18;  // s/m; exact decimal arithmetic up to roundoff
  EXPECT_ABS_CLOSE(drag_coefficient_slope_s_m(v.drag, 4.0, KinkRule::kLowerSpeed), 1e-4, kSlopeAbsTol);
  EXPECT_ABS_CLOSE(drag_coefficient_slope_s_m(v.drag, 4.0, KinkRule::kUpperSpeed), 3e-4, kSlopeAbsTol);
  EXPECT_ABS_CLOSE(drag_coefficient_slope_s_m(v.drag, 4.0, KinkRule::kAverage), 2e-4, kSlopeAbsTol);
  // The last tabulated speed: the upper side is the held (flat) extension.
  EXPECT_ABS_CLOSE(drag_coefficient_slope_s_m(v.drag, 6.0, KinkRule::kAverage), 1.5e-4, kSlopeAbsTol);
  EXPECT_ABS_CLOSE(drag_coefficient_slope_s_m(v.drag, 7.0, KinkRule::kAverage), 0.0, kSlopeAbsTol);
  EXPECT_ABS_CLOSE(drag_coefficient_slope_s_m(v.drag, 1.0, KinkRule::kAverage), 0.0, kSlopeAbsTol);
  // A speed one ulp-scale away from the node still counts as the node.
  EXPECT_ABS_CLOSE(drag_coefficient_slope_s_m(v.drag, 4.0 * (1.0 + 1e-12), KinkRule::kAverage), 2e-4,
                   kSlopeAbsTol);
  // Damping at the kink with the average rule = mean of the one-sided ones.
  HullDampingOptions lower;
  lower.kink_rule = KinkRule::kLowerSpeed;
  HullDampingOptions upper;
  upper.kink_rule = KinkRule::kUpperSpeed;
  EXPECT_REL_CLOSE(hull_damping_n_s_m(v, 4.0),
                   0.5 * (hull_damping_n_s_m(v, 4.0, lower) + hull_damping_n_s_m(v, 4.0, upper)), kRoundoffRelTol);
}

TEST(PropulsionHullDamping, ForwardDifferenceOptionIsTheSecantSlope) {
  // EVIDENCE-OF: EQ-PROPULSION-2
  // Constant C_T: (c (V + dV)^2 - c V^2) / dV = c (2 V + dV).
  const auto v = vessel_with_table({1.0, 10.0}, {3e-3, 3e-3});
  HullDampingOptions o;
  o.speed_step_m_s = units::ft_s_to_m_s(1.0);
  const double c = 0.5 * kRhoSeawater_kg_m3 * 1000.0 * 3e-3;
  EXPECT_REL_CLOSE(hull_damping_n_s_m(v, 3.0, o), c * (2.0 * 3.0 + o.speed_step_m_s), 1e-11);
  // The margin factor scales R and its slope alike.
  HullDampingOptions margin;
  margin.resistance_factor = 1.1;
  EXPECT_REL_CLOSE(hull_damping_n_s_m(v, 3.0, margin), 1.1 * hull_damping_n_s_m(v, 3.0), kRoundoffRelTol);
}

// ---- EQ-PROPULSION-3: B-series derivatives and the pitch solve ------------

TEST(PropulsionBSeries, AnalyticDerivativesMatchCentralDifferences) {
  // EVIDENCE-OF: EQ-PROPULSION-3
  // Central difference, h = 1e-5: truncation ~h^2 K''' ~ 1e-10, roundoff
  // ~1e-16 / 1e-5 = 1e-11, against derivatives of order 0.1-1: 1e-7 relative.
  constexpr double kFiniteDifferenceRelTol = 1e-7;
  const double h = 1e-5;
  const BSeriesBlades b{5, 0.65};
  for (double j : {0.15, 0.45, 0.8}) {
    for (double pd : {0.6, 1.0, 1.3}) {
      EXPECT_REL_CLOSE(bseries_dkt_dj(b, j, pd), (bseries_kt(b, j + h, pd) - bseries_kt(b, j - h, pd)) / (2 * h),
                       kFiniteDifferenceRelTol);
      EXPECT_REL_CLOSE(bseries_dkt_dpitch(b, j, pd),
                       (bseries_kt(b, j, pd + h) - bseries_kt(b, j, pd - h)) / (2 * h), kFiniteDifferenceRelTol);
      EXPECT_REL_CLOSE(bseries_dkq_dj(b, j, pd), (bseries_kq(b, j + h, pd) - bseries_kq(b, j - h, pd)) / (2 * h),
                       kFiniteDifferenceRelTol);
    }
  }
}

TEST(PropulsionBSeries, PitchSolveInvertsThrustCoefficient) {
  // EVIDENCE-OF: EQ-PROPULSION-5
  // Manufactured: K_T(J, 0.87) is the target, so the solve must return 0.87.
  // Solver stops at |residual| <= 1e-13 with dK_T/d(P/D) ~ 0.5: 1e-11 in P/D.
  constexpr double kPitchAbsTol = 1e-11;
  const BSeriesBlades b{4, 0.55};
  for (double j : {0.0, 0.1, 0.4, 0.7}) {
    const double target = bseries_kt(b, j, 0.87);
    EXPECT_ABS_CLOSE(solve_bseries_pitch_ratio(b, j, target), 0.87, kPitchAbsTol);
  }
}

// ---- EQ-PROPULSION-4..6: tug propeller at constant RPM ---------------------

TEST(PropulsionTugPropeller, ThrustBalanceAndPowerIdentities) {
  // EVIDENCE-OF: EQ-PROPULSION-4
  // EVIDENCE-OF: EQ-PROPULSION-5
  const auto tug = test::make_tatf166();
  const double v = units::ft_s_to_m_s(10.0);
  const double tension = units::lbf_to_n(60000.0);
  const auto r = tug_propeller_damping(tug, v, tension);
  ASSERT_EQ(r.status, PropellerSolveStatus::kSolved);
  // N_p T = R_tug + T_mean (thesis steps 3-4); solver residual 1e-13 in K_T.
  EXPECT_REL_CLOSE(2.0 * r.thrust_per_propeller_n, hull_resistance_n(tug, v) + tension, 1e-11);
  // n = 0.8 * 227 rpm; J = V (1 - w) / (n D).
  const double n = 0.8 * 227.0 / 60.0;
  EXPECT_REL_CLOSE(r.rev_per_s, n, kRoundoffRelTol);
  EXPECT_REL_CLOSE(r.advance_ratio, v * 0.9 / (n * units::ft_to_m(9.0)), kRoundoffRelTol);
  // P_D = N_p 2 pi n Q.
  EXPECT_REL_CLOSE(r.delivered_power_w, 2.0 * 2.0 * kPi * n * r.torque_per_propeller_n_m, kRoundoffRelTol);
  // With the thrust deduction applied, T (1 - t) balances the resistance.
  auto tug_t = tug;
  tug_t.propellers->thrust_deduction = 0.2;
  TugPropellerDampingOptions deduct;
  deduct.apply_thrust_deduction = true;
  const auto rt = tug_propeller_damping(tug_t, v, tension, deduct);
  EXPECT_REL_CLOSE(rt.required_thrust_per_propeller_n, r.required_thrust_per_propeller_n / 0.8, kRoundoffRelTol);
}

TEST(PropulsionTugPropeller, SmallStepDifferenceConvergesToAnalyticDamping) {
  // EVIDENCE-OF: EQ-PROPULSION-6
  // -(T(V + dV) - T(V)) / dV -> -rho n D^3 (1 - w) dK_T/dJ as dV -> 0. With
  // dV = 1e-5 m/s the truncation is ~dV K_T''/(2 K_T') ~ 1e-6 relative.
  constexpr double kStepLimitRelTol = 1e-5;
  const auto tug = test::make_tatf166();
  const double v = units::kt_to_m_s(6.0);
  const double tension = units::lbf_to_n(50000.0);
  TugPropellerDampingOptions analytic;
  analytic.speed_step_m_s = 0.0;
  analytic.damping_floor_n_s_m = 0.0;
  TugPropellerDampingOptions tiny = analytic;
  tiny.speed_step_m_s = 1e-5;
  const auto a = tug_propeller_damping(tug, v, tension, analytic);
  const auto f = tug_propeller_damping(tug, v, tension, tiny);
  EXPECT_REL_CLOSE(f.damping_per_propeller_n_s_m, a.damping_per_propeller_n_s_m, kStepLimitRelTol);
  // Closed form of the analytic branch, from the returned state.
  const BSeriesBlades b{4, 0.55};
  const double d = units::ft_to_m(9.0);
  const double dkt_dj = bseries_dkt_dj(b, a.advance_ratio, a.pitch_ratio);
  EXPECT_REL_CLOSE(a.damping_per_propeller_n_s_m, -kRhoSeawater_kg_m3 * a.rev_per_s * d * d * d * 0.9 * dkt_dj,
                   kRoundoffRelTol);
  EXPECT_GT(a.damping_per_propeller_n_s_m, 0.0);  // thrust falls with speed at constant n
}

TEST(PropulsionTugPropeller, DampingScalesWithRevolutionsAtSimilarOperatingPoint) {
  // EVIDENCE-OF: EQ-PROPULSION-6
  // B_P = -rho n D^3 (1 - w) dK_T/dJ: at the same J and K_T (V and n both
  // doubled, thrust x4), P/D is the same and the damping doubles.
  auto tug = test::make_tatf166();
  TugPropellerDampingOptions o;
  o.speed_step_m_s = 0.0;
  const double v = units::kt_to_m_s(5.0);
  const double tension = units::lbf_to_n(40000.0);
  const auto base = tug_propeller_damping(tug, v, tension, o);
  tug.propellers->rpm_max *= 2.0;
  const double thrust_total_x4 = 4.0 * 2.0 * base.thrust_per_propeller_n;
  const double tension_x4 = thrust_total_x4 - hull_resistance_n(tug, 2.0 * v);
  const auto fast = tug_propeller_damping(tug, 2.0 * v, tension_x4, o);
  EXPECT_ABS_CLOSE(fast.pitch_ratio, base.pitch_ratio, 1e-10);  // same K_T, same J
  EXPECT_REL_CLOSE(fast.damping_per_propeller_n_s_m, 2.0 * base.damping_per_propeller_n_s_m, 1e-9);
}

TEST(PropulsionTugPropeller, AllPropellersShareIsCountTimesOne) {
  // EVIDENCE-OF: EQ-PROPULSION-6
  const auto tug = test::make_tatf166();
  TugPropellerDampingOptions one;
  TugPropellerDampingOptions all;
  all.share = PropellerDampingShare::kAllPropellers;
  const double v = units::ft_s_to_m_s(10.0);
  const double tension = units::lbf_to_n(60000.0);
  const auto r1 = tug_propeller_damping(tug, v, tension, one);
  const auto r2 = tug_propeller_damping(tug, v, tension, all);
  EXPECT_REL_CLOSE(r2.damping_n_s_m, 2.0 * r1.damping_n_s_m, kRoundoffRelTol);
  EXPECT_REL_CLOSE(r1.damping_n_s_m, r1.damping_per_propeller_n_s_m, kRoundoffRelTol);
  // Tug surge damping = hull + the propeller share.
  const auto s = tug_surge_damping(tug, v, tension);
  EXPECT_REL_CLOSE(s.total_n_s_m, hull_damping_n_s_m(tug, v) + r1.damping_n_s_m, kRoundoffRelTol);
}

// ---- EQ-PROPULSION-7..9: the tow's propeller --------------------------------

model::Vessel tow_with_propellers() {
  auto tow = test::make_tow("tow", 35000.0, 3100.0, test::ittc57_drag_curve(units::ft_to_m(529.0), 1.0));
  model::Propellers p;
  p.count = 2;
  p.diameter_m = units::ft_to_m(17.0);
  p.blades = 5;
  p.expanded_area_ratio = 0.75;
  p.pitch_ratio = 1.0;
  p.rpm_max = 166.0;
  p.wake_fraction = 0.10;
  tow.propellers = p;
  return tow;
}

TEST(PropulsionTowPropeller, NavyFormulaInPoundsFeetKnots) {
  // EVIDENCE-OF: EQ-PROPULSION-7
  // Towing Manual: R_P = 3.737 A_P V^2 [lbf, ft^2, kt]. LHA 1: A_P = 320 ft^2
  // at 6 kt gives 43,050 lbf (docs/ship-data.md 2.3 rounds it to 43,000).
  // Tolerance: C_DP = 1.3181 is rounded to 5 digits (8e-6) and rho differs
  // from 1.9905 slug/ft^3 by 8e-6: 1e-4 relative.
  constexpr double kNavyCoefficientRelTol = 1e-4;
  const auto tow = tow_with_propellers();
  TowPropellerOptions o;
  o.projected_area_m2 = units::ft2_to_m2(320.0);
  EXPECT_REL_CLOSE(units::n_to_lbf(tow_propeller_drag_n(tow, units::kt_to_m_s(6.0), o)), 3.737 * 320.0 * 36.0,
                   kNavyCoefficientRelTol);
}

TEST(PropulsionTowPropeller, ProjectedAreaFromExpandedArea) {
  // EVIDENCE-OF: EQ-PROPULSION-7
  // UFC 4-159-03 eq. 4-22: A_P/A_E = 1.067 - 0.229 P/D = 0.838 at P/D = 1.
  const auto tow = tow_with_propellers();
  const double d = units::ft_to_m(17.0);
  EXPECT_REL_CLOSE(propeller_projected_area_m2(tow), 2.0 * kPi * d * d / 4.0 * 0.75 * 0.838, kRoundoffRelTol);
}

TEST(PropulsionTowPropeller, FreeSpinningIsHalfLockedAndRemovedIsZero) {
  // EVIDENCE-OF: EQ-PROPULSION-9
  const auto tow = tow_with_propellers();
  const double v = units::kt_to_m_s(7.0);
  TowPropellerOptions locked;
  TowPropellerOptions free = locked;
  free.state = TowPropellerState::kFreeSpinning;
  TowPropellerOptions removed = locked;
  removed.state = TowPropellerState::kRemoved;
  EXPECT_REL_CLOSE(tow_propeller_drag_n(tow, v, free), 0.5 * tow_propeller_drag_n(tow, v, locked), kRoundoffRelTol);
  EXPECT_EQ(tow_propeller_drag_n(tow, v, removed), 0.0);
  EXPECT_EQ(tow_propeller_damping_n_s_m(tow, v, removed), 0.0);
}

TEST(PropulsionTowPropeller, DampingIsSlopeOfQuadraticDrag) {
  // EVIDENCE-OF: EQ-PROPULSION-9
  // R = c V^2: the central difference is exact for a quadratic, so the
  // analytic 2 R / V must match it to roundoff (1e-9 for h = 1e-3 m/s).
  constexpr double kQuadraticFdRelTol = 1e-9;
  const auto tow = tow_with_propellers();
  const double v = units::kt_to_m_s(6.0);
  const double h = 1e-3;
  for (auto model : {LockedPropellerDragModel::kNavyProjectedArea, LockedPropellerDragModel::kDiskAreaWake}) {
    TowPropellerOptions o;
    o.model = model;
    EXPECT_REL_CLOSE(tow_propeller_damping_n_s_m(tow, v, o),
                     (tow_propeller_drag_n(tow, v + h, o) - tow_propeller_drag_n(tow, v - h, o)) / (2 * h),
                     kQuadraticFdRelTol);
  }
  // Tow surge damping = hull + propeller.
  TowPropellerOptions o;
  const auto s = tow_surge_damping(tow, v, {}, o);
  EXPECT_REL_CLOSE(s.total_n_s_m, hull_damping_n_s_m(tow, v) + tow_propeller_damping_n_s_m(tow, v, o),
                   kRoundoffRelTol);
  // Thesis 12D model (propeller left out): hull damping only.
  TowPropellerOptions removed;
  removed.state = TowPropellerState::kRemoved;
  EXPECT_EQ(tow_surge_damping(tow, v, {}, removed).total_n_s_m, hull_damping_n_s_m(tow, v));
}

TEST(PropulsionTowPropeller, DiskAreaWithWakeEqualsNavyAtProjectedRatio072) {
  // EVIDENCE-OF: EQ-PROPULSION-8
  // Thesis ch. 2 (below eq. 2.5): for A_P/A_0 = 0.72, eq. 2.4 corrected for
  // the wake and eq. 2.5 "give identical answers". With w = 0.10:
  // 1.17 * 0.9^2 = 0.9477 vs 1.3181 * 0.72 = 0.9490 (0.14 % apart).
  constexpr double kThesisEquivalenceRelTol = 0.003;  // "identical" to the 3 digits the thesis works with
  const auto tow = tow_with_propellers();
  const double d = units::ft_to_m(17.0);
  const double disk_m2 = 2.0 * kPi * d * d / 4.0;
  TowPropellerOptions navy;
  navy.projected_area_m2 = 0.72 * disk_m2;
  TowPropellerOptions disk;
  disk.model = LockedPropellerDragModel::kDiskAreaWake;
  const double v = units::kt_to_m_s(5.0);
  EXPECT_REL_CLOSE(tow_propeller_drag_n(tow, v, disk), tow_propeller_drag_n(tow, v, navy), kThesisEquivalenceRelTol);
  // Without the wake the disk form is 1/0.81 larger (it "over-estimates").
  disk.model = LockedPropellerDragModel::kDiskArea;
  TowPropellerOptions disk_wake = disk;
  disk_wake.model = LockedPropellerDragModel::kDiskAreaWake;
  EXPECT_REL_CLOSE(tow_propeller_drag_n(tow, v, disk), tow_propeller_drag_n(tow, v, disk_wake) / 0.81,
                   kRoundoffRelTol);
}

// ---- EQ-PROPULSION-10: wind --------------------------------------------------

TEST(PropulsionWind, NavyFormulaInPoundsFeetKnots) {
  // EVIDENCE-OF: EQ-PROPULSION-10
  // Towing Manual: R_W = 0.00506 C_w K A_T V_R^2 [lbf, ft^2, kt]; head wind
  // 25 kt on a tow at 7.75 kt, A_T = 3,100 ft^2, C_w = 1, K = 1:
  // 0.00506 * 3100 * 32.75^2 = 16,824 lbf. C_W0 = 1.4945 is rounded
  // (2e-5) and rho_air = 1.2250 vs 0.002377 slug/ft^3 (4e-5): 1e-4.
  constexpr double kNavyCoefficientRelTol = 1e-4;
  const auto tow = test::make_tow("tow", 35000.0, 3100.0, test::ittc57_drag_curve(160.0, 1.0));
  WindDragOptions o;
  o.wind_coefficient = 1.0;
  const double r = wind_drag_n(tow, units::kt_to_m_s(7.75), units::kt_to_m_s(25.0), kPi, o);
  EXPECT_REL_CLOSE(units::n_to_lbf(r), 0.00506 * 3100.0 * 32.75 * 32.75, kNavyCoefficientRelTol);
}

TEST(PropulsionWind, NavyAndTaylorFormsAgree) {
  // EVIDENCE-OF: EQ-PROPULSION-10
  // Thesis ch. 2: eq. 2.8 "gives nearly the same values" as Taylor's eq.
  // 2.6: 1.4945 * 0.85 = 1.270 vs 1.28, 0.8 % apart.
  constexpr double kFormulaAgreementRelTol = 0.01;
  const auto tow = test::make_tow("tow", 35000.0, 3100.0, test::ittc57_drag_curve(160.0, 1.0));
  WindDragOptions navy;
  WindDragOptions taylor;
  taylor.model = WindDragModel::kTaylor;
  const double v = units::kt_to_m_s(6.0);
  const double u = units::kt_to_m_s(30.0);
  EXPECT_REL_CLOSE(wind_drag_n(tow, v, u, kPi, navy), wind_drag_n(tow, v, u, kPi, taylor), kFormulaAgreementRelTol);
}

TEST(PropulsionWind, RelativeWindGeometry) {
  // EVIDENCE-OF: EQ-PROPULSION-10
  constexpr double kSpeedAbsTol_m_s = 1e-12;
  const double v = 3.0;
  const double u = 10.0;
  EXPECT_ABS_CLOSE(relative_wind(v, u, kPi).along_from_ahead_m_s, 13.0, kSpeedAbsTol_m_s);    // head: V + U
  EXPECT_ABS_CLOSE(relative_wind(v, u, 0.0).along_from_ahead_m_s, -7.0, kSpeedAbsTol_m_s);    // following: V - U
  const auto beam = relative_wind(v, u, 0.5 * kPi);
  EXPECT_ABS_CLOSE(beam.along_from_ahead_m_s, 3.0, kSpeedAbsTol_m_s);
  EXPECT_ABS_CLOSE(beam.speed_m_s, std::hypot(3.0, 10.0), kSpeedAbsTol_m_s);
  // Drag follows u_R |u_R|: a following wind faster than the tow pushes it.
  const auto tow = test::make_tow("tow", 35000.0, 3100.0, test::ittc57_drag_curve(160.0, 1.0));
  const double head = wind_drag_n(tow, v, u, kPi);
  const double following = wind_drag_n(tow, v, u, 0.0);
  EXPECT_REL_CLOSE(following, -head * 49.0 / 169.0, kRoundoffRelTol);
  EXPECT_REL_CLOSE(wind_drag_n(tow, v, u, 0.5 * kPi), wind_drag_n(tow, v, 0.0, kPi), 1e-12);
}

// ---- EQ-PROPULSION-11: eq. 2.9 direction correction ------------------------

TEST(PropulsionSea, ThesisEquation29InTowdbHeadings) {
  // EVIDENCE-OF: EQ-PROPULSION-11
  // Thesis eq. 2.9: R_S = R_head cos(theta), theta from head seas, 0 beyond
  // 90 deg. towdb mu = 180 deg is head (theta = 0), mu = 120 deg is theta = 60.
  constexpr double kForceAbsTol_n = 1e-9;
  const double head = 1000.0;
  EXPECT_ABS_CLOSE(direction_corrected_added_resistance_n(head, kPi), 1000.0, kForceAbsTol_n);
  EXPECT_ABS_CLOSE(direction_corrected_added_resistance_n(head, units::deg_to_rad(120.0)), 500.0, kForceAbsTol_n);
  EXPECT_ABS_CLOSE(direction_corrected_added_resistance_n(head, units::deg_to_rad(-150.0)),
                   1000.0 * std::cos(units::deg_to_rad(30.0)), kForceAbsTol_n);
  EXPECT_ABS_CLOSE(direction_corrected_added_resistance_n(head, units::deg_to_rad(210.0)),
                   1000.0 * std::cos(units::deg_to_rad(30.0)), kForceAbsTol_n);
  EXPECT_ABS_CLOSE(direction_corrected_added_resistance_n(head, 0.5 * kPi), 0.0, kForceAbsTol_n);
  EXPECT_EQ(direction_corrected_added_resistance_n(head, units::deg_to_rad(60.0)), 0.0);  // quartering: 0
  EXPECT_EQ(direction_corrected_added_resistance_n(head, 0.0), 0.0);                       // following: 0
}

// ---- EQ-PROPULSION-12: the sum -----------------------------------------------

TEST(PropulsionMeanTension, ComponentsAddUpWithMarginAndTowlineFraction) {
  // EVIDENCE-OF: EQ-PROPULSION-12
  const auto tow = tow_with_propellers();
  MeanTensionConditions c;
  c.tow_speed_m_s = units::kt_to_m_s(6.0);
  c.wind_speed_m_s = units::kt_to_m_s(20.0);
  c.sea_added_resistance_n = 20000.0;
  c.sea_input = SeaResistanceInput::kHeadSeasCorrected;
  c.wave_heading_rad = units::deg_to_rad(120.0);
  const auto b = mean_tension(tow, c);
  EXPECT_REL_CLOSE(b.hull_n, 1.10 * hull_resistance_n(tow, c.tow_speed_m_s), kRoundoffRelTol);
  EXPECT_REL_CLOSE(b.sea_n, 10000.0, kRoundoffRelTol);
  EXPECT_REL_CLOSE(b.tow_resistance_n, b.hull_n + b.propeller_n + b.wind_n + b.sea_n, kRoundoffRelTol);
  EXPECT_REL_CLOSE(b.total_n, 1.10 * b.tow_resistance_n, kRoundoffRelTol);
  // Towing Manual margin 25 %: the hull term grows by 1.25 / 1.10.
  MeanTensionOptions manual;
  manual.hull_margin = 0.25;
  EXPECT_REL_CLOSE(mean_tension(tow, c, manual).hull_n, b.hull_n * 1.25 / 1.10, kRoundoffRelTol);
  // A supplied towline drag replaces the 10 % rule.
  c.towline_drag_n = 1234.0;
  const auto supplied = mean_tension(tow, c);
  EXPECT_REL_CLOSE(supplied.total_n, b.tow_resistance_n + 1234.0, kRoundoffRelTol);
}

}  // namespace
}  // namespace towdb::propulsion
