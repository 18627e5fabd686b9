// Programmatic hulls for the seakeeping tests (closed-form offsets, no ship
// files): Journee's Wigley hull family.
//
// Wigley hull (Journee 1992, TU Delft report 0909): half breadth
//   y = (B/2) [(1 - zeta^2)(1 - xi^2)(1 + 0.2 xi^2) + alpha zeta^2 (1 - zeta^8)(1 - xi^2)^4],
//   xi = 2x/L, zeta = depth/d. Station waterline beam B (1 - xi^2)(1 + 0.2 xi^2),
//   draft d, area coefficient sigma = 2/3 + alpha (8/33)(1 - xi^2)^3 / (1 + 0.2 xi^2)
//   (integrals of the offsets; alpha = 1 gives C_b = 0.561 of Wigley I).
#ifndef TOWDB_TESTS_SUPPORT_SEAKEEPING_HULLS_HPP
#define TOWDB_TESTS_SUPPORT_SEAKEEPING_HULLS_HPP

#include <cmath>

#include "common/constants.hpp"
#include "model/vessel.hpp"

namespace towdb::test {

struct WigleyParticulars {
  double length_m = 3.0;      // Wigley I model: L = 3 m
  double beam_m = 0.3;        // B = 0.3 m
  double draft_m = 0.1875;    // d = 0.1875 m
  double alpha = 1.0;         // 1 for Wigley I and II, 0 for III and IV
  double kg_m = 0.17;         // not given in the report summary used; affects only C55 slightly
  double gm_m = 0.05;         // assumed (roll only)
  double kyy_over_l = 0.25;   // Journee: k_yy = 0.75 m = 0.25 L
  int stations = 41;
};

inline model::Vessel wigley_vessel(const WigleyParticulars& p = {}) {
  model::Vessel v;
  v.name = "Wigley";
  model::Hull& h = v.hull;
  h.length_pp_m = p.length_m;
  h.length_overall_m = p.length_m;
  h.beam_m = p.beam_m;
  h.draft_m = p.draft_m;
  for (int i = 0; i < p.stations; ++i) {
    const double xi = -1.0 + 2.0 * i / (p.stations - 1);
    model::Station s;
    s.x_m = 0.5 * xi * p.length_m;
    const double f = (1.0 - xi * xi) * (1.0 + 0.2 * xi * xi);
    if (f > 0.0 && i > 0 && i + 1 < p.stations) {
      s.beam_m = p.beam_m * f;
      s.draft_m = p.draft_m;
      s.area_coefficient = 2.0 / 3.0 + p.alpha * (8.0 / 33.0) * std::pow(1.0 - xi * xi, 3) / (1.0 + 0.2 * xi * xi);
    }
    h.stations.push_back(s);
  }
  // Volume: B d L/2 [ (2/3) int (1-xi^2)(1+0.2xi^2) dxi + alpha (8/33) int (1-xi^2)^4 dxi ]
  // with the integrals over [-1, 1] equal to 104/75 and 256/315.
  const double volume = p.beam_m * p.draft_m * 0.5 * p.length_m *
                        ((2.0 / 3.0) * (104.0 / 75.0) + p.alpha * (8.0 / 33.0) * (256.0 / 315.0));
  h.displacement_kg = kRhoSeawater_kg_m3 * volume;
  h.kg_m = p.kg_m;
  h.gm_m = p.gm_m;
  h.radius_gyration_roll_m = 0.4 * p.beam_m;
  h.radius_gyration_pitch_m = p.kyy_over_l * p.length_m;
  h.radius_gyration_yaw_m = p.kyy_over_l * p.length_m;
  h.roll_damping_ratio = 0.05;
  h.surge_added_mass_ratio = 0.05;
  h.wetted_surface_m2 = 1.0;
  return v;
}

}  // namespace towdb::test

#endif  // TOWDB_TESTS_SUPPORT_SEAKEEPING_HULLS_HPP
