// Grid mean tensions of the sweep (generator/sweep/spec/grid_tension.hpp) against
// closed forms in the thesis's and the Towing Manual's own units.
// Test plan:
//   sweep-tension-1  YRBM (no propeller), no wind: T_calc = 1.10 x 1.10 x (1/2) rho S V^2 C_T and
//                    the lower tension = 1.10 x (1/2) rho S V^2 C_T (EQ-SWEEP-1, -2)
//   sweep-tension-2  the lower tension adds half the Navy locked-propeller drag 3.737 A_p V^2
//                    (lbf, ft^2, kt; thesis eq. 2.5) to the hull with margin
//   sweep-tension-3  the head-wind term is the Navy 0.00506 C_w K A_T V_R^2 (thesis eq. 2.8) with
//                    V_R = V + U, the same at every heading (thesis Appendix C)
//   sweep-tension-4  speed reduction on a manufactured T(V) = c V^2 and on LHA 1 in a 35 kt wind
//                    (EQ-SWEEP-3; thesis ch. 5: LHA-1 cannot be towed at 9 kt in 30-35 kt winds)
#include <cmath>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "propulsion/tow_propeller.hpp"
#include "sweep/spec/grid_tension.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

const io::ShipCatalog& catalog() {
  static const io::ShipCatalog c = io::ShipCatalog::load(source_dir() / "ships");
  return c;
}

// (1/2) rho S V^2 C_T(V) in lbf (EQ-PROPULSION-1, thesis eq. 2.3).
double hull_lbf(const model::Vessel& v, double speed_kt) {
  const double v_m_s = units::kt_to_m_s(speed_kt);
  return units::n_to_lbf(0.5 * kRhoSeawater_kg_m3 * v.hull.wetted_surface_m2 * v_m_s * v_m_s *
                         v.drag.coefficient_at(v_m_s));
}

// Same formula, different order of operations: rounding only.
constexpr double kSameFormulaRelTol = 1e-12;
// The Navy's dimensional constants (3.737, 0.00506) have 4 and 3 significant
// figures; towdb uses the dimensionless coefficients derived from them.
constexpr double kNavyConstantRelTol = 2e-3;

TEST(SweepMeanTension, BargeWithoutPropellerOrWind) {  // sweep-tension-1
  // EVIDENCE-OF: EQ-SWEEP-1
  // EVIDENCE-OF: EQ-SWEEP-2
  const model::Vessel& yrbm = catalog().vessel("YRBM").vessel;
  ASSERT_FALSE(yrbm.propellers.has_value());
  sweep::MeanTensionModel m;  // margin 0.10, towline 10 %
  for (double v_kt : {3.0, 5.0, 9.0}) {
    const auto b = sweep::calculated_mean_tension(yrbm, v_kt, 0.0, 180.0, 0.0, m);
    const double wind_lbf = units::n_to_lbf(b.wind_n);  // the tow's own speed through still air
    EXPECT_REL_CLOSE(units::n_to_lbf(b.hull_n), 1.10 * hull_lbf(yrbm, v_kt), kSameFormulaRelTol);
    EXPECT_EQ(b.propeller_n, 0.0);
    EXPECT_REL_CLOSE(units::n_to_lbf(b.total_n), 1.10 * (1.10 * hull_lbf(yrbm, v_kt) + wind_lbf), kSameFormulaRelTol);
    EXPECT_REL_CLOSE(sweep::hull_half_propeller_tension_lbf(yrbm, v_kt, m), 1.10 * hull_lbf(yrbm, v_kt),
                     kSameFormulaRelTol);
  }
  m.hull_margin = 0.25;  // the Towing Manual's margin
  EXPECT_REL_CLOSE(sweep::hull_half_propeller_tension_lbf(yrbm, 5.0, m), 1.25 * hull_lbf(yrbm, 5.0),
                   kSameFormulaRelTol);
}

TEST(SweepMeanTension, LowerTensionAddsHalfTheNavyPropellerDrag) {  // sweep-tension-2
  // EVIDENCE-OF: EQ-SWEEP-2 — thesis ch. 5: "hull resistance plus one half of the propeller
  // resistance"; Towing Manual R_P = 3.737 A_p V^2 [lbf, ft^2, kt].
  for (const char* name : {"FFG 7", "AE 26", "CG 47", "LHA 1"}) {
    const model::Vessel& tow = catalog().vessel(name).vessel;
    const double a_p_ft2 = units::m2_to_ft2(propulsion::propeller_projected_area_m2(tow));
    ASSERT_GT(a_p_ft2, 10.0) << name;
    sweep::MeanTensionModel m;
    for (double v_kt : {5.0, 8.5}) {
      const double lower = sweep::hull_half_propeller_tension_lbf(tow, v_kt, m);
      EXPECT_REL_CLOSE(lower - 1.10 * hull_lbf(tow, v_kt), 0.5 * 3.737 * a_p_ft2 * v_kt * v_kt, kNavyConstantRelTol)
          << name << " at " << v_kt << " kt";
    }
  }
}

TEST(SweepMeanTension, HeadWindTermIsTheNavyFormula) {  // sweep-tension-3
  // EVIDENCE-OF: EQ-SWEEP-1 — R_W = 0.00506 C_w K A_T V_R^2 (thesis eq. 2.8), C_w = 0.85, K = 1,
  // V_R = V + U from ahead; the towline adds 10 %.
  const model::Vessel& ffg = catalog().vessel("FFG 7").vessel;
  const double a_t_ft2 = units::m2_to_ft2(ffg.hull.windage_frontal_m2);
  sweep::MeanTensionModel m;  // wind from ahead
  const double v_kt = 5.0;
  const double calm = units::n_to_lbf(sweep::calculated_mean_tension(ffg, v_kt, 0.0, 180.0, 0.0, m).total_n);
  for (double u_kt : {20.0, 30.0, 35.0}) {
    const double windy = units::n_to_lbf(sweep::calculated_mean_tension(ffg, v_kt, u_kt, 180.0, 0.0, m).total_n);
    const double navy = 0.00506 * 0.85 * 1.0 * a_t_ft2 * ((v_kt + u_kt) * (v_kt + u_kt) - v_kt * v_kt);
    EXPECT_REL_CLOSE(windy - calm, 1.10 * navy, kNavyConstantRelTol) << u_kt << " kt";
    // Thesis Appendix C: one mean tension for all four headings of a condition.
    for (double heading_deg : {0.0, 60.0, 120.0}) {
      EXPECT_EQ(sweep::calculated_mean_tension(ffg, v_kt, u_kt, heading_deg, 0.0, m).total_n,
                sweep::calculated_mean_tension(ffg, v_kt, u_kt, 180.0, 0.0, m).total_n);
    }
  }
  // With the wind along the wave heading, a following 20 kt wind at 5 kt pushes (V_R = -15 kt).
  m.wind = sweep::MeanTensionWind::kHeading;
  const auto following = sweep::calculated_mean_tension(ffg, v_kt, 20.0, 0.0, 0.0, m);
  EXPECT_LT(following.wind_n, 0.0);
  EXPECT_REL_CLOSE(units::n_to_lbf(following.wind_n), -0.00506 * 0.85 * a_t_ft2 * 15.0 * 15.0, kNavyConstantRelTol);
}

TEST(SweepMeanTension, SpeedReduction) {  // sweep-tension-4
  // EVIDENCE-OF: EQ-SWEEP-3
  sweep::MeanTensionModel m;  // limit 125,000 lbf, 1 kt steps, 3 kt minimum
  auto quadratic = [](double v_kt) { return 2000.0 * v_kt * v_kt; };  // 162,000 lbf at 9 kt
  std::string reason;
  auto chosen = sweep::choose_speed(9.0, m, quadratic, &reason);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_EQ(chosen->speed_kt, 7.0);  // 8 kt: 128,000 > limit; 7 kt: 98,000
  EXPECT_TRUE(chosen->reduced);
  EXPECT_EQ(chosen->calculated_lbf, 98000.0);
  chosen = sweep::choose_speed(5.0, m, quadratic, &reason);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_EQ(chosen->speed_kt, 5.0);
  EXPECT_FALSE(chosen->reduced);
  m.speed_step_kt = 0.5;
  EXPECT_EQ(sweep::choose_speed(9.0, m, quadratic, &reason)->speed_kt, 7.5);  // 112,500 lbf
  m.speed_step_kt = 1.0;
  m.min_speed_kt = 8.0;
  EXPECT_FALSE(sweep::choose_speed(9.0, m, quadratic, &reason).has_value());
  EXPECT_NE(reason.find("exceeds 125000 lbf even at the lowest speed tried (8 kt)"), std::string::npos) << reason;

  // LHA 1 in a 35 kt head wind (thesis ch. 5: too heavy for the tugs at 9 kt).
  const model::Vessel& lha = catalog().vessel("LHA 1").vessel;
  sweep::MeanTensionModel thesis;
  auto t_calc = [&](double v_kt) {
    return units::n_to_lbf(sweep::calculated_mean_tension(lha, v_kt, 35.0, 180.0, 0.0, thesis).total_n);
  };
  ASSERT_GT(t_calc(9.0), 125000.0);
  const auto lha_choice = sweep::choose_speed(9.0, thesis, t_calc, &reason);
  if (lha_choice) {
    EXPECT_TRUE(lha_choice->reduced);
    EXPECT_LE(lha_choice->calculated_lbf, 125000.0);
    EXPECT_GT(t_calc(lha_choice->speed_kt + 1.0), 125000.0);
  } else {
    EXPECT_GT(t_calc(3.0), 125000.0);
  }
}

}  // namespace
}  // namespace towdb::test
