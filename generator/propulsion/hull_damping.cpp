#include "propulsion/hull_damping.hpp"

#include <algorithm>
#include <cmath>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::propulsion {

namespace {

// A speed this close (relative) to a tabulated speed is that speed: the
// table's kt values converted to m/s may differ from a caller's by an ulp.
constexpr double kNodeRelTol = 1e-9;

void require_speed(double speed_m_s) {
  require_input(std::isfinite(speed_m_s) && speed_m_s >= 0.0, "propulsion: speed_m_s", speed_m_s,
                "must be finite and >= 0 (forward towing speed)");
}

double segment_slope(const model::DragCurve& d, std::size_t i) {
  return (d.total_resistance_coefficient[i + 1] - d.total_resistance_coefficient[i]) /
         (d.speed_m_s[i + 1] - d.speed_m_s[i]);
}

}  // namespace

void HullDampingOptions::validate() const {
  require_in_range("HullDampingOptions.resistance_factor", resistance_factor, 0.5, 2.0);
  require_in_range("HullDampingOptions.speed_step_m_s", speed_step_m_s, 0.0, 5.0);
}

double drag_coefficient_slope_s_m(const model::DragCurve& drag, double speed_m_s, KinkRule rule) {
  const auto& v = drag.speed_m_s;
  TOWDB_ASSERT(v.size() >= 2 && v.size() == drag.total_resistance_coefficient.size());
  const std::size_t segments = v.size() - 1;
  // Index of the first tabulated speed >= V (within the node tolerance).
  const auto it = std::lower_bound(v.begin(), v.end(), speed_m_s,
                                   [](double node, double x) { return node < x * (1.0 - kNodeRelTol); });
  const std::size_t k = static_cast<std::size_t>(it - v.begin());
  const bool at_node = k < v.size() && std::abs(v[k] - speed_m_s) <= kNodeRelTol * std::abs(v[k]);
  if (!at_node) {
    // Strictly inside segment k-1, or outside the table (held C_T: slope 0).
    if (k == 0 || k == v.size()) return 0.0;
    return segment_slope(drag, k - 1);
  }
  const double lower = k == 0 ? 0.0 : segment_slope(drag, k - 1);
  const double upper = k == segments ? 0.0 : segment_slope(drag, k);
  switch (rule) {
    case KinkRule::kLowerSpeed:
      return lower;
    case KinkRule::kUpperSpeed:
      return upper;
    case KinkRule::kAverage:
      break;
  }
  return 0.5 * (lower + upper);
}

double hull_resistance_n(const model::Vessel& vessel, double speed_m_s, double resistance_factor) {
  require_speed(speed_m_s);
  return resistance_factor * 0.5 * kRhoSeawater_kg_m3 * vessel.hull.wetted_surface_m2 * speed_m_s *
         speed_m_s * vessel.drag.coefficient_at(speed_m_s);
}

double hull_damping_n_s_m(const model::Vessel& vessel, double speed_m_s, const HullDampingOptions& options) {
  options.validate();
  require_speed(speed_m_s);
  if (options.speed_step_m_s > 0.0) {
    const double dv = options.speed_step_m_s;
    return (hull_resistance_n(vessel, speed_m_s + dv, options.resistance_factor) -
            hull_resistance_n(vessel, speed_m_s, options.resistance_factor)) /
           dv;
  }
  const double rho_s = kRhoSeawater_kg_m3 * vessel.hull.wetted_surface_m2;
  const double c_t = vessel.drag.coefficient_at(speed_m_s);
  const double dc_dv = drag_coefficient_slope_s_m(vessel.drag, speed_m_s, options.kink_rule);
  return options.resistance_factor *
         (rho_s * speed_m_s * c_t + 0.5 * rho_s * speed_m_s * speed_m_s * dc_dv);
}

}  // namespace towdb::propulsion
