// Hull resistance and hull surge damping from a vessel's drag curve
// (EQ-PROPULSION-1 and EQ-PROPULSION-2 in propulsion/propulsion.hpp).
//
// Inputs: a model::Vessel (wetted surface [m^2], C_T(V) table [-]) and the
// speed V [m/s], V >= 0. Outputs: resistance [N], damping [N s/m].
#ifndef TOWDB_PROPULSION_HULL_DAMPING_HPP
#define TOWDB_PROPULSION_HULL_DAMPING_HPP

#include "model/vessel.hpp"

namespace towdb::propulsion {

// Which slope of the piecewise-linear C_T(V) to use at a tabulated speed.
enum class KinkRule {
  kAverage,     // mean of the lower- and upper-speed segment slopes (default)
  kLowerSpeed,  // slope of the segment below the tabulated speed
  kUpperSpeed,  // slope of the segment above it
};

struct HullDampingOptions {
  // Multiplies R(V) and hence dR/dV: 1 + margin. The thesis's damping is
  // the slope of the bare drag file (1.0); the mean tension applies its own
  // margin separately (MeanTensionOptions::hull_margin).
  double resistance_factor = 1.0;
  // Slope rule at the kinks of the piecewise-linear C_T table.
  KinkRule kink_rule = KinkRule::kAverage;
  // 0: analytic derivative (EQ-PROPULSION-2). > 0 [m/s]: forward difference
  // (R(V + dV) - R(V)) / dV, as the thesis's programs stepped V.
  double speed_step_m_s = 0.0;

  // Throws InputError naming the field: resistance_factor in [0.5, 2],
  // speed_step_m_s in [0, 5] m/s.
  void validate() const;
};

// Surge damping of one vessel, split by origin [N s/m].
struct SurgeDamping {
  double hull_n_s_m = 0.0;
  double propeller_n_s_m = 0.0;
  double total_n_s_m = 0.0;
};

// dC_T/dV [s/m] of the vessel's drag table at V [m/s] (0 outside the table),
// with the kink rule at tabulated speeds.
double drag_coefficient_slope_s_m(const model::DragCurve& drag, double speed_m_s, KinkRule rule);

// R_H(V) [N] = factor * (1/2) rho S V^2 C_T(V) (EQ-PROPULSION-1). V >= 0.
double hull_resistance_n(const model::Vessel& vessel, double speed_m_s, double resistance_factor = 1.0);

// B_H = dR_H/dV [N s/m] (EQ-PROPULSION-2). V >= 0.
double hull_damping_n_s_m(const model::Vessel& vessel, double speed_m_s,
                          const HullDampingOptions& options = {});

}  // namespace towdb::propulsion

#endif  // TOWDB_PROPULSION_HULL_DAMPING_HPP
