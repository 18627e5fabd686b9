// Tests of the 12-DOF coupled model (generator/coupled).
//   coupled-1  zero towline stiffness and damping: the 12-DOF answer equals the
//              two separate 6-DOF strip-theory answers (issue "Vessel
//              hydrodynamics", verification).
//   coupled-2  the extension vector: signs and lever arms of EQ-COUPLED-1.
//   coupled-3  the line couples the vessels: with a line, the tow's wave moves
//              the tug, and xi_ns is split exactly as P + Q e^{ikG cos mu}.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "common/units.hpp"
#include "coupled/coupled.hpp"
#include "io/ship_file.hpp"
#include "test_support.hpp"

namespace towdb::coupled {
namespace {

const io::ShipCatalog& catalog() {
  static const io::ShipCatalog cat = io::ShipCatalog::load(test::source_dir() / "ships");
  return cat;
}

LineGeometry geometry_for(const model::Vessel& tug, const model::Vessel& tow) {
  LineGeometry g;
  g.tug_angle_rad = 0.12;
  g.tow_angle_rad = 0.25;
  g.tug_point = tug.tow_point;
  g.tow_point = tow.tow_point;
  g.separation_m = 600.0;
  return g;
}

std::vector<double> omegas() { return {0.3, 0.5, 0.7, 0.9, 1.2}; }

TEST(Coupled, ZeroLineGivesTheSeparateSixDofAnswers) {  // coupled-1, EVIDENCE-OF: EQ-COUPLED-3
  const model::Vessel& tug = catalog().vessel("T-ATF").vessel;
  const model::Vessel& tow = catalog().vessel("FFG 7").vessel;
  const double u = units::kt_to_m_s(9.0);
  for (double heading_deg : {0.0, 60.0, 180.0}) {
    const double mu = units::deg_to_rad(heading_deg);
    const auto r_tug = seakeeping::compute_response(tug, u, mu, omegas());
    const auto r_tow = seakeeping::compute_response(tow, u, mu, omegas());
    const auto c = couple(r_tug, r_tow, geometry_for(tug, tow), LinearLine{0.0, 0.0}, SurgeDampings{0.0, 0.0});
    ASSERT_EQ(c.size(), omegas().size());
    for (std::size_t i = 0; i < c.size(); ++i) {
      for (int d = 0; d < 6; ++d) {
        // Same 6x6 solve either way: agreement to round-off of the LU factorisation.
        const double scale_tug = std::abs(r_tug[i].rao[d]) + 1e-12;
        const double scale_tow = std::abs(r_tow[i].rao[d]) + 1e-12;
        EXPECT_LT(std::abs(c[i].motion_p[d] - r_tug[i].rao[d]), 1e-8 * scale_tug) << heading_deg << " " << i << " " << d;
        EXPECT_LT(std::abs(c[i].motion_q[6 + d] - r_tow[i].rao[d]), 1e-8 * scale_tow) << heading_deg << " " << i << " " << d;
        EXPECT_EQ(c[i].motion_p[6 + d], std::complex<double>(0.0, 0.0));
        EXPECT_EQ(c[i].motion_q[d], std::complex<double>(0.0, 0.0));
      }
    }
  }
}

TEST(Coupled, ExtensionVectorSignsAndLevers) {  // coupled-2, EVIDENCE-OF: EQ-COUPLED-1
  LineGeometry g;
  g.tug_angle_rad = 0.1;
  g.tow_angle_rad = 0.3;
  g.tug_point = {-30.0, 2.0};
  g.tow_point = {60.0, 8.0};
  g.separation_m = 500.0;
  const Vector12d s = extension_vector(g);
  // Tug surging forward and tow surging aft both stretch the line.
  EXPECT_DOUBLE_EQ(s[0], std::cos(0.1));
  EXPECT_DOUBLE_EQ(s[6], -std::cos(0.3));
  // Raising either fitting stretches a sagging line.
  EXPECT_GT(s[2], 0.0);
  EXPECT_GT(s[8], 0.0);
  // Tug pitch bow down (+) raises its stern fitting (x < 0): u_z = -x_p eta5 > 0,
  // and moves a fitting above the waterline forward: u_x = z_p eta5 > 0. Both stretch.
  EXPECT_DOUBLE_EQ(s[4], 2.0 * std::cos(0.1) + 30.0 * std::sin(0.1));
  // Tow pitch bow down lowers its bow fitting (slackens) and moves it forward (slackens).
  EXPECT_DOUBLE_EQ(s[10], -8.0 * std::cos(0.3) - 60.0 * std::sin(0.3));
  // Sway, roll, yaw do not stretch an in-line towline to first order.
  for (int d : {1, 3, 5, 7, 9, 11}) EXPECT_EQ(s[d], 0.0);
  const Vector12d ns = non_surge_extension_vector(g);
  EXPECT_EQ(ns[0], 0.0);
  EXPECT_EQ(ns[6], 0.0);
  EXPECT_EQ(ns[2], s[2]);
}

TEST(Coupled, LineCouplesTheVessels) {  // coupled-3
  const model::Vessel& tug = catalog().vessel("T-ATF").vessel;
  const model::Vessel& tow = catalog().vessel("FFG 7").vessel;
  const double u = units::kt_to_m_s(5.0), mu = kPi;
  const auto r_tug = seakeeping::compute_response(tug, u, mu, omegas());
  const auto r_tow = seakeeping::compute_response(tow, u, mu, omegas());
  const LineGeometry g = geometry_for(tug, tow);
  const auto c = couple(r_tug, r_tow, g, LinearLine{3.0e5, 2.0e4}, SurgeDampings{2.0e4, 5.0e4});
  for (const auto& r : c) {
    // The tow's wave now moves the tug (through the line), in surge above all.
    EXPECT_GT(std::abs(r.motion_q[0]), 0.0);
    // xi_ns is S_ns . x for each part.
    const Vector12d s_ns = non_surge_extension_vector(g);
    std::complex<double> p(0, 0), q(0, 0);
    for (int d = 0; d < 12; ++d) {
      p += s_ns[d] * r.motion_p[d];
      q += s_ns[d] * r.motion_q[d];
    }
    EXPECT_LT(std::abs(p - r.xi_ns_p), 1e-12 * (std::abs(p) + 1e-30));
    EXPECT_LT(std::abs(q - r.xi_ns_q), 1e-12 * (std::abs(q) + 1e-30));
    // Head seas: drift coefficients are resistances (> 0) on both vessels.
    EXPECT_GT(r.drift_tug_n_per_m2, 0.0);
    EXPECT_GT(r.drift_tow_n_per_m2, 0.0);
  }
}

}  // namespace
}  // namespace towdb::coupled
