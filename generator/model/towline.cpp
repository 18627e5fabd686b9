#include "model/towline.hpp"

#include <algorithm>
#include <limits>

#include "common/error.hpp"

namespace towdb::model {

const char* to_string(LineKind kind) {
  switch (kind) {
    case LineKind::kWire: return "wire";
    case LineKind::kFiber: return "fiber";
    case LineKind::kChain: return "chain";
  }
  return "?";
}

double Towline::total_length_m() const {
  double total = 0.0;
  for (const auto& s : segments) total += s.length_m;
  return total;
}

double Towline::breaking_strength_n() const {
  double weakest = std::numeric_limits<double>::infinity();
  for (const auto& s : segments) weakest = std::min(weakest, s.component.breaking_strength_n);
  return weakest;
}

double Towline::axial_compliance_m_per_n() const {
  double c = 0.0;
  for (const auto& s : segments) c += s.length_m / s.component.ea_n;
  return c;
}

void validate(const TowlineComponent& c) {
  const std::string& n = c.name;
  if (n.empty()) throw InputError("towline component name is empty");
  require_positive(n + ": ea", c.ea_n);
  require_positive(n + ": hydrodynamic_diameter", c.hydrodynamic_diameter_m);
  require_positive(n + ": mass_per_length", c.mass_per_length_kg_m);
  require_in_range(n + ": weight_in_water", c.weight_in_water_n_m, 0.0, 1e5);
  require_positive(n + ": breaking_strength", c.breaking_strength_n);
  require_in_range(n + ": drag_coefficient_normal", c.drag_coefficient_normal, 0.1, 5.0);
  require_in_range(n + ": added_mass_coefficient", c.added_mass_coefficient, 0.0, 3.0);
  require_in_range(n + ": fixed_length", c.fixed_length_m, 0.0, 1e4);
}

void validate(const Towline& t) {
  if (t.segments.empty()) throw InputError("towline: no segments");
  for (const auto& s : t.segments) {
    validate(s.component);
    require_positive("towline segment '" + s.component.name + "' length", s.length_m);
  }
}

}  // namespace towdb::model
