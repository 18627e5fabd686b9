// Mean (steady) towline tension and its components (EQ-PROPULSION-10, -11
// and -12 in propulsion/propulsion.hpp; thesis ch. 2; U.S. Navy Towing
// Manual App. G).
//
// Inputs: the tow (model::Vessel: drag curve, wetted surface [m^2], frontal
// windage [m^2], propellers), the conditions (tow speed [m/s], true wind
// speed [m/s] and heading [rad], sea-state added resistance [N] from the
// seakeeping module, optionally the towline drag [N]).
// Output: MeanTensionBreakdown, every component in N.
#ifndef TOWDB_PROPULSION_MEAN_TENSION_HPP
#define TOWDB_PROPULSION_MEAN_TENSION_HPP

#include <optional>

#include "common/constants.hpp"
#include "model/vessel.hpp"
#include "propulsion/tow_propeller.hpp"

namespace towdb::propulsion {

enum class WindDragModel {
  kNavyTowingManual,  // R_W = (1/2) rho_a C_W0 C_w K A_T V_R^2 (eq. 2.8), default
  kTaylor,            // R_W = 1.28 (1/2) rho_a K A_T V_R^2 (eq. 2.6)
};

struct WindDragOptions {
  // Formula (default: the Towing Manual's, which carries C_w).
  WindDragModel model = WindDragModel::kNavyTowingManual;
  // C_W0 = 2 * 0.00506 / (0.002377 * 1.68781^2): the Navy's 0.00506
  // lbf/(ft^2 kt^2) over (1/2) rho_air (EQ-PROPULSION-10).
  double navy_base_coefficient = 1.4945;
  // C_w: the manual's wind coefficient, 0.7 to 1.0; 0.85 is mid-range and
  // makes the Navy form agree with Taylor's within 1 %.
  double wind_coefficient = 0.85;
  // Taylor's resistance coefficient (thesis eq. 2.6).
  double taylor_coefficient = 1.28;
  // Frontal windage A_T [m^2]; 0 = the vessel's hull.windage_frontal_m2.
  double frontal_area_m2 = 0.0;

  // Throws InputError naming the field: navy_base_coefficient and
  // taylor_coefficient in [0.5, 3], wind_coefficient in [0.5, 1.2],
  // frontal_area_m2 in [0, 1e5].
  void validate() const;
};

// The relative (apparent) wind seen by a vessel at speed V [m/s] in a true
// wind U [m/s] with heading mu [rad] (0 = following, pi = head).
struct RelativeWind {
  double along_from_ahead_m_s = 0.0;  // u_R = V - U cos(mu), > 0 from ahead
  double across_m_s = 0.0;            // v_R = U sin(mu)
  double speed_m_s = 0.0;             // V_R = sqrt(u_R^2 + v_R^2)
};
RelativeWind relative_wind(double vessel_speed_m_s, double wind_speed_m_s, double wind_heading_rad);

// Along-ship wind drag R_W [N] (> 0 aft) on the vessel (EQ-PROPULSION-10).
double wind_drag_n(const model::Vessel& vessel, double vessel_speed_m_s, double wind_speed_m_s,
                   double wind_heading_rad, const WindDragOptions& options = {});

// Thesis eq. 2.9 in towdb's heading convention (EQ-PROPULSION-11): the
// added resistance [N] at wave heading mu [rad] from a head-seas value [N].
double direction_corrected_added_resistance_n(double head_seas_resistance_n, double wave_heading_rad);

// How MeanTensionConditions::sea_added_resistance_n is to be read.
enum class SeaResistanceInput {
  kAtHeading,          // already for the wave heading (strip theory, eq. 2.2): used as is
  kHeadSeasCorrected,  // a head-seas value: eq. 2.9 direction correction applied
};

struct MeanTensionConditions {
  double tow_speed_m_s = 0.0;                 // V > 0
  double wind_speed_m_s = 0.0;                // true wind U >= 0
  double wind_heading_rad = kPi;              // 0 following, pi head wind
  double sea_added_resistance_n = 0.0;        // R_S or R_S,head (see sea_input)
  SeaResistanceInput sea_input = SeaResistanceInput::kAtHeading;
  double wave_heading_rad = kPi;              // used by kHeadSeasCorrected
  std::optional<double> towline_drag_n;       // replaces the fraction rule when given
};

struct MeanTensionOptions {
  // Hull margin m for appendages, roughness and fouling (thesis: 0.10;
  // Towing Manual: 0.25).
  double hull_margin = 0.10;
  // The tow's propeller: state and drag formula (Towing Manual: locked).
  TowPropellerOptions propeller;
  // Wind drag formula and coefficients.
  WindDragOptions wind;
  // Towline drag as a fraction of the tow resistance (Towing Manual: 10 %).
  double towline_drag_fraction = 0.10;

  // Throws InputError naming the field: hull_margin in [0, 1],
  // towline_drag_fraction in [0, 0.5], and the nested options' rules.
  void validate() const;
};

struct MeanTensionBreakdown {
  double hull_n = 0.0;             // (1 + m) R_H
  double propeller_n = 0.0;        // R_P
  double wind_n = 0.0;             // R_W (< 0 in a following wind faster than the tow)
  double sea_n = 0.0;              // R_S after any direction correction
  double tow_resistance_n = 0.0;   // R_tow = hull + propeller + wind + sea
  double towline_n = 0.0;          // R_line
  double total_n = 0.0;            // T_mean = R_tow + R_line
  double relative_wind_m_s = 0.0;  // V_R
};

// EQ-PROPULSION-12. Throws InputError for bad conditions or options. The
// total may come out <= 0 (a following gale with trailing seas); the caller
// decides whether such a case can be towed.
MeanTensionBreakdown mean_tension(const model::Vessel& tow, const MeanTensionConditions& conditions,
                                  const MeanTensionOptions& options = {});

}  // namespace towdb::propulsion

#endif  // TOWDB_PROPULSION_MEAN_TENSION_HPP
