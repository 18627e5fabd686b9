#include "sweep/spec/sweep_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "common/error.hpp"
#include "common/units.hpp"
#include "io/strict_toml.hpp"
#include "sweep/spec/keys.hpp"

namespace towdb::sweep {

namespace {

// Accepted ranges in sweep files (user units); see docs/sweep-files.md.
constexpr double kMinSpeed_kt = 0.1;
constexpr double kMaxSpeed_kt = 30.0;
constexpr double kMaxWind_kt = 100.0;
constexpr double kMinPmWind_kt = 1.0;  // a Pierson-Moskowitz sea from a wind (towdb simulate's lower bound too)
constexpr double kMinHs_ft = 0.1;
constexpr double kMaxHs_ft = 100.0;
constexpr double kMinTp_s = 1.0;
constexpr double kMaxTp_s = 40.0;
constexpr double kMinGamma = 1.0;
constexpr double kMaxGamma = 10.0;
constexpr double kMinLength_ft = 100.0;  // the catalog's shortest hawser
constexpr double kMaxLength_ft = 10000.0;
constexpr double kMinTension_lbf = 1.0;
constexpr double kMaxTension_lbf = 2.0e6;
constexpr double kMinFactor = 0.01;
constexpr double kMaxFactor = 10.0;
constexpr std::int64_t kMaxDays = 1000000;
constexpr std::int64_t kMaxSeed = (std::int64_t{1} << 62);

const char* kFormat = "towdb-sweep-1";

std::string read_text_file(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) throw InputError(path.string() + ": is a directory, expected a sweep file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open the sweep file (missing or unreadable)");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string line_of(const toml::node& node) { return std::to_string(node.source().begin.line); }

// The keys a table may hold; anything else is an error in file order.
void check_keys(const toml::table& table, const std::string& path, const std::string& section,
                const std::set<std::string>& allowed) {
  const toml::node* first = nullptr;
  std::string first_key;
  for (const auto& [k, node] : table) {
    if (allowed.count(std::string(k.str()))) continue;
    if (!first || node.source().begin < first->source().begin) {
      first = &node;
      first_key = std::string(k.str());
    }
  }
  if (!first) return;
  // Units are part of the key name: "length_m" next to an accepted "length_ft".
  auto stem = [](const std::string& k) { return k.substr(0, k.rfind('_')); };
  for (const auto& a : allowed) {
    if (first_key.find('_') != std::string::npos && stem(a) == stem(first_key)) {
      throw InputError(path + ":" + line_of(*first) + ": " + (section.empty() ? "" : section + ".") + first_key +
                       ": unknown key; wrong unit suffix? this table expects '" + a + "'");
    }
  }
  std::string accepted;
  for (const auto& a : allowed) accepted += (accepted.empty() ? "" : ", ") + a;
  throw InputError(path + ":" + line_of(*first) + ": " + (section.empty() ? "" : section + ".") + first_key +
                   ": unknown key; accepted keys here: " + accepted);
}

// The elements of an array of tables (inline or [[...]]), each wrapped in a
// StrictTable named section[i].
std::vector<std::pair<const toml::table*, std::string>> table_array(const toml::table& parent,
                                                                     std::string_view key, const std::string& path,
                                                                     const std::string& section, bool required) {
  std::vector<std::pair<const toml::table*, std::string>> out;
  const toml::node* node = parent.get(key);
  const std::string name = (section.empty() ? "" : section + ".") + std::string(key);
  if (!node) {
    if (required) {
      throw InputError(path + ":" + std::to_string(parent.source().begin.line) + ": " +
                       (section.empty() ? "top level" : section) + ": missing key '" + std::string(key) + "'");
    }
    return out;
  }
  if (!node->is_array()) throw InputError(path + ":" + line_of(*node) + ": " + name + ": expected an array of tables");
  std::size_t i = 0;
  for (const toml::node& item : *node->as_array()) {
    ++i;
    if (!item.is_table()) {
      throw InputError(path + ":" + line_of(*node) + ": " + name + ": element " + std::to_string(i) +
                       " is not a table");
    }
    out.emplace_back(item.as_table(), name + "[" + std::to_string(i) + "]");
  }
  if (out.empty() && required) throw InputError(path + ":" + line_of(*node) + ": " + name + ": is empty");
  return out;
}

// Settings a [defaults] table sets and a [[grid]] or [[case]] may override.
struct Settings {
  std::optional<int> days;
  std::int64_t base_seed = 1;  // documented default
  MeanTensionModel model;
};

const std::set<std::string> kSettingKeys = {"days", "base_seed", "hull_margin", "propeller", "mean_tension_wind",
                                            "mean_tension_limit_lbf", "speed_step_kt", "min_speed_kt", "sea_resistance"};

void read_settings(io::StrictTable& t, Settings* s) {
  if (t.has("days")) s->days = static_cast<int>(t.integer("days", 1, kMaxDays));
  if (t.has("base_seed")) s->base_seed = t.integer("base_seed", 0, kMaxSeed);
  if (t.has("hull_margin")) s->model.hull_margin = t.number("hull_margin", 0.0, 1.0);
  if (t.has("propeller")) {
    const std::string p = t.string("propeller", {"locked", "free", "removed"});
    s->model.propeller = p == "locked" ? propulsion::TowPropellerState::kLocked
                         : p == "free" ? propulsion::TowPropellerState::kFreeSpinning
                                       : propulsion::TowPropellerState::kRemoved;
  }
  if (t.has("mean_tension_wind")) {
    s->model.wind = t.string("mean_tension_wind", {"head", "heading"}) == "head" ? MeanTensionWind::kHead
                                                                                 : MeanTensionWind::kHeading;
  }
  if (t.has("mean_tension_limit_lbf")) s->model.limit_lbf = t.number("mean_tension_limit_lbf", 1000.0, 2.0e6);
  if (t.has("speed_step_kt")) s->model.speed_step_kt = t.number("speed_step_kt", 0.1, 5.0);
  if (t.has("min_speed_kt")) s->model.min_speed_kt = t.number("min_speed_kt", 0.5, 30.0);
  if (t.has("sea_resistance")) {
    const std::string r = t.string("sea_resistance", {"none", "strip-theory-head", "strip-theory"});
    s->model.sea_resistance = r == "none"                ? SeaResistanceModel::kNone
                              : r == "strip-theory-head" ? SeaResistanceModel::kStripTheoryHead
                                                         : SeaResistanceModel::kStripTheoryHeading;
  }
}

model::LineKind read_line(io::StrictTable& t, std::string_view key) {
  return t.string(key, {"wire", "fiber"}) == "wire" ? model::LineKind::kWire : model::LineKind::kFiber;
}

// Sea keys shared by [[case]] entries and grid `seas` elements.
const std::set<std::string> kSeaKeys = {"spectrum",    "wind_kt",    "hs_ft",           "tp_s", "gamma",
                                        "swell_hs_ft", "swell_tp_s", "swell_heading_deg"};

SeaSpec read_sea(io::StrictTable& t) {
  SeaSpec sea;
  if (t.has("spectrum")) {
    sea.kind = spectrum_kind_from_string(t.string("spectrum", {"pierson-moskowitz", "bretschneider", "jonswap"}),
                                         t.where("spectrum"));
  }
  sea.wind_kt = t.optional_number("wind_kt", 0.0, kMaxWind_kt);
  sea.hs_ft = t.optional_number("hs_ft", kMinHs_ft, kMaxHs_ft);
  sea.tp_s = t.optional_number("tp_s", kMinTp_s, kMaxTp_s);
  sea.gamma = t.optional_number("gamma", kMinGamma, kMaxGamma);
  const bool any_swell = t.has("swell_hs_ft") || t.has("swell_tp_s") || t.has("swell_heading_deg");
  if (any_swell) {
    SwellSpec swell;
    swell.hs_ft = t.number("swell_hs_ft", kMinHs_ft, kMaxHs_ft);
    swell.tp_s = t.number("swell_tp_s", kMinTp_s, kMaxTp_s);
    swell.heading_deg = t.number("swell_heading_deg", 0.0, 360.0);
    sea.swell = swell;
  }
  switch (sea.kind) {
    case SpectrumKind::kPiersonMoskowitz:
      if (!sea.wind_kt) throw InputError(t.where("spectrum") + ": a pierson-moskowitz sea needs wind_kt");
      if (!(*sea.wind_kt >= kMinPmWind_kt)) {
        throw InputError(t.where("wind_kt") + ": wind_kt = " + canonical_number(*sea.wind_kt) +
                         ": a pierson-moskowitz sea needs at least " + canonical_number(kMinPmWind_kt) +
                         " kt (0 is allowed only beside hs_ft and tp_s)");
      }
      if (sea.hs_ft || sea.tp_s || sea.gamma) {
        throw InputError(t.where(sea.hs_ft ? "hs_ft" : sea.tp_s ? "tp_s" : "gamma") +
                         ": not allowed in a pierson-moskowitz sea (the wind sets height and period)");
      }
      break;
    case SpectrumKind::kBretschneider:
    case SpectrumKind::kJonswap:
      if (!sea.hs_ft || !sea.tp_s) {
        throw InputError(t.where("spectrum") + ": a " + to_string(sea.kind) + " sea needs hs_ft and tp_s");
      }
      if (sea.kind == SpectrumKind::kJonswap && !sea.gamma) {
        throw InputError(t.where("spectrum") + ": a jonswap sea needs gamma");
      }
      if (sea.kind == SpectrumKind::kBretschneider && sea.gamma) {
        throw InputError(t.where("gamma") + ": not allowed in a bretschneider sea (use spectrum = \"jonswap\")");
      }
      break;
  }
  return sea;
}

MeanTensionLevel read_level(io::StrictTable& t) {
  MeanTensionLevel level;
  level.label = t.string("label");
  if (level.label.empty()) throw InputError(t.where("label") + ": must not be empty");
  const std::string basis = t.string("basis", {"calculated", "hull+half-propeller", "given"});
  level.basis = basis == "calculated"            ? MeanTensionBasis::kCalculated
                : basis == "hull+half-propeller" ? MeanTensionBasis::kHullHalfPropeller
                                                 : MeanTensionBasis::kGiven;
  if (t.has("factor")) level.factor = t.number("factor", kMinFactor, kMaxFactor);
  if (level.basis == MeanTensionBasis::kGiven) {
    level.value_lbf = t.number("value_lbf", kMinTension_lbf, kMaxTension_lbf);
  }
  t.finish();
  return level;
}

std::vector<double> read_list(io::StrictTable& t, std::string_view key, double lo, double hi) {
  return t.number_array(key, lo, hi);
}

GridEntry read_grid(const toml::table& table, const std::string& path, const std::string& section,
                    const Settings& defaults) {
  std::set<std::string> allowed = {"label", "tugs",         "tows",     "speeds_kt",     "winds_kt",
                                   "seas",  "headings_deg", "towlines", "mean_tensions", "coverage_note"};
  allowed.insert(kSettingKeys.begin(), kSettingKeys.end());
  check_keys(table, path, section, allowed);
  io::StrictTable t(table, path, section);
  GridEntry g;
  g.line = static_cast<int>(table.source().begin.line);
  g.label = t.string("label");
  if (g.label.empty()) throw InputError(t.where("label") + ": must not be empty");
  g.coverage_note = t.optional_string("coverage_note").value_or("");
  if (t.has("coverage_note") && g.coverage_note.empty()) {
    throw InputError(t.where("coverage_note") + ": must not be empty (leave the key out when there is nothing to say)");
  }
  g.tugs = t.string_array("tugs");
  g.tows = t.string_array("tows");
  if (g.tugs.empty()) throw InputError(t.where("tugs") + ": is empty");
  if (g.tows.empty()) throw InputError(t.where("tows") + ": is empty");
  g.speeds_kt = read_list(t, "speeds_kt", kMinSpeed_kt, kMaxSpeed_kt);
  if (t.has("winds_kt") == table.contains("seas")) {
    throw InputError(path + ":" + std::to_string(g.line) + ": " + section +
                     ": give exactly one of winds_kt (Pierson-Moskowitz seas) and seas");
  }
  if (t.has("winds_kt")) {
    for (double u : read_list(t, "winds_kt", 0.0, kMaxWind_kt)) {
      SeaSpec sea;
      sea.wind_kt = u;
      g.seas.push_back(sea);
    }
  } else {
    for (const auto& [sea_table, name] : table_array(table, "seas", path, section, true)) {
      io::StrictTable st(*sea_table, path, name);
      g.seas.push_back(read_sea(st));
      st.finish();
    }
  }
  g.headings_deg = read_list(t, "headings_deg", 0.0, 360.0);
  for (const auto& [line_table, name] : table_array(table, "towlines", path, section, true)) {
    io::StrictTable lt(*line_table, path, name);
    TowlineChoice c;
    c.line = read_line(lt, "line");
    c.length_ft = lt.number("length_ft", kMinLength_ft, kMaxLength_ft);
    lt.finish();
    g.towlines.push_back(c);
  }
  std::set<std::string> labels;
  for (const auto& [level_table, name] : table_array(table, "mean_tensions", path, section, true)) {
    io::StrictTable lt(*level_table, path, name);
    MeanTensionLevel level = read_level(lt);
    if (!labels.insert(level.label).second) {
      throw InputError(lt.where("label") + ": \"" + level.label + "\" is used twice in this grid");
    }
    g.mean_tensions.push_back(level);
  }
  Settings s = defaults;
  read_settings(t, &s);
  if (!s.days) throw InputError(path + ":" + std::to_string(g.line) + ": " + section + ": days is not set (here or in [defaults])");
  g.days = *s.days;
  g.base_seed = s.base_seed;
  g.mean_model = s.model;
  return g;
}

CaseEntry read_case(const toml::table& table, const std::string& path, const std::string& section,
                    const Settings& defaults) {
  std::set<std::string> allowed = {"label",     "tug",       "tow",  "speed_kt",         "heading_deg",
                                   "line",      "length_ft", "seed", "mean_tension_lbf", "mean_tension_label"};
  allowed.insert(kSeaKeys.begin(), kSeaKeys.end());
  allowed.insert("days");
  allowed.insert("base_seed");
  check_keys(table, path, section, allowed);
  io::StrictTable t(table, path, section);
  CaseEntry c;
  c.line = static_cast<int>(table.source().begin.line);
  c.label = t.string("label");
  if (c.label.empty()) throw InputError(t.where("label") + ": must not be empty");
  CaseSpec& s = c.spec;
  s.sweep_label = c.label;
  s.tug = t.string("tug");
  s.tow = t.string("tow");
  s.speed_kt = t.number("speed_kt", kMinSpeed_kt, kMaxSpeed_kt);
  s.nominal_speed_kt = s.speed_kt;
  s.sea = read_sea(t);
  s.heading_deg = t.number("heading_deg", 0.0, 360.0);
  s.line = read_line(t, "line");
  s.length_ft = t.number("length_ft", kMinLength_ft, kMaxLength_ft);
  s.mean_tension_lbf = t.number("mean_tension_lbf", kMinTension_lbf, kMaxTension_lbf);
  s.mean_tension_label = t.optional_string("mean_tension_label").value_or("given");
  if (t.has("seed")) c.seed = t.integer("seed", 0, kMaxSeed);
  Settings st = defaults;
  if (t.has("days")) st.days = static_cast<int>(t.integer("days", 1, kMaxDays));
  if (t.has("base_seed")) st.base_seed = t.integer("base_seed", 0, kMaxSeed);
  if (!st.days) throw InputError(path + ":" + std::to_string(c.line) + ": " + section + ": days is not set (here or in [defaults])");
  s.days = *st.days;
  c.base_seed = st.base_seed;
  return c;
}

// "path:line: [grid 'label']" for messages about an entry.
std::string entry_where(const std::string& path, int line, const std::string& kind, const std::string& label) {
  return path + ":" + std::to_string(line) + ": [[" + kind + "]] '" + label + "'";
}

const model::Vessel& resolve_vessel(const io::ShipCatalog& catalog, const std::string& name, const std::string& where,
                                    bool must_be_tug) {
  const io::VesselFile* vf = catalog.find_vessel(name);
  if (!vf) {
    try {
      catalog.vessel(name);  // throws the catalog's message listing the known vessels
    } catch (const InputError& e) {
      throw InputError(where + ": " + e.what());
    }
  }
  if (must_be_tug && vf->vessel.role != model::VesselRole::kTug) {
    throw InputError(where + ": '" + name + "' is not a tug (its ship file says role = tow)");
  }
  if (!must_be_tug && vf->vessel.role != model::VesselRole::kTow) {
    throw InputError(where + ": '" + name + "' is not a tow (its ship file says role = tug)");
  }
  return vf->vessel;
}

}  // namespace

SweepFile parse_sweep(std::string_view text, const std::string& path) {
  const toml::table doc = io::parse_toml(text, path);
  SweepFile out;
  out.path = path;
  out.sha256 = io::sha256_hex(text);
  check_keys(doc, path, "", {"format", "description", "day_records", "maxima_precision", "defaults", "grid", "case"});
  io::StrictTable top(doc, path, "");
  top.string("format", {kFormat});
  out.description = top.string("description");
  if (top.has("day_records")) {
    out.day_records = top.string("day_records", {"all", "maxima"}) == "maxima" ? DayRecords::kMaxima : DayRecords::kAll;
  }
  if (top.has("maxima_precision")) {
    out.maxima_precision = top.string("maxima_precision", {"binary32", "binary16"}) == "binary16"
                               ? MaximaPrecision::kBinary16
                               : MaximaPrecision::kBinary32;
  }
  Settings defaults;
  if (doc.contains("defaults")) {
    io::StrictTable d = top.table("defaults");
    read_settings(d, &defaults);
    d.finish();
  }
  for (const auto& [table, name] : table_array(doc, "grid", path, "", false)) {
    out.grids.push_back(read_grid(*table, path, name, defaults));
  }
  for (const auto& [table, name] : table_array(doc, "case", path, "", false)) {
    out.cases.push_back(read_case(*table, path, name, defaults));
  }
  if (out.grids.empty() && out.cases.empty()) {
    throw InputError(path + ": the sweep has no [[grid]] and no [[case]] entries");
  }
  return out;
}

SweepFile load_sweep(const std::filesystem::path& path) {
  return parse_sweep(read_text_file(path), path.string());
}

namespace {

// Expands a sweep's entries into cases, one entry at a time, refusing an
// entry that repeats an earlier case's condition.
class SweepExpander {
 public:
  SweepExpander(const SweepFile& sweep, const io::ShipCatalog& catalog, const ExpandOptions& options)
      : sweep_(sweep), catalog_(catalog), options_(options) {}

  // Entries in file order (grids and cases interleaved by source line).
  SweepExpansion expand() {
    std::size_t gi = 0, ci = 0;
    while (gi < sweep_.grids.size() || ci < sweep_.cases.size()) {
      const bool take_grid = ci >= sweep_.cases.size() ||
                             (gi < sweep_.grids.size() && sweep_.grids[gi].line < sweep_.cases[ci].line);
      if (take_grid) {
        expand_grid(sweep_.grids[gi++]);
      } else {
        expand_case(sweep_.cases[ci++]);
      }
    }
    return std::move(out_);
  }

 private:
  // One condition of a grid: where it comes from and what it is.
  struct GridCondition {
    const GridEntry& grid;
    const std::string& where;
    const model::Vessel& tug;
    const model::Vessel& tow;
    double nominal_speed_kt;
    const SeaSpec& sea;
    double heading_deg;
  };

  void expand_case(const CaseEntry& c);
  void expand_grid(const GridEntry& g);
  // The speed to tow a grid condition at (EQ-SWEEP-3), or nullopt with the
  // condition recorded as skipped.
  std::optional<SpeedChoice> grid_speed(const GridCondition& k, bool needs_calculated);
  // The cases of one grid condition: every towline and mean-tension level.
  void add_grid_cases(const GridCondition& k, const SpeedChoice& speed);
  // Adds a case after checking it, its mean tension against the towline's
  // breaking strength, and that no earlier case has its condition.
  void add(CaseSpec spec, const std::string& where);
  void check_towline(const model::Vessel& tug, model::LineKind line, double length_ft, const std::string& where) const;

  const SweepFile& sweep_;
  const io::ShipCatalog& catalog_;
  const ExpandOptions& options_;
  SweepExpansion out_;
  std::map<std::string, std::string> seen_;  // condition_key -> where it came from
};

void SweepExpander::add(CaseSpec spec, const std::string& where) {
  try {
    spec.validate();
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  // The static catenary (and the towline fit) exist only below the breaking strength.
  const model::Vessel& tug = catalog_.vessel(spec.tug).vessel;
  const double breaking_n = catalog_.towline(tug, spec.line, units::ft_to_m(spec.length_ft)).breaking_strength_n();
  if (!(spec.mean_tension_n() < breaking_n)) {
    throw InputError(where + ": mean_tension_lbf = " + format_value(spec.mean_tension_lbf) +
                     ": must be below the towline's breaking strength, " +
                     canonical_number(std::round(units::n_to_lbf(breaking_n))) + " lbf (" + spec.tug + ", " +
                     model::to_string(spec.line) + " " + canonical_number(spec.length_ft) + " ft)");
  }
  const auto [it, inserted] = seen_.emplace(spec.condition_key, where);
  if (!inserted) {
    throw InputError(where + ": gives the same case as " + it->second + " (" + spec.tug + " / " + spec.tow + ", " +
                     canonical_number(spec.speed_kt) + " kt, " + sea_text(spec.sea) + ", " +
                     canonical_number(spec.heading_deg) + " deg, " + model::to_string(spec.line) + " " +
                     canonical_number(spec.length_ft) + " ft, " + spec.mean_tension_label + ")");
  }
  out_.cases.push_back(std::move(spec));
}

void SweepExpander::check_towline(const model::Vessel& tug, model::LineKind line, double length_ft,
                                  const std::string& where) const {
  try {
    catalog_.towline(tug, line, units::ft_to_m(length_ft));
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

void SweepExpander::expand_case(const CaseEntry& c) {
  const std::string where = entry_where(sweep_.path, c.line, "case", c.label);
  CaseSpec spec = c.spec;
  const model::Vessel& tug = resolve_vessel(catalog_, spec.tug, where, true);
  spec.tug = tug.name;
  spec.tow = resolve_vessel(catalog_, spec.tow, where, false).name;
  check_towline(tug, spec.line, spec.length_ft, where);
  spec.seed = c.seed ? *c.seed : case_seed(c.base_seed, spec);
  spec.condition_key = condition_key(spec, true);
  add(std::move(spec), where);
}

void SweepExpander::expand_grid(const GridEntry& g) {
  const std::string where = entry_where(sweep_.path, g.line, "grid", g.label);
  g.mean_model.validate();
  bool needs_calculated = false;
  for (const auto& level : g.mean_tensions) needs_calculated |= level.basis == MeanTensionBasis::kCalculated;
  for (const std::string& tug_name : g.tugs) {
    const model::Vessel& tug = resolve_vessel(catalog_, tug_name, where, true);
    for (const TowlineChoice& tl : g.towlines) check_towline(tug, tl.line, tl.length_ft, where);
    for (const std::string& tow_name : g.tows) {
      const model::Vessel& tow = resolve_vessel(catalog_, tow_name, where, false);
      if (!g.coverage_note.empty()) out_.notes.push_back({g.label, tug.name, tow.name, g.coverage_note});
      for (double v0_kt : g.speeds_kt) {
        for (const SeaSpec& sea : g.seas) {
          if (needs_calculated && !sea.wind_kt) {
            throw InputError(where + ": a \"calculated\" mean tension needs a wind; the sea '" + sea_text(sea) +
                             "' has no wind_kt");
          }
          for (double heading_deg : g.headings_deg) {
            const GridCondition k{g, where, tug, tow, v0_kt, sea, heading_deg};
            const std::optional<SpeedChoice> speed = grid_speed(k, needs_calculated);
            if (speed) add_grid_cases(k, *speed);
          }
        }
      }
    }
  }
}

std::optional<SpeedChoice> SweepExpander::grid_speed(const GridCondition& k, bool needs_calculated) {
  const GridEntry& g = k.grid;
  const double v0_kt = k.nominal_speed_kt;
  SpeedChoice speed{v0_kt, 0.0, false};
  if (!k.sea.wind_kt) return speed;
  // T_calc(V) of this condition in lbf (EQ-SWEEP-1).
  auto t_calc_lbf = [&](double v_kt) {
    double rs_n = 0.0;
    if (g.mean_model.sea_resistance != SeaResistanceModel::kNone) {
      if (!options_.sea_resistance) {
        throw InputError(k.where + ": sea_resistance needs the strip-theory hook, which this caller does "
                                   "not provide");
      }
      const double mu_deg =
          g.mean_model.sea_resistance == SeaResistanceModel::kStripTheoryHead ? 180.0 : k.heading_deg;
      rs_n = options_.sea_resistance(k.tow, v_kt, k.sea, mu_deg);
    }
    return units::n_to_lbf(
        calculated_mean_tension(k.tow, v_kt, k.sea.wind_kt.value_or(0.0), k.heading_deg, rs_n, g.mean_model)
            .total_n);
  };
  const auto skip = [&](std::string reason) {
    out_.skipped.push_back({g.label, k.tug.name, k.tow.name, v0_kt, sea_text(k.sea), k.heading_deg, std::move(reason)});
    return std::nullopt;
  };
  std::string reason;
  const std::optional<SpeedChoice> chosen = choose_speed(v0_kt, g.mean_model, t_calc_lbf, &reason);
  if (!chosen) return skip(reason);
  speed = *chosen;
  // A speed reduced down to another of the grid's speeds would repeat that
  // speed's cases: the condition is skipped (thesis ch. 5: "eliminated").
  double lower_nominal_kt = 0.0;
  for (double v : g.speeds_kt) {
    if (v < v0_kt) lower_nominal_kt = std::max(lower_nominal_kt, v);
  }
  if (speed.reduced && lower_nominal_kt > 0.0 && speed.speed_kt <= lower_nominal_kt) {
    return skip("calculated mean tension exceeds " + format_value(g.mean_model.limit_lbf) + " lbf above " +
                format_value(speed.speed_kt) + " kt, which the grid's " + format_value(lower_nominal_kt) +
                " kt cases already cover");
  }
  if (needs_calculated && !(speed.calculated_lbf > 0.0)) {
    return skip("calculated mean tension " + format_value(speed.calculated_lbf) +
                " lbf is not positive (wind and sea push the tow)");
  }
  return speed;
}

void SweepExpander::add_grid_cases(const GridCondition& k, const SpeedChoice& speed) {
  const GridEntry& g = k.grid;
  for (const TowlineChoice& tl : g.towlines) {
    for (const MeanTensionLevel& level : g.mean_tensions) {
      CaseSpec spec;
      spec.tug = k.tug.name;
      spec.tow = k.tow.name;
      spec.speed_kt = speed.speed_kt;
      spec.nominal_speed_kt = k.nominal_speed_kt;
      spec.sea = k.sea;
      spec.heading_deg = k.heading_deg;
      spec.line = tl.line;
      spec.length_ft = tl.length_ft;
      switch (level.basis) {  // EQ-SWEEP-2
        case MeanTensionBasis::kCalculated:
          spec.mean_tension_lbf = level.factor * speed.calculated_lbf;
          break;
        case MeanTensionBasis::kHullHalfPropeller:
          spec.mean_tension_lbf = level.factor * hull_half_propeller_tension_lbf(k.tow, speed.speed_kt, g.mean_model);
          break;
        case MeanTensionBasis::kGiven:
          spec.mean_tension_lbf = level.factor * *level.value_lbf;
          break;
      }
      spec.mean_tension_label = level.label;
      if (k.sea.wind_kt && speed.calculated_lbf > 0.0) {
        spec.calculated_mean_tension_lbf = speed.calculated_lbf;
      }
      spec.days = g.days;
      spec.sweep_label = g.label;
      spec.seed = case_seed(g.base_seed, spec);
      spec.condition_key = condition_key(spec, level.basis == MeanTensionBasis::kGiven);
      add(std::move(spec), k.where);
    }
  }
}

}  // namespace

SweepExpansion expand_sweep(const SweepFile& sweep, const io::ShipCatalog& catalog, const ExpandOptions& options) {
  return SweepExpander(sweep, catalog, options).expand();
}

}  // namespace towdb::sweep
