#include "io/ship_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include <openssl/evp.h>
#include <unistd.h>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "io/file_bytes.hpp"
#include "model/hull_form.hpp"

namespace towdb::io {

namespace {

// Cross-check tolerances (documented in docs/ship-files.md).
// |C_b stated - disp / (rho L B T)| may differ by rounding of the published
// particulars: 0.02 is about 3 % of a typical C_b.
constexpr double kBlockCoefficientAbsTol = 0.02;
// The station table is a generated or digitised approximation of the hull:
// its volume integral may differ from the displacement by up to 5 %.
constexpr double kStationVolumeRelTol = 0.05;

void check_format(StrictTable& top, const std::string& expected) {
  top.string("format", {expected});
}

}  // namespace

std::string normalize_name(std::string_view name) {
  std::string out;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  return out;
}

std::string sha256_hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1) {
    throw Error("SHA-256 computation failed (libcrypto)");
  }
  static const char* kHex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out.push_back(kHex[digest[i] >> 4]);
    out.push_back(kHex[digest[i] & 0xF]);
  }
  return out;
}

VesselFile parse_vessel(std::string_view text, const std::string& path) {
  using namespace units;
  const toml::table doc = parse_toml(text, path);
  VesselFile out;
  model::Vessel& v = out.vessel;
  v.source_path = path;
  v.content_sha256 = sha256_hex(text);

  StrictTable top(doc, path, "", &out.provenance);
  check_format(top, "towdb-vessel-1");

  StrictTable id = top.table("vessel");
  v.name = id.string("name");
  if (normalize_name(v.name).empty()) id.string("name", {"a name with letters or digits"});
  if (id.has("aliases")) v.aliases = id.string_array("aliases");
  const std::string role = id.string("role", {"tug", "tow"});
  v.role = role == "tug" ? model::VesselRole::kTug : model::VesselRole::kTow;
  out.description = id.optional_string("description").value_or("");
  id.finish();

  StrictTable hull = top.table("hull");
  model::Hull& h = v.hull;
  h.length_overall_m = ft_to_m(hull.sourced_number("length_overall_ft", 10.0, 1500.0));
  h.length_pp_m = ft_to_m(hull.sourced_number("length_pp_ft", 10.0, 1500.0));
  h.beam_m = ft_to_m(hull.sourced_number("beam_ft", 5.0, 200.0));
  h.draft_m = ft_to_m(hull.sourced_number("draft_ft", 0.5, 60.0));
  h.displacement_kg = long_tons_to_kg(hull.sourced_number("displacement_lt", 50.0, 150000.0));
  const double cb_stated = hull.sourced_number("block_coefficient", 0.3, 1.0);
  h.lcg_m = ft_to_m(hull.sourced_number("lcg_ft", -200.0, 200.0));
  h.kg_m = ft_to_m(hull.sourced_number("kg_ft", 0.5, 100.0));
  h.gm_m = ft_to_m(hull.sourced_number("gm_ft", 0.1, 100.0));
  h.radius_gyration_roll_m = ft_to_m(hull.sourced_number("radius_gyration_roll_ft", 1.0, 100.0));
  h.radius_gyration_pitch_m = ft_to_m(hull.sourced_number("radius_gyration_pitch_ft", 5.0, 400.0));
  h.radius_gyration_yaw_m = ft_to_m(hull.sourced_number("radius_gyration_yaw_ft", 5.0, 400.0));
  h.wetted_surface_m2 = ft2_to_m2(hull.sourced_number("wetted_surface_ft2", 100.0, 500000.0));
  h.windage_frontal_m2 = ft2_to_m2(hull.sourced_number("windage_frontal_ft2", 0.0, 50000.0));
  h.roll_damping_ratio = hull.sourced_number("roll_damping_ratio", 0.0, 0.5);
  h.surge_added_mass_ratio = hull.sourced_number("surge_added_mass_ratio", 0.0, 0.5);

  {
    StrictTable st = hull.table("stations");
    st.table_provenance("station table");
    const auto x = st.number_array("x_ft", -800.0, 800.0);
    const auto b = st.number_array("beam_ft", 0.0, 200.0);
    const auto t = st.number_array("draft_ft", 0.0, 60.0);
    const auto s = st.number_array("area_coefficient", 0.0, 1.0);
    if (b.size() != x.size() || t.size() != x.size() || s.size() != x.size()) {
      throw InputError(st.where("x_ft") + ": x_ft, beam_ft, draft_ft and area_coefficient must have the "
                       "same length (" + std::to_string(x.size()) + ", " + std::to_string(b.size()) + ", " +
                       std::to_string(t.size()) + ", " + std::to_string(s.size()) + ")");
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      h.stations.push_back({ft_to_m(x[i]), ft_to_m(b[i]), ft_to_m(t[i]), s[i]});
    }
    st.finish();
  }
  hull.finish();

  {
    StrictTable drag = top.table("drag");
    drag.table_provenance("drag table");
    const auto speed = drag.number_array("speed_kt", 0.0, 40.0);
    const auto ct = drag.number_array("total_resistance_coefficient", 1e-4, 0.1);
    if (speed.size() != ct.size()) {
      throw InputError(drag.where("speed_kt") + ": speed_kt and total_resistance_coefficient must have the "
                       "same length (" + std::to_string(speed.size()) + ", " + std::to_string(ct.size()) + ")");
    }
    for (std::size_t i = 1; i < speed.size(); ++i) {
      if (!(speed[i] > speed[i - 1])) {
        throw InputError(drag.where("speed_kt") + ": speed_kt[" + std::to_string(i) + "] = " + format_value(speed[i]) +
                         ": the speeds must increase (previous " + format_value(speed[i - 1]) + ")");
      }
    }
    for (double s : speed) v.drag.speed_m_s.push_back(kt_to_m_s(s));
    v.drag.total_resistance_coefficient = ct;
    drag.finish();
  }

  {
    StrictTable tp = top.table("tow_point");
    const double x_ft = tp.sourced_number("x_ft", -800.0, 800.0);
    if (v.role == model::VesselRole::kTug ? !(x_ft < 0.0) : !(x_ft > 0.0)) {
      throw InputError(tp.where("x_ft") + ": x_ft = " + format_value(x_ft) +
                       (v.role == model::VesselRole::kTug ? ": a tug's tow point is aft of midships (< 0)"
                                                          : ": a tow's towing fitting is forward of midships (> 0)"));
    }
    v.tow_point.x_m = ft_to_m(x_ft);
    v.tow_point.z_m = ft_to_m(tp.sourced_number("z_ft", -20.0, 150.0));
    tp.finish();
  }

  if (auto prop = top.optional_table("propellers")) {
    model::Propellers p;
    p.count = static_cast<int>(prop->sourced_integer("count", 1, 6));
    p.diameter_m = ft_to_m(prop->sourced_number("diameter_ft", 1.0, 40.0));
    p.blades = static_cast<int>(prop->sourced_integer("blades", 2, 7));
    p.expanded_area_ratio = prop->sourced_number("expanded_area_ratio", 0.3, 1.05);
    p.pitch_ratio = prop->sourced_number("pitch_ratio", 0.5, 1.4);
    p.rpm_max = prop->sourced_number("rpm_max", 30.0, 2000.0);
    p.wake_fraction = prop->sourced_number("wake_fraction", 0.0, 0.6);
    p.thrust_deduction = prop->sourced_number("thrust_deduction", 0.0, 0.5);
    p.installed_power_w = hp_to_w(prop->sourced_number("installed_power_hp", 0.0, 200000.0));
    p.pitch = prop->sourced_string("pitch", {"fixed", "controllable"}) == "fixed"
                  ? model::PropellerPitch::kFixed
                  : model::PropellerPitch::kControllable;
    p.nozzle = prop->sourced_boolean("nozzle");
    prop->finish();
    v.propellers = p;
  }

  if (auto lines = top.optional_table("towlines")) {
    if (v.role != model::VesselRole::kTug) {
      throw InputError(lines->where("wire_hawser") + ": [towlines] is only allowed for role = \"tug\"");
    }
    v.wire_hawser = lines->string("wire_hawser");
    v.fiber_hawser = lines->string("fiber_hawser");
    v.pendant = lines->string("pendant");
    lines->finish();
  }
  top.finish();

  // Cross-checks between numbers.
  const double cb_computed = h.block_coefficient();
  if (std::abs(cb_stated - cb_computed) > kBlockCoefficientAbsTol) {
    throw InputError(path + ": hull.block_coefficient = " + format_value(cb_stated) +
                     " disagrees with displacement / (rho L B T) = " + format_value(cb_computed) +
                     "; allowed difference " + format_value(kBlockCoefficientAbsTol));
  }
  if (h.length_pp_m > h.length_overall_m) {
    throw InputError(path + ": hull.length_pp_ft = " + format_value(m_to_ft(h.length_pp_m)) +
                     " exceeds length_overall_ft = " + format_value(m_to_ft(h.length_overall_m)));
  }
  if (h.stations.size() >= 2) {
    const double v_st = model::station_volume_m3(h.stations);
    const double v_disp = h.displacement_volume_m3();
    if (std::abs(v_st - v_disp) > kStationVolumeRelTol * v_disp) {
      throw InputError(path + ": hull.stations: volume integral " + format_value(v_st) +
                       " m^3 differs from the displacement volume " + format_value(v_disp) +
                       " m^3 by more than " + format_value(100.0 * kStationVolumeRelTol) + " %");
    }
  }
  try {
    model::validate(v);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  return out;
}

TowlineFile parse_towline_component(std::string_view text, const std::string& path) {
  using namespace units;
  const toml::table doc = parse_toml(text, path);
  TowlineFile out;
  model::TowlineComponent& c = out.component;
  c.source_path = path;
  c.content_sha256 = sha256_hex(text);

  StrictTable top(doc, path, "", &out.provenance);
  check_format(top, "towdb-towline-1");
  StrictTable id = top.table("component");
  c.name = id.string("name");
  const std::string kind = id.string("kind", {"wire", "fiber", "chain"});
  c.kind = kind == "wire" ? model::LineKind::kWire
                          : (kind == "fiber" ? model::LineKind::kFiber : model::LineKind::kChain);
  out.description = id.optional_string("description").value_or("");
  id.finish();

  StrictTable p = top.table("properties");
  c.ea_n = lbf_to_n(p.sourced_number("ea_lbf", 1e4, 1e10));
  c.hydrodynamic_diameter_m = ft_to_m(p.sourced_number("hydrodynamic_diameter_ft", 0.01, 3.0));
  const double w_air = p.sourced_number("weight_in_air_lb_per_ft", 0.01, 500.0);
  const double w_water = p.sourced_number("weight_in_water_lb_per_ft", 0.0, 500.0);
  if (w_water > w_air) {
    throw InputError(p.where("weight_in_water_lb_per_ft") + " = " + format_value(w_water) +
                     ": must not exceed weight_in_air_lb_per_ft = " + format_value(w_air));
  }
  c.mass_per_length_kg_m = lb_per_ft_to_kg_per_m(w_air);
  c.weight_in_water_n_m = lbf_per_ft_to_n_per_m(w_water);
  c.breaking_strength_n = lbf_to_n(p.sourced_number("breaking_strength_lbf", 1e3, 1e8));
  c.drag_coefficient_normal = p.sourced_number("drag_coefficient_normal", 0.1, 5.0);
  c.added_mass_coefficient = p.sourced_number("added_mass_coefficient", 0.0, 3.0);
  if (auto fixed = p.optional_sourced_number("fixed_length_ft", 1.0, 1000.0)) c.fixed_length_m = ft_to_m(*fixed);
  p.finish();
  top.finish();
  try {
    model::validate(c);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  return out;
}

VesselFile load_vessel(const std::filesystem::path& path) {
  return parse_vessel(read_file_bytes(path), path.string());
}

TowlineFile load_towline_component(const std::filesystem::path& path) {
  return parse_towline_component(read_file_bytes(path), path.string());
}

std::filesystem::path default_ships_dir() {
  if (const char* env = std::getenv("TOWDB_SHIPS_DIR"); env && *env) return env;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / TOWDB_INSTALL_SHIPS_SUBDIR;
    if (std::filesystem::is_directory(installed)) return installed;
  }
  return TOWDB_SOURCE_SHIPS_DIR;
}

bool same_toml_content(std::string_view a, std::string_view b) {
  try {
    return toml::parse(a) == toml::parse(b);
  } catch (const toml::parse_error&) {
    return false;
  }
}

ShipCatalog ShipCatalog::with_content_hashes(const std::map<std::string, std::string>& vessel_sha256,
                                             const std::map<std::string, std::string>& component_sha256) const {
  ShipCatalog copy = *this;
  for (VesselFile& v : copy.vessels_) {
    const auto it = vessel_sha256.find(v.vessel.name);
    if (it != vessel_sha256.end()) v.vessel.content_sha256 = it->second;
  }
  for (TowlineFile& c : copy.components_) {
    const auto it = component_sha256.find(c.component.name);
    if (it != component_sha256.end()) c.component.content_sha256 = it->second;
  }
  return copy;
}

ShipCatalog ShipCatalog::load(const std::filesystem::path& ships_dir) {
  if (!std::filesystem::is_directory(ships_dir)) {
    throw InputError("ships directory '" + ships_dir.string() + "' " +
                     (std::filesystem::exists(ships_dir) ? "is not a directory" : "does not exist"));
  }
  ShipCatalog cat;
  cat.directory_ = ships_dir;
  auto sorted_toml = [](const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(dir)) {
      for (const auto& e : std::filesystem::directory_iterator(dir)) {
        if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path());
      }
    }
    std::sort(files.begin(), files.end());
    return files;
  };
  for (const auto& f : sorted_toml(ships_dir)) {
    VesselFile vf = load_vessel(f);
    std::vector<std::string> names = vf.vessel.aliases;
    names.insert(names.begin(), vf.vessel.name);
    for (const auto& n : names) {
      const std::string key = normalize_name(n);
      const auto it = cat.vessel_index_.find(key);
      if (it != cat.vessel_index_.end()) {
        throw InputError(f.string() + ": vessel name or alias '" + n + "' is already used by " +
                         cat.vessels_[it->second].vessel.source_path + " (duplicate vessel)");
      }
      cat.vessel_index_[key] = cat.vessels_.size();
    }
    cat.vessels_.push_back(std::move(vf));
  }
  for (const auto& f : sorted_toml(ships_dir / "towlines")) {
    TowlineFile tf = load_towline_component(f);
    const std::string key = normalize_name(tf.component.name);
    if (cat.component_index_.count(key)) {
      throw InputError(f.string() + ": towline component '" + tf.component.name + "' is defined twice");
    }
    cat.component_index_[key] = cat.components_.size();
    cat.components_.push_back(std::move(tf));
  }
  if (cat.vessels_.empty()) throw InputError("ships directory '" + ships_dir.string() + "' has no vessel files");
  for (const auto& vf : cat.vessels_) {
    const model::Vessel& v = vf.vessel;
    if (v.role != model::VesselRole::kTug) continue;
    for (const std::string* name : {&v.wire_hawser, &v.fiber_hawser, &v.pendant}) {
      if (!cat.component_index_.count(normalize_name(*name))) {
        throw InputError(v.source_path + ": towlines names component '" + *name +
                         "', which is not in " + (ships_dir / "towlines").string());
      }
    }
    if (cat.component(v.pendant).component.fixed_length_m <= 0.0) {
      throw InputError(v.source_path + ": towlines.pendant '" + v.pendant + "' has no fixed_length_ft");
    }
  }
  return cat;
}

namespace {
template <typename Index, typename Items, typename Name>
const auto& find_named(const Index& index, const Items& items, std::string_view name, const char* what,
                       Name name_of) {
  const auto it = index.find(normalize_name(name));
  if (it == index.end()) {
    std::string known;
    for (const auto& item : items) known += (known.empty() ? "" : ", ") + name_of(item);
    throw InputError(std::string(what) + " '" + std::string(name) + "' is not known; known: " + known);
  }
  return items[it->second];
}
}  // namespace

const VesselFile* ShipCatalog::find_vessel(std::string_view name) const {
  const auto it = vessel_index_.find(normalize_name(name));
  return it == vessel_index_.end() ? nullptr : &vessels_[it->second];
}

const TowlineFile* ShipCatalog::find_component(std::string_view name) const {
  const auto it = component_index_.find(normalize_name(name));
  return it == component_index_.end() ? nullptr : &components_[it->second];
}

const VesselFile& ShipCatalog::vessel(std::string_view name) const {
  return find_named(vessel_index_, vessels_, name, "vessel",
                    [](const VesselFile& v) { return v.vessel.name; });
}

const TowlineFile& ShipCatalog::component(std::string_view name) const {
  return find_named(component_index_, components_, name, "towline component",
                    [](const TowlineFile& c) { return c.component.name; });
}

model::Towline ShipCatalog::towline(const model::Vessel& tug, model::LineKind hawser,
                                    double hawser_length_m) const {
  if (tug.role != model::VesselRole::kTug) {
    throw InputError("vessel '" + tug.name + "' is not a tug and carries no towline");
  }
  if (hawser == model::LineKind::kChain) throw InputError("line = chain: the hawser must be wire or fiber");
  require_in_range("towline length (ft)", units::m_to_ft(hawser_length_m), 100.0, 10000.0);
  const auto& main = component(hawser == model::LineKind::kWire ? tug.wire_hawser : tug.fiber_hawser);
  const auto& pendant = component(tug.pendant);
  model::Towline t;
  t.segments.push_back({main.component, hawser_length_m});
  t.segments.push_back({pendant.component, pendant.component.fixed_length_m});
  model::validate(t);
  return t;
}

}  // namespace towdb::io
