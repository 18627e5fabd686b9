// Vessel particulars in SI, as every model of the chain consumes them.
//
// Coordinates (ship-fixed, right-handed, origin at midships on the waterline):
//   x forward, y to port, z up. Longitudinal positions are measured from
//   midships (half the length between perpendiculars), positive forward.
//   Vertical positions of the hull (KG) are above the keel; the tow point
//   height is above the waterline.
// Units: m, kg, s, N, rad (SI); names carry the unit. The parser layer
// (generator/io) converts the user units of ships/*.toml (ft, LT, kt, lbf).
#ifndef TOWDB_MODEL_VESSEL_HPP
#define TOWDB_MODEL_VESSEL_HPP

#include <optional>
#include <string>
#include <vector>

namespace towdb::model {

enum class VesselRole { kTug, kTow };
enum class PropellerPitch { kFixed, kControllable };

// One hull section (strip) for strip theory, described as a Lewis form by its
// waterline beam, draft and area coefficient sigma = A / (B T).
struct Station {
  double x_m = 0.0;               // from midships, + forward
  double beam_m = 0.0;            // sectional waterline beam
  double draft_m = 0.0;           // sectional draft
  double area_coefficient = 0.0;  // A / (B T), 0 < sigma <= 1 (0 only for B = T = 0 ends)
};

struct Hull {
  double length_overall_m = 0.0;
  double length_pp_m = 0.0;       // length between perpendiculars / waterline, for hydrostatics
  double beam_m = 0.0;            // waterline beam
  double draft_m = 0.0;           // hull (keel) draft amidships
  double displacement_kg = 0.0;   // full-load mass
  double lcg_m = 0.0;             // longitudinal centre of gravity from midships, + forward
  double kg_m = 0.0;              // vertical centre of gravity above keel
  double gm_m = 0.0;              // transverse metacentric height
  double radius_gyration_roll_m = 0.0;
  double radius_gyration_pitch_m = 0.0;
  double radius_gyration_yaw_m = 0.0;
  double wetted_surface_m2 = 0.0;
  double windage_frontal_m2 = 0.0;      // transverse projected area above water
  double roll_damping_ratio = 0.0;      // empirical viscous roll damping, fraction of critical
  double surge_added_mass_ratio = 0.0;  // surge added mass / displacement mass (empirical)
  std::vector<Station> stations;        // ordered aft to forward

  // C_b = displacement volume / (L_pp B T).
  double block_coefficient() const;
  double displacement_volume_m3() const;
};

// Hull resistance curve: R(V) = 1/2 rho S V^2 C_T(V), S the wetted surface.
// C_T is interpolated linearly in speed; outside the table it is held at the
// end values (documented extrapolation).
struct DragCurve {
  std::vector<double> speed_m_s;                     // strictly increasing
  std::vector<double> total_resistance_coefficient;  // C_T [-]
  double coefficient_at(double speed_m_s) const;
};

struct Propellers {
  int count = 0;
  double diameter_m = 0.0;
  int blades = 0;
  double expanded_area_ratio = 0.0;  // A_E / A_0
  double pitch_ratio = 0.0;          // design P/D
  double rpm_max = 0.0;              // normal maximum operating RPM
  double wake_fraction = 0.0;        // Taylor wake fraction w
  double thrust_deduction = 0.0;     // t
  PropellerPitch pitch = PropellerPitch::kFixed;
  bool nozzle = false;               // ducted (Kort nozzle)
  double installed_power_w = 0.0;    // total for all shafts
};

struct TowPoint {
  double x_m = 0.0;  // from midships, + forward (tug: aft, negative; tow: bow, positive)
  double z_m = 0.0;  // above the waterline
};

struct Vessel {
  std::string name;                  // canonical name, e.g. "T-ATF 166"
  std::vector<std::string> aliases;  // further accepted names
  VesselRole role = VesselRole::kTow;
  Hull hull;
  DragCurve drag;
  TowPoint tow_point;
  std::optional<Propellers> propellers;  // none for an unpowered barge
  // Tug only: names of the towline components it carries (see towline.hpp).
  std::string wire_hawser;
  std::string fiber_hawser;
  std::string pendant;
  // Provenance.
  std::string source_path;   // the ship file it came from
  std::string content_sha256;  // of that file's bytes

  // R(V) [N] and dR/dV [N s/m] from the drag curve (no margin).
  double hull_resistance_n(double speed_m_s) const;
};

// Checks internal consistency; throws InputError naming the field and value.
void validate(const Vessel& vessel);

}  // namespace towdb::model

#endif  // TOWDB_MODEL_VESSEL_HPP
