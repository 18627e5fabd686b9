#include "model/vessel.hpp"

#include <algorithm>
#include <cmath>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::model {

double Hull::displacement_volume_m3() const { return displacement_kg / kRhoSeawater_kg_m3; }

double Hull::block_coefficient() const {
  return displacement_volume_m3() / (length_pp_m * beam_m * draft_m);
}

double DragCurve::coefficient_at(double query_speed_m_s) const {
  TOWDB_ASSERT(!this->speed_m_s.empty());
  const auto& v = this->speed_m_s;
  const auto& c = total_resistance_coefficient;
  if (query_speed_m_s <= v.front()) return c.front();
  if (query_speed_m_s >= v.back()) return c.back();
  const auto it = std::upper_bound(v.begin(), v.end(), query_speed_m_s);
  const std::size_t i = static_cast<std::size_t>(it - v.begin());
  const double t = (query_speed_m_s - v[i - 1]) / (v[i] - v[i - 1]);
  return c[i - 1] + t * (c[i] - c[i - 1]);
}

double Vessel::hull_resistance_n(double speed_m_s) const {
  return 0.5 * kRhoSeawater_kg_m3 * hull.wetted_surface_m2 * speed_m_s * speed_m_s *
         drag.coefficient_at(std::abs(speed_m_s));
}

namespace {

void positive(const std::string& vessel, const char* field, double value) {
  require_positive(vessel + ": " + field, value);
}

}  // namespace

void validate(const Vessel& v) {
  const std::string& n = v.name;
  if (n.empty()) throw InputError("vessel name is empty");
  const Hull& h = v.hull;
  positive(n, "length_overall", h.length_overall_m);
  positive(n, "length_pp", h.length_pp_m);
  positive(n, "beam", h.beam_m);
  positive(n, "draft", h.draft_m);
  positive(n, "displacement", h.displacement_kg);
  positive(n, "kg", h.kg_m);
  positive(n, "gm", h.gm_m);
  positive(n, "radius_gyration_roll", h.radius_gyration_roll_m);
  positive(n, "radius_gyration_pitch", h.radius_gyration_pitch_m);
  positive(n, "radius_gyration_yaw", h.radius_gyration_yaw_m);
  positive(n, "wetted_surface", h.wetted_surface_m2);
  require_in_range(n + ": length_pp / length_overall", h.length_pp_m / h.length_overall_m, 0.5, 1.0);
  require_in_range(n + ": block_coefficient", h.block_coefficient(), 0.3, 1.0);
  require_in_range(n + ": roll_damping_ratio", h.roll_damping_ratio, 0.0, 0.5);
  require_in_range(n + ": surge_added_mass_ratio", h.surge_added_mass_ratio, 0.0, 0.5);
  if (h.stations.size() < 5) {
    throw InputError(n + ": stations: " + std::to_string(h.stations.size()) +
                     " given, at least 5 are needed for strip theory");
  }
  for (std::size_t i = 0; i < h.stations.size(); ++i) {
    const Station& s = h.stations[i];
    const std::string f = n + ": station " + std::to_string(i + 1);
    if (i > 0) {
      require_input(s.x_m > h.stations[i - 1].x_m, f + " x", s.x_m,
                    "stations must be ordered aft to forward with increasing x");
    }
    require_in_range(f + " beam", s.beam_m, 0.0, 1.2 * h.beam_m);
    require_in_range(f + " draft", s.draft_m, 0.0, 1.5 * h.draft_m);
    require_in_range(f + " area_coefficient", s.area_coefficient, 0.0, 1.0);
  }
  const auto& d = v.drag;
  if (d.speed_m_s.size() < 2 || d.speed_m_s.size() != d.total_resistance_coefficient.size()) {
    throw InputError(n + ": drag table needs at least 2 speeds and one coefficient per speed");
  }
  for (std::size_t i = 0; i < d.speed_m_s.size(); ++i) {
    if (i > 0) {
      require_input(d.speed_m_s[i] > d.speed_m_s[i - 1], n + ": drag speed", d.speed_m_s[i],
                    "speeds must increase strictly");
    }
    require_in_range(n + ": drag coefficient", d.total_resistance_coefficient[i], 1e-4, 0.1);
  }
  if (v.propellers) {
    const Propellers& p = *v.propellers;
    require_in_range(n + ": propeller count", p.count, 1, 6);
    positive(n, "propeller diameter", p.diameter_m);
    require_in_range(n + ": propeller blades", p.blades, 2, 7);
    require_in_range(n + ": propeller expanded_area_ratio", p.expanded_area_ratio, 0.3, 1.05);
    require_in_range(n + ": propeller pitch_ratio", p.pitch_ratio, 0.5, 1.4);
    positive(n, "propeller rpm_max", p.rpm_max);
    require_in_range(n + ": propeller wake_fraction", p.wake_fraction, 0.0, 0.6);
    require_in_range(n + ": propeller thrust_deduction", p.thrust_deduction, 0.0, 0.5);
  }
  if (v.role == VesselRole::kTug) {
    if (!v.propellers) throw InputError(n + ": a tug needs a [propellers] table");
    if (v.wire_hawser.empty() || v.fiber_hawser.empty() || v.pendant.empty()) {
      throw InputError(n + ": a tug must name its wire_hawser, fiber_hawser and pendant");
    }
  }
}

}  // namespace towdb::model
