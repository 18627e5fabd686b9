// Tug propeller surge damping at constant RPM (thesis 3.6; EQ-PROPULSION-4,
// -5 and -6 in propulsion/propulsion.hpp), and the total surge damping of
// the tug (hull + propellers).
//
// Inputs: the tug (model::Vessel with Propellers: count, diameter [m],
// blades, A_E/A_0, rpm_max [rpm], wake_fraction, thrust_deduction), the
// towing speed V [m/s] and the mean towline tension [N].
// Outputs: thrust [N], torque [N m], power [W], damping [N s/m].
//
// Model notes: the B-series describes open propellers; the T-ATF's and ARS
// 50's propellers run in Kort nozzles (a Ka-series model would fit them
// better). The thesis used the B-series anyway, and so does towdb.
#ifndef TOWDB_PROPULSION_TUG_PROPELLER_HPP
#define TOWDB_PROPULSION_TUG_PROPELLER_HPP

#include "common/units.hpp"
#include "model/vessel.hpp"
#include "propulsion/bseries.hpp"
#include "propulsion/hull_damping.hpp"

namespace towdb::propulsion {

// How many propellers' damping acts on the tug's surge.
enum class PropellerDampingShare {
  kOnePropeller,   // one propeller's damping (thesis 3.6: conservative, default)
  kAllPropellers,  // every propeller's: N_p times one
};

struct TugPropellerDampingOptions {
  // n = rpm_fraction * rpm_max (thesis 3.6 step 1: 80 % of the maximum).
  double rpm_fraction = 0.8;
  // Speed step of the thrust difference [m/s] (thesis step 8: 1 ft/s);
  // 0 selects the analytic derivative -rho n D^3 (1 - w) dK_T/dJ.
  double speed_step_m_s = units::ft_s_to_m_s(1.0);
  // Whose damping acts on the tug (thesis: one propeller).
  PropellerDampingShare share = PropellerDampingShare::kOnePropeller;
  // Floor of the returned damping [N s/m] (thesis: "a small positive
  // value"; its value is not given). 1000 N s/m = 68.5 lbf s/ft, about 7 %
  // of the T-ATF's hull damping at 10 ft/s: small against both terms.
  double damping_floor_n_s_m = 1000.0;
  // Multiplies the tug's own drag-curve resistance in the thrust balance
  // (thesis: the bare drag file, 1.0).
  double tug_resistance_factor = 1.0;
  // Divide the required thrust by (1 - t) (false: thesis, thrust = resistance).
  bool apply_thrust_deduction = false;
  // Pitch-ratio search range (the B-series range, 0.5 to 1.4).
  double pitch_ratio_min = kBSeriesPitchRatioMin;
  double pitch_ratio_max = kBSeriesPitchRatioMax;

  // Throws InputError naming the field: rpm_fraction in (0, 1.2],
  // speed_step_m_s in [0, 5], damping_floor_n_s_m in [0, 1e7],
  // tug_resistance_factor in [0.5, 2], pitch range inside [0.5, 1.4].
  void validate() const;
};

enum class PropellerSolveStatus {
  kSolved,                 // P/D found inside the series range
  kPitchBelowSeriesRange,  // even P/D = min gives more thrust: P/D held at min
  kThrustExceedsCapacity,  // P/D = max cannot give the thrust: damping = floor
};

const char* to_string(PropellerSolveStatus status);

struct TugPropellerDamping {
  PropellerSolveStatus status = PropellerSolveStatus::kSolved;
  bool floored = false;                       // the returned damping is the floor
  double rev_per_s = 0.0;                     // n
  double advance_ratio = 0.0;                 // J at V
  double required_thrust_per_propeller_n = 0.0;
  double max_thrust_per_propeller_n = 0.0;    // at P/D = pitch_ratio_max
  double pitch_ratio = 0.0;                   // solved (or clamped) P/D
  double kt = 0.0;                            // K_T at (J, P/D)
  double kq = 0.0;                            // K_Q at (J, P/D)
  double thrust_per_propeller_n = 0.0;        // rho n^2 D^4 K_T
  double torque_per_propeller_n_m = 0.0;      // rho n^2 D^5 K_Q
  double delivered_power_w = 0.0;             // all propellers: N_p 2 pi n Q
  double damping_per_propeller_n_s_m = 0.0;   // -dT/dV of one propeller, before the floor
  double damping_n_s_m = 0.0;                 // the share, then the floor: what the surge equation uses
};

// Constant-RPM propeller damping of the tug at speed V [m/s] while it pulls
// the mean towline tension [N] (EQ-PROPULSION-5, -6). Throws InputError for
// a vessel without propellers or a blade count / area ratio outside the
// series, NumericalError if the pitch solve fails.
TugPropellerDamping tug_propeller_damping(const model::Vessel& tug, double speed_m_s,
                                          double mean_tension_n,
                                          const TugPropellerDampingOptions& options = {});

// The tug's hull damping plus its propeller damping (thesis 3.3).
SurgeDamping tug_surge_damping(const model::Vessel& tug, double speed_m_s, double mean_tension_n,
                               const HullDampingOptions& hull_options = {},
                               const TugPropellerDampingOptions& propeller_options = {});

}  // namespace towdb::propulsion

#endif  // TOWDB_PROPULSION_TUG_PROPELLER_HPP
