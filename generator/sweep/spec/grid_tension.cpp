#include "sweep/spec/grid_tension.hpp"

#include <cmath>

#include "common/error.hpp"
#include "common/units.hpp"
#include "propulsion/hull_damping.hpp"
#include "propulsion/tow_propeller.hpp"

namespace towdb::sweep {

namespace {

// A reduced speed counts as >= V_min when within this many knots of it
// (V_k = V_0 - k dV is formed exactly for the usual decimal steps; this only
// absorbs the last bit of a step such as 0.1 kt).
constexpr double kSpeedComparisonTol_kt = 1e-9;

// Fraction of the locked-propeller drag in the thesis's lower mean tension
// ("only one half of the propeller resistance is used", thesis ch. 5).
constexpr double kLowerTensionPropellerFraction = 0.5;

}  // namespace

void MeanTensionModel::validate() const {
  require_in_range("MeanTensionModel.hull_margin", hull_margin, 0.0, 1.0);
  require_in_range("MeanTensionModel.limit_lbf", limit_lbf, 1000.0, 2.0e6);
  require_in_range("MeanTensionModel.speed_step_kt", speed_step_kt, 0.1, 5.0);
  require_in_range("MeanTensionModel.min_speed_kt", min_speed_kt, 0.5, 30.0);
}

propulsion::MeanTensionBreakdown calculated_mean_tension(const model::Vessel& tow, double speed_kt, double wind_kt,
                                                         double wind_heading_deg, double sea_added_resistance_n,
                                                         const MeanTensionModel& model) {
  model.validate();
  propulsion::MeanTensionOptions options;
  options.hull_margin = model.hull_margin;
  options.propeller.state = model.propeller;
  propulsion::MeanTensionConditions c;
  c.tow_speed_m_s = units::kt_to_m_s(speed_kt);
  c.wind_speed_m_s = units::kt_to_m_s(wind_kt);
  c.wind_heading_rad = model.wind == MeanTensionWind::kHead ? kPi : units::deg_to_rad(wind_heading_deg);
  c.wave_heading_rad = units::deg_to_rad(wind_heading_deg);
  c.sea_added_resistance_n = sea_added_resistance_n;
  c.sea_input = propulsion::SeaResistanceInput::kAtHeading;
  return propulsion::mean_tension(tow, c, options);  // EQ-SWEEP-1 = EQ-PROPULSION-12
}

double hull_half_propeller_tension_lbf(const model::Vessel& tow, double speed_kt, const MeanTensionModel& model) {
  model.validate();
  require_in_range("hull_half_propeller_tension_lbf: speed_kt", speed_kt, 1e-3, 30.0);
  const double v_m_s = units::kt_to_m_s(speed_kt);
  propulsion::TowPropellerOptions locked;
  locked.state = propulsion::TowPropellerState::kLocked;
  const double hull_n = propulsion::hull_resistance_n(tow, v_m_s, 1.0 + model.hull_margin);
  const double propeller_n = propulsion::tow_propeller_drag_n(tow, v_m_s, locked);
  return units::n_to_lbf(hull_n + kLowerTensionPropellerFraction * propeller_n);  // EQ-SWEEP-2
}

std::optional<SpeedChoice> choose_speed(double nominal_speed_kt, const MeanTensionModel& model,
                                        const std::function<double(double)>& calculated_at, std::string* reason) {
  model.validate();
  require_in_range("choose_speed: nominal_speed_kt", nominal_speed_kt, 1e-3, 30.0);
  for (int k = 0;; ++k) {
    const double v_kt = nominal_speed_kt - k * model.speed_step_kt;  // EQ-SWEEP-3, formed without accumulation
    if (k > 0 && v_kt < model.min_speed_kt - kSpeedComparisonTol_kt) {
      if (reason) {
        *reason = "calculated mean tension " + format_value(std::round(calculated_at(nominal_speed_kt))) +
                  " lbf at " + format_value(nominal_speed_kt) + " kt exceeds " + format_value(model.limit_lbf) +
                  " lbf even at the lowest speed tried (" + format_value(nominal_speed_kt - (k - 1) * model.speed_step_kt) +
                  " kt)";
      }
      return std::nullopt;
    }
    const double t_lbf = calculated_at(v_kt);
    if (t_lbf <= model.limit_lbf) return SpeedChoice{v_kt, t_lbf, k > 0};
  }
}

}  // namespace towdb::sweep
