#include "propulsion/mean_tension.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "propulsion/hull_damping.hpp"

namespace towdb::propulsion {

namespace {

// Wraps an angle into (-pi, pi].
double wrap_angle_rad(double angle_rad) {
  double a = std::remainder(angle_rad, 2.0 * kPi);  // [-pi, pi]
  if (a <= -kPi) a += 2.0 * kPi;
  return a;
}

}  // namespace

void WindDragOptions::validate() const {
  require_in_range("WindDragOptions.navy_base_coefficient", navy_base_coefficient, 0.5, 3.0);
  require_in_range("WindDragOptions.wind_coefficient", wind_coefficient, 0.5, 1.2);
  require_in_range("WindDragOptions.taylor_coefficient", taylor_coefficient, 0.5, 3.0);
  require_in_range("WindDragOptions.frontal_area_m2", frontal_area_m2, 0.0, 1e5);
}

void MeanTensionOptions::validate() const {
  require_in_range("MeanTensionOptions.hull_margin", hull_margin, 0.0, 1.0);
  require_in_range("MeanTensionOptions.towline_drag_fraction", towline_drag_fraction, 0.0, 0.5);
  propeller.validate();
  wind.validate();
}

RelativeWind relative_wind(double vessel_speed_m_s, double wind_speed_m_s, double wind_heading_rad) {
  require_input(std::isfinite(vessel_speed_m_s), "propulsion: vessel_speed_m_s", vessel_speed_m_s, "must be finite");
  require_input(std::isfinite(wind_speed_m_s) && wind_speed_m_s >= 0.0, "propulsion: wind_speed_m_s",
                wind_speed_m_s, "must be finite and >= 0");
  require_input(std::isfinite(wind_heading_rad), "propulsion: wind_heading_rad", wind_heading_rad,
                "must be finite");
  RelativeWind w;
  // Ship velocity V x; wind velocity U (cos mu x + sin mu y), travelling
  // along mu (mu = 0 with the ship). Air relative to the ship: (U cos mu - V) x
  // + U sin mu y, so it comes from ahead at u_R = V - U cos(mu) (head wind,
  // mu = pi: V + U; following wind: V - U).
  w.along_from_ahead_m_s = vessel_speed_m_s - wind_speed_m_s * std::cos(wind_heading_rad);
  w.across_m_s = wind_speed_m_s * std::sin(wind_heading_rad);
  w.speed_m_s = std::hypot(w.along_from_ahead_m_s, w.across_m_s);
  return w;
}

double wind_drag_n(const model::Vessel& vessel, double vessel_speed_m_s, double wind_speed_m_s,
                   double wind_heading_rad, const WindDragOptions& options) {
  options.validate();
  const double area_m2 = options.frontal_area_m2 > 0.0 ? options.frontal_area_m2 : vessel.hull.windage_frontal_m2;
  require_input(std::isfinite(area_m2) && area_m2 >= 0.0, vessel.name + ": windage_frontal_m2", area_m2,
                "must be finite and >= 0");
  const RelativeWind w = relative_wind(vessel_speed_m_s, wind_speed_m_s, wind_heading_rad);
  const double coefficient = options.model == WindDragModel::kTaylor
                                 ? options.taylor_coefficient
                                 : options.navy_base_coefficient * options.wind_coefficient;
  // K V_R^2 = cos(a)|cos(a)| V_R^2 = u_R |u_R|  (EQ-PROPULSION-10).
  return 0.5 * kRhoAir_kg_m3 * coefficient * area_m2 * w.along_from_ahead_m_s * std::abs(w.along_from_ahead_m_s);
}

double direction_corrected_added_resistance_n(double head_seas_resistance_n, double wave_heading_rad) {
  require_input(std::isfinite(head_seas_resistance_n), "propulsion: head_seas_resistance_n", head_seas_resistance_n,
                "must be finite");
  require_input(std::isfinite(wave_heading_rad), "propulsion: wave_heading_rad", wave_heading_rad, "must be finite");
  // theta (thesis, 0 = head seas) = pi - |mu| (towdb, 0 = following).
  const double theta_rad = kPi - std::abs(wrap_angle_rad(wave_heading_rad));
  if (theta_rad > 0.5 * kPi) return 0.0;
  return head_seas_resistance_n * std::cos(theta_rad);  // EQ-PROPULSION-11
}

MeanTensionBreakdown mean_tension(const model::Vessel& tow, const MeanTensionConditions& c,
                                  const MeanTensionOptions& options) {
  options.validate();
  require_input(std::isfinite(c.tow_speed_m_s) && c.tow_speed_m_s > 0.0, "MeanTensionConditions.tow_speed_m_s",
                c.tow_speed_m_s, "must be finite and > 0");
  require_input(std::isfinite(c.sea_added_resistance_n), "MeanTensionConditions.sea_added_resistance_n",
                c.sea_added_resistance_n, "must be finite");
  if (c.towline_drag_n) {
    require_input(std::isfinite(*c.towline_drag_n) && *c.towline_drag_n >= 0.0,
                  "MeanTensionConditions.towline_drag_n", *c.towline_drag_n, "must be finite and >= 0");
  }
  MeanTensionBreakdown b;
  b.hull_n = hull_resistance_n(tow, c.tow_speed_m_s, 1.0 + options.hull_margin);
  b.propeller_n = tow_propeller_drag_n(tow, c.tow_speed_m_s, options.propeller);
  b.wind_n = wind_drag_n(tow, c.tow_speed_m_s, c.wind_speed_m_s, c.wind_heading_rad, options.wind);
  b.relative_wind_m_s = relative_wind(c.tow_speed_m_s, c.wind_speed_m_s, c.wind_heading_rad).speed_m_s;
  b.sea_n = c.sea_input == SeaResistanceInput::kHeadSeasCorrected
                ? direction_corrected_added_resistance_n(c.sea_added_resistance_n, c.wave_heading_rad)
                : c.sea_added_resistance_n;
  b.tow_resistance_n = b.hull_n + b.propeller_n + b.wind_n + b.sea_n;
  b.towline_n = c.towline_drag_n ? *c.towline_drag_n
                                 : options.towline_drag_fraction * std::max(b.tow_resistance_n, 0.0);
  b.total_n = b.tow_resistance_n + b.towline_n;  // EQ-PROPULSION-12
  return b;
}

}  // namespace towdb::propulsion
