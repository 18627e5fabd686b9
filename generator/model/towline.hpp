// Towline components and assembled towlines in SI.
//
// A towline is an ordered list of segments from the tug's tow point to the
// tow's bow fitting (thesis 5.x: wire or fiber hawser, then a 90 ft chain
// pendant at the tow). Each segment is a length of one component.
// Units: m, kg, N. Weight per length is the submerged (in-water) weight used
// by the catenary; mass per length is the structural (in-air) mass used for
// inertia in the cable dynamics.
#ifndef TOWDB_MODEL_TOWLINE_HPP
#define TOWDB_MODEL_TOWLINE_HPP

#include <string>
#include <vector>

namespace towdb::model {

enum class LineKind { kWire, kFiber, kChain };

const char* to_string(LineKind kind);

struct TowlineComponent {
  std::string name;
  LineKind kind = LineKind::kWire;
  double ea_n = 0.0;                       // axial stiffness E A
  double hydrodynamic_diameter_m = 0.0;    // drag / added-mass diameter
  double mass_per_length_kg_m = 0.0;       // in air
  double weight_in_water_n_m = 0.0;        // submerged weight per length
  double breaking_strength_n = 0.0;
  double drag_coefficient_normal = 0.0;    // C_D on hydrodynamic diameter
  double added_mass_coefficient = 0.0;     // C_A on rho pi D^2 / 4
  double fixed_length_m = 0.0;             // > 0 for a pendant of fixed length
  std::string source_path;
  std::string content_sha256;
};

struct TowlineSegment {
  TowlineComponent component;
  double length_m = 0.0;
};

struct Towline {
  std::vector<TowlineSegment> segments;  // ordered tug -> tow

  double total_length_m() const;
  // The weakest segment's breaking strength.
  double breaking_strength_n() const;
  // Series compliance sum_i L_i / (EA)_i [m/N].
  double axial_compliance_m_per_n() const;
};

void validate(const TowlineComponent& component);
void validate(const Towline& towline);

}  // namespace towdb::model

#endif  // TOWDB_MODEL_TOWLINE_HPP
