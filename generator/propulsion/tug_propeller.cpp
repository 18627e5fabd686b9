#include "propulsion/tug_propeller.hpp"

#include <cmath>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::propulsion {

void TugPropellerDampingOptions::validate() const {
  require_input(std::isfinite(rpm_fraction) && rpm_fraction > 0.0 && rpm_fraction <= 1.2,
                "TugPropellerDampingOptions.rpm_fraction", rpm_fraction,
                "must be in (0, 1.2] (fraction of the maximum RPM)");
  require_in_range("TugPropellerDampingOptions.speed_step_m_s", speed_step_m_s, 0.0, 5.0);
  require_in_range("TugPropellerDampingOptions.damping_floor_n_s_m", damping_floor_n_s_m, 0.0, 1e7);
  require_in_range("TugPropellerDampingOptions.tug_resistance_factor", tug_resistance_factor, 0.5, 2.0);
  require_in_range("TugPropellerDampingOptions.pitch_ratio_min", pitch_ratio_min, kBSeriesPitchRatioMin,
                   kBSeriesPitchRatioMax);
  require_in_range("TugPropellerDampingOptions.pitch_ratio_max", pitch_ratio_max, kBSeriesPitchRatioMin,
                   kBSeriesPitchRatioMax);
  require_input(pitch_ratio_min < pitch_ratio_max, "TugPropellerDampingOptions.pitch_ratio_min",
                pitch_ratio_min, "must be below pitch_ratio_max = " + format_value(pitch_ratio_max));
}

const char* to_string(PropellerSolveStatus status) {
  switch (status) {
    case PropellerSolveStatus::kSolved:
      return "solved";
    case PropellerSolveStatus::kPitchBelowSeriesRange:
      return "pitch_below_series_range";
    case PropellerSolveStatus::kThrustExceedsCapacity:
      return "thrust_exceeds_capacity";
  }
  return "unknown";
}

TugPropellerDamping tug_propeller_damping(const model::Vessel& tug, double speed_m_s, double mean_tension_n,
                                          const TugPropellerDampingOptions& options) {
  options.validate();
  if (!tug.propellers) {
    throw InputError(tug.name + ": propellers: none given; the tug propeller damping needs them");
  }
  const model::Propellers& p = *tug.propellers;
  const std::string who = tug.name + ": propeller ";
  require_in_range(who + "count", p.count, 1, 6);
  require_positive(who + "diameter_m", p.diameter_m);
  require_positive(who + "rpm_max", p.rpm_max);
  require_in_range(who + "wake_fraction", p.wake_fraction, 0.0, 0.6);
  require_in_range(who + "thrust_deduction", p.thrust_deduction, 0.0, 0.5);
  const BSeriesBlades blades{p.blades, p.expanded_area_ratio};
  blades.validate();
  require_input(std::isfinite(speed_m_s) && speed_m_s >= 0.0, "propulsion: speed_m_s", speed_m_s,
                "must be finite and >= 0");
  require_input(std::isfinite(mean_tension_n) && mean_tension_n >= 0.0, "propulsion: mean_tension_n",
                mean_tension_n, "must be finite and >= 0");

  TugPropellerDamping r;
  const double count = static_cast<double>(p.count);
  const double d = p.diameter_m;
  const double n = options.rpm_fraction * units::rpm_to_rev_s(p.rpm_max);  // EQ-PROPULSION-5
  const double one_minus_w = 1.0 - p.wake_fraction;
  const double thrust_scale_n = kRhoSeawater_kg_m3 * n * n * d * d * d * d;  // rho n^2 D^4
  const double torque_scale_n_m = thrust_scale_n * d;                        // rho n^2 D^5
  const auto advance_ratio = [&](double v_m_s) { return v_m_s * one_minus_w / (n * d); };  // EQ-PROPULSION-4

  r.rev_per_s = n;
  r.advance_ratio = advance_ratio(speed_m_s);
  const double deduction = options.apply_thrust_deduction ? 1.0 - p.thrust_deduction : 1.0;
  r.required_thrust_per_propeller_n =
      (hull_resistance_n(tug, speed_m_s, options.tug_resistance_factor) + mean_tension_n) / (count * deduction);
  const double kt_required = r.required_thrust_per_propeller_n / thrust_scale_n;
  const double j = r.advance_ratio;
  const double kt_at_min = bseries_kt(blades, j, options.pitch_ratio_min);
  const double kt_at_max = bseries_kt(blades, j, options.pitch_ratio_max);
  r.max_thrust_per_propeller_n = thrust_scale_n * kt_at_max;

  if (kt_required > kt_at_max) {
    r.status = PropellerSolveStatus::kThrustExceedsCapacity;
    r.pitch_ratio = options.pitch_ratio_max;
  } else if (kt_required < kt_at_min) {
    r.status = PropellerSolveStatus::kPitchBelowSeriesRange;
    r.pitch_ratio = options.pitch_ratio_min;
  } else {
    r.pitch_ratio = solve_bseries_pitch_ratio(blades, j, kt_required, options.pitch_ratio_min,
                                              options.pitch_ratio_max);
  }
  r.kt = bseries_kt(blades, j, r.pitch_ratio);
  r.kq = bseries_kq(blades, j, r.pitch_ratio);
  r.thrust_per_propeller_n = thrust_scale_n * r.kt;
  r.torque_per_propeller_n_m = torque_scale_n_m * r.kq;
  r.delivered_power_w = count * 2.0 * kPi * n * r.torque_per_propeller_n_m;

  // EQ-PROPULSION-6: thrust change at constant n and fixed pitch.
  if (options.speed_step_m_s > 0.0) {
    const double dv = options.speed_step_m_s;
    const double kt_next = bseries_kt(blades, advance_ratio(speed_m_s + dv), r.pitch_ratio);
    r.damping_per_propeller_n_s_m = -thrust_scale_n * (kt_next - r.kt) / dv;
  } else {
    r.damping_per_propeller_n_s_m =
        -kRhoSeawater_kg_m3 * n * d * d * d * one_minus_w * bseries_dkt_dj(blades, j, r.pitch_ratio);
  }

  const double shared = options.share == PropellerDampingShare::kAllPropellers
                            ? count * r.damping_per_propeller_n_s_m
                            : r.damping_per_propeller_n_s_m;
  if (r.status == PropellerSolveStatus::kThrustExceedsCapacity || !(shared >= options.damping_floor_n_s_m)) {
    r.damping_n_s_m = options.damping_floor_n_s_m;
    r.floored = true;
  } else {
    r.damping_n_s_m = shared;
  }
  return r;
}

SurgeDamping tug_surge_damping(const model::Vessel& tug, double speed_m_s, double mean_tension_n,
                               const HullDampingOptions& hull_options,
                               const TugPropellerDampingOptions& propeller_options) {
  SurgeDamping s;
  s.hull_n_s_m = hull_damping_n_s_m(tug, speed_m_s, hull_options);
  s.propeller_n_s_m = tug_propeller_damping(tug, speed_m_s, mean_tension_n, propeller_options).damping_n_s_m;
  s.total_n_s_m = s.hull_n_s_m + s.propeller_n_s_m;
  return s;
}

}  // namespace towdb::propulsion
