#include "propulsion/tow_propeller.hpp"

#include <cmath>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::propulsion {

namespace {

// Projected-to-expanded area ratio A_P/A_E = 1.067 - 0.229 P/D
// (UFC 4-159-03 eq. 4-22): 0.838 at P/D = 1.
double projected_to_expanded_ratio(double pitch_ratio) { return 1.067 - 0.229 * pitch_ratio; }

double disk_area_m2(const model::Propellers& p) {
  return static_cast<double>(p.count) * kPi * p.diameter_m * p.diameter_m / 4.0;
}

bool uses_wake(LockedPropellerDragModel model) {
  return model == LockedPropellerDragModel::kNavyProjectedAreaWake ||
         model == LockedPropellerDragModel::kDiskAreaWake;
}

}  // namespace

const char* to_string(TowPropellerState state) {
  switch (state) {
    case TowPropellerState::kLocked:
      return "locked";
    case TowPropellerState::kFreeSpinning:
      return "free_spinning";
    case TowPropellerState::kRemoved:
      return "removed";
  }
  return "unknown";
}

const char* to_string(LockedPropellerDragModel model) {
  switch (model) {
    case LockedPropellerDragModel::kNavyProjectedArea:
      return "navy_projected_area";
    case LockedPropellerDragModel::kNavyProjectedAreaWake:
      return "navy_projected_area_wake";
    case LockedPropellerDragModel::kDiskArea:
      return "disk_area";
    case LockedPropellerDragModel::kDiskAreaWake:
      return "disk_area_wake";
  }
  return "unknown";
}

void TowPropellerOptions::validate() const {
  require_in_range("TowPropellerOptions.projected_area_drag_coefficient", projected_area_drag_coefficient, 0.3,
                   3.0);
  require_in_range("TowPropellerOptions.disk_drag_coefficient", disk_drag_coefficient, 0.3, 3.0);
  require_in_range("TowPropellerOptions.free_spinning_fraction", free_spinning_fraction, 0.0, 1.0);
  require_in_range("TowPropellerOptions.projected_area_m2", projected_area_m2, 0.0, 1000.0);
}

double propeller_projected_area_m2(const model::Vessel& vessel) {
  if (!vessel.propellers) return 0.0;
  const model::Propellers& p = *vessel.propellers;
  return disk_area_m2(p) * p.expanded_area_ratio * projected_to_expanded_ratio(p.pitch_ratio);
}

double tow_propeller_drag_n(const model::Vessel& tow, double speed_m_s, const TowPropellerOptions& options) {
  options.validate();
  require_input(std::isfinite(speed_m_s) && speed_m_s >= 0.0, "propulsion: speed_m_s", speed_m_s,
                "must be finite and >= 0");
  if (!tow.propellers || options.state == TowPropellerState::kRemoved) return 0.0;
  const model::Propellers& p = *tow.propellers;
  require_in_range(tow.name + ": propeller wake_fraction", p.wake_fraction, 0.0, 0.6);
  const double v_p = uses_wake(options.model) ? speed_m_s * (1.0 - p.wake_fraction) : speed_m_s;
  const double q = 0.5 * kRhoSeawater_kg_m3 * v_p * v_p;  // dynamic pressure at the propeller [Pa]
  double locked_n = 0.0;
  switch (options.model) {
    case LockedPropellerDragModel::kNavyProjectedArea:
    case LockedPropellerDragModel::kNavyProjectedAreaWake: {
      const double area_m2 =
          options.projected_area_m2 > 0.0 ? options.projected_area_m2 : propeller_projected_area_m2(tow);
      locked_n = q * options.projected_area_drag_coefficient * area_m2;  // EQ-PROPULSION-7
      break;
    }
    case LockedPropellerDragModel::kDiskArea:
    case LockedPropellerDragModel::kDiskAreaWake:
      locked_n = q * options.disk_drag_coefficient * disk_area_m2(p);  // EQ-PROPULSION-8
      break;
  }
  return options.state == TowPropellerState::kFreeSpinning ? options.free_spinning_fraction * locked_n
                                                           : locked_n;  // EQ-PROPULSION-9
}

double tow_propeller_damping_n_s_m(const model::Vessel& tow, double speed_m_s, const TowPropellerOptions& options) {
  const double drag_n = tow_propeller_drag_n(tow, speed_m_s, options);
  if (speed_m_s == 0.0) return 0.0;
  return 2.0 * drag_n / speed_m_s;  // d(c V^2)/dV = 2 c V = 2 R / V
}

SurgeDamping tow_surge_damping(const model::Vessel& tow, double speed_m_s, const HullDampingOptions& hull_options,
                               const TowPropellerOptions& propeller_options) {
  SurgeDamping s;
  s.hull_n_s_m = hull_damping_n_s_m(tow, speed_m_s, hull_options);
  s.propeller_n_s_m = tow_propeller_damping_n_s_m(tow, speed_m_s, propeller_options);
  s.total_n_s_m = s.hull_n_s_m + s.propeller_n_s_m;
  return s;
}

}  // namespace towdb::propulsion
