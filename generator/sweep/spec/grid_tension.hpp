// Mean tensions of a sweep condition (EQ-SWEEP-1..3 in sweep/sweep.hpp):
// the Towing-Manual calculated value, the thesis's lower "hull plus half the
// propeller" value, and the speed reduction above the tugs' capacity.
//
// Inputs: the tow (model::Vessel), speed [kt], wind [kt], wind heading [deg]
// (0 following, 180 head), sea-state added resistance [N]. Outputs in lbf
// (the sweep's unit) plus the SI breakdown of propulsion::mean_tension.
#ifndef TOWDB_SWEEP_GRID_TENSION_HPP
#define TOWDB_SWEEP_GRID_TENSION_HPP

#include <functional>
#include <optional>
#include <string>

#include "model/vessel.hpp"
#include "propulsion/mean_tension.hpp"

namespace towdb::sweep {

enum class MeanTensionWind {
  kHead,     // wind from ahead for every heading (thesis Appendix C: one mean per condition)
  kHeading,  // wind along the case's wave heading
};

enum class SeaResistanceModel { kNone, kStripTheoryHead, kStripTheoryHeading };

struct MeanTensionModel {
  // Hull margin m (thesis ch. 2: 0.10; Towing Manual: 0.25).
  double hull_margin = 0.10;
  // The tow's propeller in the calculated value (Towing Manual: locked).
  propulsion::TowPropellerState propeller = propulsion::TowPropellerState::kLocked;
  // Direction of the wind in the wind-drag term (thesis: head wind).
  MeanTensionWind wind = MeanTensionWind::kHead;
  // T_max [lbf]: above it the speed is reduced (thesis ch. 5: 125,000 lbf,
  // beyond the capacity of the tugs).
  double limit_lbf = 125000.0;
  // dV [kt]: step of the speed reduction (thesis: 9 -> 8.5 and 5 -> 3 kt occur; 1 kt default).
  double speed_step_kt = 1.0;
  // V_min [kt]: lowest speed tried before the condition is skipped (thesis's lowest: 3 kt).
  double min_speed_kt = 3.0;
  // Sea-state added resistance R_S in the calculated tension (EQ-SWEEP-1):
  // none (0), strip theory in head seas for every heading (like the Towing
  // Manual's head-sea curve: one mean tension per condition, thesis Appendix
  // C), or strip theory at the case's own heading.
  SeaResistanceModel sea_resistance = SeaResistanceModel::kNone;

  // Throws InputError naming the field: hull_margin in [0, 1], limit_lbf in
  // [1000, 2e6], speed_step_kt in [0.1, 5], min_speed_kt in [0.5, 30].
  void validate() const;
};

// EQ-SWEEP-1 (SI breakdown; total_n is T_calc). wind_heading_deg is used
// only with MeanTensionWind::kHeading.
propulsion::MeanTensionBreakdown calculated_mean_tension(const model::Vessel& tow, double speed_kt, double wind_kt,
                                                         double wind_heading_deg, double sea_added_resistance_n,
                                                         const MeanTensionModel& model);

// EQ-SWEEP-2, lower basis: (1 + m) R_H(V) + R_P,locked(V) / 2 [lbf].
double hull_half_propeller_tension_lbf(const model::Vessel& tow, double speed_kt, const MeanTensionModel& model);

struct SpeedChoice {
  double speed_kt = 0.0;           // V_k
  double calculated_lbf = 0.0;     // T_calc(V_k)
  bool reduced = false;            // k > 0
};

// EQ-SWEEP-3: the speed to tow at, or nullopt (with *reason set) when even
// V_min gives T_calc > T_max. `calculated_at` maps a speed [kt] to T_calc [lbf].
std::optional<SpeedChoice> choose_speed(double nominal_speed_kt, const MeanTensionModel& model,
                                        const std::function<double(double)>& calculated_at, std::string* reason);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_GRID_TENSION_HPP
