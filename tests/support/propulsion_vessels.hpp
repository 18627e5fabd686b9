// Test vessels for the propulsion tests, built in code (the ships/*.toml
// files are written elsewhere). Every number states its source; E marks an
// engineering estimate from docs/ship-data.md.
#ifndef TOWDB_TESTS_SUPPORT_PROPULSION_VESSELS_HPP
#define TOWDB_TESTS_SUPPORT_PROPULSION_VESSELS_HPP

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/units.hpp"
#include "model/vessel.hpp"
#include "test_support.hpp"

namespace towdb::test {

// Reads a CSV of numbers from tests/data/<relative>; '#' lines are comments.
inline std::vector<std::vector<double>> read_numeric_csv(const std::string& relative) {
  const auto path = source_dir() / "tests" / "data" / relative;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(std::move(row));
  }
  return rows;
}

// A drag curve from (speed kt, C_T) pairs.
inline model::DragCurve drag_curve_from_kt(const std::vector<std::pair<double, double>>& table) {
  model::DragCurve d;
  for (const auto& [speed_kt, c_t] : table) {
    d.speed_m_s.push_back(units::kt_to_m_s(speed_kt));
    d.total_resistance_coefficient.push_back(c_t);
  }
  return d;
}

// ITTC-1957 model-ship correlation line C_F = 0.075 / (log10 Re - 2)^2.
inline double ittc57_friction_coefficient(double speed_m_s, double length_m, double nu_m2_s) {
  const double log_re = std::log10(speed_m_s * length_m / nu_m2_s);
  return 0.075 / ((log_re - 2.0) * (log_re - 2.0));
}

// A drag file C_T(V) = form_factor * C_F,ITTC57(V) at 1..14 kt: the
// estimate used for hulls whose drag file is not public (wave resistance
// is negligible at towing Froude numbers < 0.1).
inline model::DragCurve ittc57_drag_curve(double length_m, double form_factor) {
  std::vector<std::pair<double, double>> table;
  for (int kt = 1; kt <= 14; ++kt) {
    const double v = units::kt_to_m_s(kt);
    table.emplace_back(kt, form_factor * ittc57_friction_coefficient(v, length_m, kNuSeawater_m2_s));
  }
  return drag_curve_from_kt(table);
}

// T-ATF 166 as a tug: drag file tests/data/propulsion/tatf166_drag.csv
// (thesis App. A, docs/ship-data.md 7.1) on S = 10,475 ft^2 (docs/ship-data.md 7.1);
// two propellers, D = 9.0 ft (thesis App. A), 227 rpm at 100 %
// (docs/ship-data.md 7.2: 204.3 rpm = 90 %), 4 blades (E), A_E/A_0 = 0.55
// (E, docs/ship-data.md 2.3), wake fraction 0.10 (E, a twin-screw tug).
inline model::Vessel make_tatf166() {
  model::Vessel v;
  v.name = "T-ATF 166 (test)";
  v.role = model::VesselRole::kTug;
  v.hull.length_overall_m = units::ft_to_m(226.0);
  v.hull.length_pp_m = units::ft_to_m(204.0);
  v.hull.beam_m = units::ft_to_m(42.0);
  v.hull.draft_m = units::ft_to_m(15.0);
  v.hull.displacement_kg = units::long_tons_to_kg(2260.0);
  v.hull.wetted_surface_m2 = units::ft2_to_m2(10475.0);
  std::vector<std::pair<double, double>> table;
  for (const auto& row : read_numeric_csv("propulsion/tatf166_drag.csv")) table.emplace_back(row.at(0), row.at(1));
  v.drag = drag_curve_from_kt(table);
  model::Propellers p;
  p.count = 2;
  p.diameter_m = units::ft_to_m(9.0);
  p.blades = 4;
  p.expanded_area_ratio = 0.55;
  p.pitch_ratio = 1.0;
  p.rpm_max = 227.0;
  p.wake_fraction = 0.10;
  p.thrust_deduction = 0.0;
  p.pitch = model::PropellerPitch::kControllable;
  p.nozzle = true;
  p.installed_power_w = units::hp_to_w(7680.0);  // docs/ship-data.md 2.2 (S40)
  v.propellers = p;
  return v;
}

// A tow with a given drag curve, wetted surface, windage and propellers.
inline model::Vessel make_tow(const std::string& name, double wetted_surface_ft2, double windage_ft2,
                              model::DragCurve drag) {
  model::Vessel v;
  v.name = name;
  v.role = model::VesselRole::kTow;
  v.hull.wetted_surface_m2 = units::ft2_to_m2(wetted_surface_ft2);
  v.hull.windage_frontal_m2 = units::ft2_to_m2(windage_ft2);
  v.drag = std::move(drag);
  return v;
}

}  // namespace towdb::test

#endif  // TOWDB_TESTS_SUPPORT_PROPULSION_VESSELS_HPP
