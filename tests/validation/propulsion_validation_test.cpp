// Validation of towdb::propulsion against published towing figures:
//   1. Thesis 3.6: T-ATF towing LHA-1 at 10 ft/s, propeller damping
//      3,856 lbf s/ft at constant RPM (hull damping 754).
//   2. U.S. Navy Towing Manual worked example (Army TB 55-1900-232-10,
//      App. L-5; docs/ship-data.md 5.1): DD 963 tow resistance 90,000-113,000 lbf
//      over 6.9-7.75 kt in a 25 kt head wind, checked with a CG-47-like tow.
// Inputs that the sources do not give are estimates, stated below; the
// checks are therefore order-of-magnitude (1) and +-15 % (2).
#include <cstdio>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "propulsion/propulsion.hpp"
#include "propulsion_vessels.hpp"
#include "test_support.hpp"

namespace towdb::propulsion {
namespace {

// LHA 1 as a tow (docs/ship-data.md 3.3): L_wl 778 ft; S = 88,100 ft^2 (E,
// Denny-Mumford, docs/ship-data.md 2.3); A_T = 8,000 ft^2 (E); two locked 20 ft
// propellers with A_P = 320 ft^2 (E, docs/ship-data.md 2.3), wake 0.10 (E).
// Drag file (E): C_T = 1.2 C_F,ITTC57 (form factor 1.2 for a C_b = 0.65
// hull; wave resistance negligible at Fn < 0.07).
model::Vessel make_lha1() {
  auto tow = test::make_tow("LHA 1 (test)", 88100.0, 8000.0, test::ittc57_drag_curve(units::ft_to_m(778.0), 1.2));
  model::Propellers p;
  p.count = 2;
  p.diameter_m = units::ft_to_m(20.0);
  p.blades = 5;
  p.expanded_area_ratio = 0.60;
  p.pitch_ratio = 1.0;
  p.rpm_max = 160.0;
  p.wake_fraction = 0.10;
  tow.propellers = p;
  return tow;
}

TEST(PropulsionValidation, TatfPropellerDampingTowingLha1OrderOfMagnitude) {
  // EVIDENCE-OF: EQ-PROPULSION-6
  // EVIDENCE-OF: EQ-PROPULSION-12
  // Mean tension: thesis ch. 2 method (10 % hull margin, eq. 2.5 with the
  // wake, 20 kt head wind as in the thesis's Table 3-1 case; no sea term).
  // Then the thesis 3.6 procedure at n = 0.8 * 227 rpm, 1 ft/s step.
  // Thesis: 3,856 lbf s/ft, read here as both propellers' damping (it then
  // says the simulation keeps one propeller's, "not the full damping").
  constexpr double kOrderOfMagnitudeFactor = 2.0;  // T-ATF EAR, wake and LHA drag are estimates
  const auto tatf = test::make_tatf166();
  const auto lha = make_lha1();
  const double v = units::ft_s_to_m_s(10.0);
  MeanTensionConditions c;
  c.tow_speed_m_s = v;
  c.wind_speed_m_s = units::kt_to_m_s(20.0);
  MeanTensionOptions mo;
  mo.propeller.model = LockedPropellerDragModel::kNavyProjectedAreaWake;
  mo.propeller.projected_area_m2 = units::ft2_to_m2(320.0);
  const auto tension = mean_tension(lha, c, mo);
  TugPropellerDampingOptions all;
  all.share = PropellerDampingShare::kAllPropellers;
  const auto r = tug_propeller_damping(tatf, v, tension.total_n, all);
  ASSERT_EQ(r.status, PropellerSolveStatus::kSolved);
  const double full_lbf_s_ft = units::n_s_per_m_to_lbf_s_per_ft(r.damping_n_s_m);
  const double hull_lbf_s_ft = units::n_s_per_m_to_lbf_s_per_ft(hull_damping_n_s_m(tatf, v));
  std::printf("[ LHA-1 mean tension %.0f lbf (hull %.0f, prop %.0f, wind %.0f, line %.0f); T-ATF P/D %.3f, "
              "J %.3f, propeller damping (2 props) %.0f lbf s/ft vs thesis 3,856; hull %.0f vs 754; "
              "power %.0f hp ]\n",
              units::n_to_lbf(tension.total_n), units::n_to_lbf(tension.hull_n), units::n_to_lbf(tension.propeller_n),
              units::n_to_lbf(tension.wind_n), units::n_to_lbf(tension.towline_n), r.pitch_ratio, r.advance_ratio,
              full_lbf_s_ft, hull_lbf_s_ft, r.delivered_power_w / units::hp_to_w(1.0));
  EXPECT_GT(full_lbf_s_ft, 3856.0 / kOrderOfMagnitudeFactor);
  EXPECT_LT(full_lbf_s_ft, 3856.0 * kOrderOfMagnitudeFactor);
  // Thesis finding: constant-RPM damping far exceeds the hull damping.
  EXPECT_GT(full_lbf_s_ft, 3.0 * hull_lbf_s_ft);
}

TEST(PropulsionValidation, TatfThrustCapacityNearThesisNegativeDampingThreshold) {
  // EVIDENCE-OF: EQ-PROPULSION-6
  // Thesis 3.6: the damping came out negative "for very high mean tensions
  // (> 140,000 lbs)", when the thrust asked exceeded what the tug could
  // give. towdb's capacity (P/D = 1.4 at n = 0.8 * 227 rpm, 5 kt) is the
  // mean tension 2 T_max - R_tug; it must sit near 140,000 lbf, and above
  // it the floor must take over.
  constexpr double kCapacityRelTol = 0.25;  // thesis gives no speed; EAR and wake are estimates
  const auto tatf = test::make_tatf166();
  const double v = units::kt_to_m_s(5.0);
  const auto r = tug_propeller_damping(tatf, v, units::lbf_to_n(50000.0));
  const double capacity_lbf = units::n_to_lbf(2.0 * r.max_thrust_per_propeller_n - hull_resistance_n(tatf, v));
  std::printf("[ T-ATF mean-tension capacity at 5 kt: %.0f lbf vs thesis ~140,000 ]\n", capacity_lbf);
  EXPECT_REL_CLOSE(capacity_lbf, 140000.0, kCapacityRelTol);
  const auto above = tug_propeller_damping(tatf, v, units::lbf_to_n(1.05 * capacity_lbf));
  EXPECT_EQ(above.status, PropellerSolveStatus::kThrustExceedsCapacity);
  EXPECT_TRUE(above.floored);
}

TEST(PropulsionValidation, Ffg7TowInTrailingSeasNearMeasuredTension) {
  // EVIDENCE-OF: EQ-PROPULSION-11
  // EVIDENCE-OF: EQ-PROPULSION-12
  // Thesis Table 2-3, case 1: an FFG-7 towed at 8 kt, 12 kt wind, wave angle
  // 177 deg from head seas (towdb heading 3 deg, trailing): actual towline
  // resistance 40,000 lbf; the thesis's calculation gave 49,102 and POSSE
  // 59,499 ("both models overestimate"). In trailing seas eq. 2.9 makes the
  // sea term 0, so this case checks hull + propeller + wind + line.
  // Inputs (docs/ship-data.md 2.3 / 3.6, E): S = 20,000 ft^2, L = 408 ft,
  // C_T = 1.2 C_F,ITTC57, one locked propeller A_P = 127 ft^2 at V (1 - w),
  // w = 0.10, A_T = 2,200 ft^2; the wind assumed to blow with the seas.
  constexpr double kMeasuredTowRelTol = 0.25;  // one measured tow; areas, wake and drag file estimated
  auto tow = test::make_tow("FFG 7 (test)", 20000.0, 2200.0, test::ittc57_drag_curve(units::ft_to_m(408.0), 1.2));
  model::Propellers p;
  p.count = 1;
  p.diameter_m = units::ft_to_m(16.5);
  p.blades = 5;
  p.expanded_area_ratio = 0.70;
  p.pitch_ratio = 1.0;
  p.rpm_max = 180.0;
  p.wake_fraction = 0.10;
  tow.propellers = p;
  MeanTensionOptions thesis;  // 10 % hull margin, 10 % towline
  thesis.propeller.model = LockedPropellerDragModel::kNavyProjectedAreaWake;
  thesis.propeller.projected_area_m2 = units::ft2_to_m2(127.0);
  MeanTensionConditions c;
  c.tow_speed_m_s = units::kt_to_m_s(8.0);
  c.wind_speed_m_s = units::kt_to_m_s(12.0);
  c.wind_heading_rad = units::deg_to_rad(180.0 - 177.0);
  c.wave_heading_rad = units::deg_to_rad(180.0 - 177.0);
  c.sea_added_resistance_n = units::lbf_to_n(10000.0);  // any head-seas value: eq. 2.9 zeroes it here
  c.sea_input = SeaResistanceInput::kHeadSeasCorrected;
  const auto b = mean_tension(tow, c, thesis);
  const double total_lbf = units::n_to_lbf(b.total_n);
  std::printf("[ FFG-7 8 kt trailing: towdb %.0f lbf (hull %.0f, prop %.0f, wind %.0f, sea %.0f, line %.0f) vs "
              "actual 40,000, thesis calc 49,102 ]\n",
              total_lbf, units::n_to_lbf(b.hull_n), units::n_to_lbf(b.propeller_n), units::n_to_lbf(b.wind_n),
              units::n_to_lbf(b.sea_n), units::n_to_lbf(b.towline_n));
  EXPECT_EQ(b.sea_n, 0.0);
  EXPECT_REL_CLOSE(total_lbf, 40000.0, kMeasuredTowRelTol);
}

TEST(PropulsionValidation, NavyDd963MeanTensionWithCg47LikeTow) {
  // EVIDENCE-OF: EQ-PROPULSION-7
  // EVIDENCE-OF: EQ-PROPULSION-10
  // EVIDENCE-OF: EQ-PROPULSION-12
  // Towing Manual method (its 25 % hull margin, locked propellers at ship
  // speed, C_w = 1.0 and K = 1 for the 25 kt head wind, 10 % towline drag).
  // CG-47-like tow (docs/ship-data.md 2.3 / 3.5): S = 35,000 ft^2, L = 529 ft,
  // drag file C_T = C_F,ITTC57 (the manual's Fig. G-1 was not available),
  // A_P = 290 ft^2, A_T = 3,100 ft^2. The Navy figures include sea-state
  // added resistance, which is left out here (no value published), so
  // towdb should land at or somewhat below them.
  constexpr double kNavyExampleRelTol = 0.15;  // estimated areas, no sea term, DD 963 vs CG 47
  auto tow = test::make_tow("CG 47 (test)", 35000.0, 3100.0, test::ittc57_drag_curve(units::ft_to_m(529.0), 1.0));
  model::Propellers p;
  p.count = 2;
  p.diameter_m = units::ft_to_m(17.0);
  p.blades = 5;
  p.expanded_area_ratio = 0.75;
  p.pitch_ratio = 1.0;
  p.rpm_max = 166.0;
  p.wake_fraction = 0.10;
  tow.propellers = p;
  MeanTensionOptions manual;
  manual.hull_margin = 0.25;
  manual.propeller.projected_area_m2 = units::ft2_to_m2(290.0);
  manual.wind.wind_coefficient = 1.0;
  struct NavyPoint {
    double speed_kt;
    double tension_lbf;
  };
  // docs/ship-data.md 5.1 (S17): T-ATF 6.9 kt / 90,000; ARS 50 7.2 / 98,000;
  // ATS 1 7.4 / 106,000; T-ATF 7.75 / 113,000.
  for (const NavyPoint& point : {NavyPoint{6.9, 90000.0}, NavyPoint{7.2, 98000.0}, NavyPoint{7.4, 106000.0},
                                 NavyPoint{7.75, 113000.0}}) {
    MeanTensionConditions c;
    c.tow_speed_m_s = units::kt_to_m_s(point.speed_kt);
    c.wind_speed_m_s = units::kt_to_m_s(25.0);
    const auto b = mean_tension(tow, c, manual);
    const double total_lbf = units::n_to_lbf(b.total_n);
    std::printf("[ %.2f kt: towdb %.0f lbf (hull %.0f, prop %.0f, wind %.0f, line %.0f) vs Navy %.0f: %+.1f %% ]\n",
                point.speed_kt, total_lbf, units::n_to_lbf(b.hull_n), units::n_to_lbf(b.propeller_n),
                units::n_to_lbf(b.wind_n), units::n_to_lbf(b.towline_n), point.tension_lbf,
                100.0 * (total_lbf / point.tension_lbf - 1.0));
    EXPECT_REL_CLOSE(total_lbf, point.tension_lbf, kNavyExampleRelTol);
    EXPECT_LE(total_lbf, point.tension_lbf);  // the sea term is missing, so not above
  }
}

}  // namespace
}  // namespace towdb::propulsion
