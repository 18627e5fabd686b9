// The towed ship's propeller drag and its surge damping (EQ-PROPULSION-7,
// -8 and -9 in propulsion/propulsion.hpp; thesis ch. 2 and future work item
// 4 of section 6.1), and the tow's total surge damping.
//
// Inputs: the tow (model::Vessel; its Propellers give count, diameter [m],
// A_E/A_0, design P/D and wake fraction), the tow speed V [m/s].
// Outputs: drag [N] (> 0, aft), damping [N s/m].
#ifndef TOWDB_PROPULSION_TOW_PROPELLER_HPP
#define TOWDB_PROPULSION_TOW_PROPELLER_HPP

#include "model/vessel.hpp"
#include "propulsion/hull_damping.hpp"

namespace towdb::propulsion {

enum class TowPropellerState {
  kLocked,        // shaft locked: full drag (Towing Manual default)
  kFreeSpinning,  // windmilling: free_spinning_fraction of the locked drag
  kRemoved,       // no propeller drag
};

enum class LockedPropellerDragModel {
  kNavyProjectedArea,      // eq. 2.5 at ship speed, as the Towing Manual prints it
  kNavyProjectedAreaWake,  // eq. 2.5 at V (1 - w): the thesis's ch. 2 calculation
  kDiskArea,               // eq. 2.4 at ship speed (over-estimates, thesis ch. 2)
  kDiskAreaWake,           // eq. 2.4 at V (1 - w), as the thesis recommends
};

const char* to_string(TowPropellerState state);
const char* to_string(LockedPropellerDragModel model);

struct TowPropellerOptions {
  // Locked, free-spinning or removed (Towing Manual mean tension: locked).
  TowPropellerState state = TowPropellerState::kLocked;
  // Which locked-drag formula (Towing Manual: projected area at ship speed).
  LockedPropellerDragModel model = LockedPropellerDragModel::kNavyProjectedArea;
  // C_DP on the projected area: 2 * 3.737 / (1.9905 * 1.68781^2), i.e. the
  // Navy's 3.737 lbf/(ft^2 kt^2) in sea water (EQ-PROPULSION-7).
  double projected_area_drag_coefficient = 1.3181;
  // C_D on the disk area: a bluff disk (Hoerner 1965; thesis eq. 2.4).
  double disk_drag_coefficient = 1.17;
  // Fraction of the locked drag when free-spinning (Towing Manual: one half).
  double free_spinning_fraction = 0.5;
  // Total projected area of all propellers [m^2]; 0 = from the geometry,
  // N_p (pi D^2/4) (A_E/A_0) (1.067 - 0.229 P/D) (UFC 4-159-03 eq. 4-22).
  double projected_area_m2 = 0.0;

  // Throws InputError naming the field: coefficients in [0.3, 3],
  // free_spinning_fraction in [0, 1], projected_area_m2 in [0, 1000].
  void validate() const;
};

// Total projected area of the vessel's propellers [m^2] (EQ-PROPULSION-7),
// 0 for a vessel without propellers.
double propeller_projected_area_m2(const model::Vessel& vessel);

// R_P [N] of the tow's propellers at V [m/s] >= 0 (EQ-PROPULSION-7..9);
// 0 without propellers or when removed.
double tow_propeller_drag_n(const model::Vessel& tow, double speed_m_s, const TowPropellerOptions& options = {});

// dR_P/dV = 2 R_P / V [N s/m] (EQ-PROPULSION-9); at V = 0 the analytic
// limit 2 R_P / V -> 0 (the drag is quadratic).
double tow_propeller_damping_n_s_m(const model::Vessel& tow, double speed_m_s,
                                   const TowPropellerOptions& options = {});

// The tow's hull damping plus its propeller damping. The thesis's 12D model
// left the tow's propeller out: pass TowPropellerState::kRemoved to match it.
SurgeDamping tow_surge_damping(const model::Vessel& tow, double speed_m_s, const HullDampingOptions& hull_options,
                               const TowPropellerOptions& propeller_options);

}  // namespace towdb::propulsion

#endif  // TOWDB_PROPULSION_TOW_PROPELLER_HPP
