// Closed-form limits of the static multi-segment elastic catenary
// (towdb::towline, towline/towline.hpp EQ-TOWLINE-1..5).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "test_support.hpp"
#include "towline/catenary.hpp"
#include "towline_test_lines.hpp"

namespace towdb::towline {
namespace {

// Closed forms evaluated in double precision against a solver closed to
// 1e-12 of the line length: 1e-9 relative leaves room for the asinh/cosh
// conditioning of a moderately deep catenary.
constexpr double kClosedFormRelTol = 1e-9;
// "Inextensible" here means EA = 1e15 N, so H/EA ~ 1e-10 is left in the span.
constexpr double kInextensibleRelTol = 1e-8;
// Splitting a segment only regroups floating-point sums.
constexpr double kSplitRelTol = 1e-11;

model::TowlineComponent uniform_component(double ea_n, double w_n_m) {
  model::TowlineComponent c;
  c.name = "uniform";
  c.ea_n = ea_n;
  c.hydrodynamic_diameter_m = 0.05;
  c.mass_per_length_kg_m = 10.0;
  c.weight_in_water_n_m = w_n_m;
  c.breaking_strength_n = 1e7;
  c.drag_coefficient_normal = 1.0;
  c.added_mass_coefficient = 1.0;
  return c;
}

model::Towline single(double ea_n, double w_n_m, double length_m) {
  model::Towline t;
  t.segments.push_back({uniform_component(ea_n, w_n_m), length_m});
  return t;
}

// EVIDENCE-OF: EQ-TOWLINE-2
// EVIDENCE-OF: EQ-TOWLINE-3
// Level ends, inextensible: X = (2H/w) asinh(wL/2H), sag = (H/w)(cosh(wX/2H) - 1),
// end angle atan(wL/2H) (Irvine 1981, eqs. 1.5-1.8).
TEST(TowlineCatenary, InextensibleLevelLimitIsTheClassicalCatenary) {
  const double w = 100.0, l = 600.0;
  for (double h : {2e3, 1e4, 1e5}) {
    const Catenary cat = Catenary::solve(single(1e15, w, l), {5.0, 5.0}, h);
    const double span = 2.0 * h / w * std::asinh(w * l / (2.0 * h));
    EXPECT_REL_CLOSE(cat.span_m(), span, kInextensibleRelTol);
    EXPECT_REL_CLOSE(cat.sag_m(), h / w * (std::cosh(w * span / (2.0 * h)) - 1.0), kInextensibleRelTol);
    EXPECT_REL_CLOSE(cat.tug_angle_rad(), std::atan(w * l / (2.0 * h)), kInextensibleRelTol);
    EXPECT_REL_CLOSE(cat.tow_angle_rad(), cat.tug_angle_rad(), kInextensibleRelTol);
    EXPECT_REL_CLOSE(cat.lowest_elevation_m(), 5.0 - cat.sag_m(), kInextensibleRelTol);
    EXPECT_REL_CLOSE(cat.min_tension_n(), h, kClosedFormRelTol);
  }
}

// EVIDENCE-OF: EQ-TOWLINE-3
// Unequal heights, inextensible: L^2 - dh^2 = (2H/w)^2 sinh^2(w X / 2H).
TEST(TowlineCatenary, InextensibleInclinedLimitSatisfiesTheLengthIdentity) {
  const double w = 50.0, l = 500.0, dh = 40.0;
  for (double h : {1e3, 2e4, 5e5}) {
    const Catenary cat = Catenary::solve(single(1e15, w, l), {2.0, 2.0 + dh}, h);
    const double chord_len = 2.0 * h / w * std::sinh(w * cat.span_m() / (2.0 * h));
    EXPECT_REL_CLOSE(std::sqrt(l * l - dh * dh), chord_len, kInextensibleRelTol);
  }
}

// EVIDENCE-OF: EQ-TOWLINE-2
// Elastic, level ends (Irvine 1981 eq. 2.9): X = (2H/w) asinh(wL/2H) + H L/EA.
TEST(TowlineCatenary, ElasticLevelSpanMatchesIrvine) {
  const double w = 80.0, l = 600.0, ea = 5e7;
  for (double h : {5e3, 1e5, 6e5}) {
    const Catenary cat = Catenary::solve(single(ea, w, l), {3.0, 3.0}, h);
    EXPECT_REL_CLOSE(cat.span_m(), 2.0 * h / w * std::asinh(w * l / (2.0 * h)) + h * l / ea, kClosedFormRelTol);
    // Stretched length: L + (1/EA) int T ds.
    const double stretched = l + h * l / ea * 0.5 *
                                     (std::sqrt(1.0 + std::pow(w * l / (2.0 * h), 2)) +
                                      std::asinh(w * l / (2.0 * h)) * 2.0 * h / (w * l));
    EXPECT_REL_CLOSE(cat.stretched_length_m(), stretched, kClosedFormRelTol);
  }
}

// EVIDENCE-OF: EQ-TOWLINE-4
// Weightless line = straight spring: T = H C/X, C = L + T sum L_i/EA_i, and at
// level ends dH/dX = 1 / sum L_i/EA_i exactly (two segments).
TEST(TowlineCatenary, TautWeightlessLimitIsAStraightSpring) {
  model::Towline t;
  t.segments.push_back({uniform_component(2e7, 0.0), 400.0});
  t.segments.push_back({uniform_component(9e8, 0.0), 30.0});
  const double compliance = 400.0 / 2e7 + 30.0 / 9e8;
  const Catenary level = Catenary::solve(t, {4.0, 4.0}, 3e5);
  EXPECT_REL_CLOSE(level.span_m(), 430.0 + 3e5 * compliance, kClosedFormRelTol);
  EXPECT_REL_CLOSE(level.static_stiffness_n_m(), 1.0 / compliance, kClosedFormRelTol);
  EXPECT_ABS_CLOSE(level.sag_m(), 0.0, 1e-9);  // [m] straight line

  const Catenary inclined = Catenary::solve(t, {2.0, 10.0}, 3e5);
  const double chord = inclined.chord_m();
  const double tension = 3e5 * chord / inclined.span_m();
  EXPECT_REL_CLOSE(chord, 430.0 + tension * compliance, kClosedFormRelTol);
  EXPECT_REL_CLOSE(inclined.tug_tension_n(), tension, kClosedFormRelTol);
}

// EVIDENCE-OF: EQ-TOWLINE-1
// Splitting a segment into two identical pieces changes nothing.
TEST(TowlineCatenary, SplittingASegmentChangesNothing) {
  const model::Towline whole = test::thesis_towline("wire", 2000.0);
  model::Towline split;
  split.segments.push_back({whole.segments[0].component, units::ft_to_m(1234.5)});
  split.segments.push_back({whole.segments[0].component, units::ft_to_m(765.5)});
  split.segments.push_back(whole.segments[1]);
  for (double lbf : {2000.0, 20500.0, 150000.0}) {
    const Catenary a = Catenary::solve(whole, test::thesis_tow_points(), units::lbf_to_n(lbf));
    const Catenary b = Catenary::solve(split, test::thesis_tow_points(), units::lbf_to_n(lbf));
    EXPECT_REL_CLOSE(b.span_m(), a.span_m(), kSplitRelTol);
    EXPECT_REL_CLOSE(b.sag_m(), a.sag_m(), kSplitRelTol);
    EXPECT_REL_CLOSE(b.tug_angle_rad(), a.tug_angle_rad(), kSplitRelTol);
    EXPECT_REL_CLOSE(b.tow_angle_rad(), a.tow_angle_rad(), kSplitRelTol);
    EXPECT_REL_CLOSE(b.static_stiffness_n_m(), a.static_stiffness_n_m(), kSplitRelTol);
    const double s = units::ft_to_m(1500.0);
    EXPECT_REL_CLOSE(b.point_at(s).y_m, a.point_at(s).y_m, kSplitRelTol);
  }
}

// EVIDENCE-OF: EQ-TOWLINE-4
// The analytic dH/dX equals a central difference of the solved span X(H).
TEST(TowlineCatenary, StaticStiffnessEqualsFiniteDifferenceOfSpan) {
  // Central difference with dH = 1e-4 H: truncation ~1e-8, roundoff
  // ~1e-12 * X / (1e-4 dX) -> 1e-6 relative is safe.
  constexpr double kFiniteDifferenceRelTol = 1e-6;
  for (const char* hawser : {"wire", "nylon"}) {
    const model::Towline t = test::thesis_towline(hawser, 1500.0);
    for (double lbf : {2000.0, 10000.0, 60000.0, 150000.0}) {
      const double h = units::lbf_to_n(lbf);
      const double dh = 1e-4 * h;
      const Catenary c0 = Catenary::solve(t, test::thesis_tow_points(), h);
      const Catenary cp = Catenary::solve(t, test::thesis_tow_points(), h + dh);
      const Catenary cm = Catenary::solve(t, test::thesis_tow_points(), h - dh);
      EXPECT_REL_CLOSE(c0.static_stiffness_n_m(), 2.0 * dh / (cp.span_m() - cm.span_m()),
                       kFiniteDifferenceRelTol)
          << hawser << " at " << lbf << " lbf";
      const auto f = c0.flexibility_m_n();
      EXPECT_REL_CLOSE(f[0][1], f[1][0], 1e-14);  // Maxwell reciprocity (same expression)
    }
  }
}

// EVIDENCE-OF: EQ-TOWLINE-4
// Shallow single segment: 1/k = L/EA + w^2 L^3 / (12 H^3) (Irvine 1981 eq. 2.37
// linearised); sag/span = wL/8H = 1/800 here and both terms are of the same
// size, so the parabolic formula holds to O((sag/span)^2).
TEST(TowlineCatenary, ShallowStiffnessMatchesTheParabolicCable) {
  constexpr double kShallowRelTol = 1e-4;  // O((sag/span)^2) and O(H/EA) terms
  const double w = 2.0, l = 500.0, ea = 4e9, h = 1e5;
  const Catenary cat = Catenary::solve(single(ea, w, l), {1.0, 1.0}, h);
  EXPECT_REL_CLOSE(cat.static_stiffness_n_m(), 1.0 / (l / ea + w * w * l * l * l / (12.0 * h * h * h)),
                   kShallowRelTol);
}

// EVIDENCE-OF: EQ-TOWLINE-5
// Curvature = d(slope)/dp, checked by a central difference along the line.
TEST(TowlineCatenary, CurvatureIsTheSlopeDerivative) {
  constexpr double kDifferenceRelTol = 1e-6;  // ds = 0.01 m on a 500 m scale
  const Catenary cat = Catenary::solve(test::thesis_towline("wire", 1000.0), test::thesis_tow_points(),
                                       units::lbf_to_n(10000.0));
  for (double s : {50.0, 200.0, 300.0}) {
    const double ds = 0.01;
    const CatenaryPoint a = cat.point_at(s - ds), b = cat.point_at(s + ds), m = cat.point_at(s);
    EXPECT_REL_CLOSE(m.curvature_1_m, (b.slope_rad - a.slope_rad) / (b.p_m - a.p_m), kDifferenceRelTol);
  }
}

// EVIDENCE-OF: EQ-TOWLINE-3
// The bracketed solver converges from a slack wire at 2,000 lbf to a nearly
// straight fiber line at 150,000 lbf (the thesis's solver failed there): the
// end point lands on the tow's fitting and the span grows with tension.
TEST(TowlineCatenary, ConvergesFromSlackWireToTautFiber) {
  constexpr double kEndPointAbsTol_m = 1e-8;
  const towline::TowPoints pts = test::thesis_tow_points();
  for (const char* hawser : {"wire", "nylon"}) {
    for (double length_ft : {800.0, 1500.0, 2000.0}) {
      const model::Towline t = test::thesis_towline(hawser, length_ft);
      double previous_span = 0.0;
      for (int k = 0; k <= 40; ++k) {
        const double lbf = 2000.0 * std::pow(75.0, k / 40.0);  // 2,000 .. 150,000 lbf
        const Catenary cat = Catenary::solve(t, pts, units::lbf_to_n(lbf));
        const CatenaryPoint end = cat.point_at(cat.unstretched_length_m());
        EXPECT_ABS_CLOSE(end.y_m, pts.tow_height_m, kEndPointAbsTol_m);
        EXPECT_ABS_CLOSE(end.x_m, cat.span_m(), kEndPointAbsTol_m);
        EXPECT_GT(cat.span_m(), previous_span) << hawser << " " << length_ft << " ft at " << lbf << " lbf";
        previous_span = cat.span_m();
      }
    }
  }
}

}  // namespace
}  // namespace towdb::towline
