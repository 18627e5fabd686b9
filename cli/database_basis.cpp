#include "database_basis.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "common/error.hpp"
#include "common/units.hpp"
#include "store/database.hpp"
#include "sweep/build/simulation_runner.hpp"
#include "sweep/spec/sweep_file.hpp"

namespace towdb::cli {

namespace {

struct RecordedBuild {
  std::int64_t build_id = 0;
  std::string sweep_file;
  std::string sweep_sha256;
};

std::optional<RecordedBuild> newest_completed_build(const std::filesystem::path& db_path) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  store::Statement st = db.prepare(
      "SELECT build_id, sweep_file, sweep_sha256 FROM builds WHERE status = 'completed' ORDER BY build_id DESC "
      "LIMIT 1");
  if (!st.step()) return std::nullopt;
  return RecordedBuild{st.column_int(0), st.column_text(1), st.column_text(2)};
}

// The recorded sweep path as written (absolute, or relative to the working
// directory), then relative to each folder above the database: a build run
// from the repository root records "db/sweeps/x.toml".
std::vector<std::filesystem::path> candidate_paths(const std::filesystem::path& db_path, const std::string& recorded) {
  namespace fs = std::filesystem;
  std::vector<fs::path> out{fs::path(recorded)};
  const fs::path rel(recorded);
  if (rel.is_absolute()) return out;
  std::error_code ec;
  fs::path dir = fs::absolute(db_path, ec).parent_path();
  for (int depth = 0; depth < 16 && !dir.empty(); ++depth) {
    out.push_back(dir / rel);
    if (dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  return out;
}

bool same_model(const sweep::MeanTensionModel& a, const sweep::MeanTensionModel& b) {
  return a.hull_margin == b.hull_margin && a.propeller == b.propeller && a.wind == b.wind &&
         a.sea_resistance == b.sea_resistance;
}

// The one model of the sweep's grids that have a "calculated" mean tension.
BasisLookup basis_of_sweep(const sweep::SweepFile& file, const std::string& source) {
  std::optional<sweep::MeanTensionModel> found;
  for (const sweep::GridEntry& g : file.grids) {
    bool calculated = false;
    for (const auto& level : g.mean_tensions) calculated |= level.basis == sweep::MeanTensionBasis::kCalculated;
    if (!calculated) continue;
    if (found && !same_model(*found, g.mean_model)) {
      return {std::nullopt, "the grids of " + source + " compute the calculated mean tension in different ways"};
    }
    found = g.mean_model;
  }
  if (!found) return {std::nullopt, source + " has no grid with a \"calculated\" mean tension"};
  return {DatabaseBasis{*found, source}, ""};
}

// What the database's vessels table records of this vessel's ship file.
enum class RecordedShipFile { kThisFile, kAnotherFile, kNone };

RecordedShipFile recorded_ship_file(store::Database& db, const model::Vessel& v) {
  store::Statement st =
      db.prepare("SELECT count(*), coalesce(sum(content_sha256 = ?2), 0) FROM vessels WHERE name = ?1");
  st.bind(1, v.name).bind(2, v.content_sha256);
  st.step();
  if (st.column_int(1) > 0) return RecordedShipFile::kThisFile;
  return st.column_int(0) > 0 ? RecordedShipFile::kAnotherFile : RecordedShipFile::kNone;
}

// A stored case's calculated mean tension and the inputs it was computed at
// (EQ-SWEEP-1: the node's own tow, speed, wind and heading).
struct StoredCalculated {
  std::int64_t case_id = 0;
  std::string tow;
  double speed_kt = 0.0, wind_kt = 0.0, heading_deg = 0.0, calculated_lbf = 0.0;
};

std::optional<StoredCalculated> first_stored_calculated(const std::filesystem::path& db_path) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  store::Statement st = db.prepare(
      "SELECT case_id, tow_name, speed_kt, wind_kt, heading_deg, calculated_mean_tension_lbf FROM cases "
      "WHERE status = 'done' AND calculated_mean_tension_lbf IS NOT NULL AND wind_kt IS NOT NULL "
      "AND (nominal_speed_kt IS NULL OR nominal_speed_kt = speed_kt) ORDER BY case_id LIMIT 1");
  if (!st.step()) return std::nullopt;
  return StoredCalculated{st.column_int(0),    st.column_text(1),   st.column_double(2),
                          st.column_double(3), st.column_double(4), st.column_double(5)};
}

// The same formula and inputs as the build (sweep_file.cpp grid_speed): only
// the last bits may differ, from the order of the strip theory's sums.
constexpr double kBasisCheckRelTol = 1e-9;

// A sweep file whose bytes changed since the build (a comment, say) is still
// the database's basis when its model reproduces a calculated mean tension
// the database stores (which also checks the tow's ship file where it counts:
// its resistance); empty when it does, else why not.
std::string check_basis_against_store(const DatabaseBasis& basis, const io::ShipCatalog& catalog,
                                      const std::filesystem::path& db_path) {
  const std::optional<StoredCalculated> c = first_stored_calculated(db_path);
  if (!c) return "the database stores no calculated mean tension to check it against";
  if (catalog.find_vessel(c->tow) == nullptr) return "the ships hold no " + c->tow + " to check it with";
  const double lbf =
      calculated_mean_tension(basis, catalog, db_path, c->tow, c->speed_kt, c->wind_kt, c->heading_deg).total_lbf;
  if (std::abs(lbf - c->calculated_lbf) > kBasisCheckRelTol * c->calculated_lbf) {
    return "its model gives " + format_value(lbf) + " lbf where case " + std::to_string(c->case_id) + " stores " +
           format_value(c->calculated_lbf) + " lbf";
  }
  return "";
}

}  // namespace

const char* propeller_name(propulsion::TowPropellerState s) {
  switch (s) {
    case propulsion::TowPropellerState::kLocked: return "locked";
    case propulsion::TowPropellerState::kFreeSpinning: return "free";
    case propulsion::TowPropellerState::kRemoved: return "removed";
  }
  return "removed";
}

const char* sea_resistance_name(sweep::SeaResistanceModel m) {
  switch (m) {
    case sweep::SeaResistanceModel::kNone: return "none";
    case sweep::SeaResistanceModel::kStripTheoryHead: return "strip-theory-head";
    case sweep::SeaResistanceModel::kStripTheoryHeading: return "strip-theory";
  }
  return "none";
}

simulation::CaseOptions build_case_options() {
  simulation::CaseOptions o;
  o.num_threads = 1;
  return o;
}

BasisLookup read_database_basis(const std::filesystem::path& db_path, const io::ShipCatalog* catalog) {
  const std::optional<RecordedBuild> build = newest_completed_build(db_path);
  if (!build) return {std::nullopt, "the database records no completed build (table builds)"};
  const std::string which = "the sweep file " + build->sweep_file + " of build " + std::to_string(build->build_id);
  std::string changed;  // why a file found is not the build's basis
  for (const auto& p : candidate_paths(db_path, build->sweep_file)) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) continue;
    sweep::SweepFile file;
    try {
      file = sweep::load_sweep(p);
    } catch (const InputError&) {
      changed = " no longer parses";  // not the file the build read
      continue;
    }
    const std::string source = which + " (" + p.string() + ")";
    if (file.sha256 == build->sweep_sha256) return basis_of_sweep(file, source);
    changed = " has changed since the build (SHA-256 differs)";
    if (catalog == nullptr) continue;
    BasisLookup edited = basis_of_sweep(file, source + ", changed since the build");
    if (!edited.basis) continue;
    const std::string mismatch = check_basis_against_store(*edited.basis, *catalog, db_path);
    if (mismatch.empty()) {
      edited.basis->source += "; its model reproduces the calculated mean tensions the database stores";
      return edited;
    }
    changed += ", and " + mismatch;
  }
  return {std::nullopt, which + (changed.empty() ? " was not found (looked as written and above the database)"
                                                 : changed)};
}

std::vector<std::string> vessels_changed_since_build(const std::filesystem::path& db_path,
                                                     const io::ShipCatalog& catalog,
                                                     const std::vector<std::string>& names) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  std::vector<std::string> changed;
  for (const std::string& name : names) {
    const io::VesselFile* file = catalog.find_vessel(name);
    if (file != nullptr && recorded_ship_file(db, file->vessel) == RecordedShipFile::kAnotherFile) {
      changed.push_back(file->vessel.name);
    }
  }
  return changed;
}

CalculatedMeanTension calculated_mean_tension(const DatabaseBasis& basis, const io::ShipCatalog& catalog,
                                              const std::filesystem::path& db_path, const std::string& tow_name,
                                              double speed_kt, double wind_kt, double heading_deg) {
  const model::Vessel& tow = catalog.vessel(tow_name).vessel;
  const sweep::MeanTensionModel& m = basis.model;
  double rs_n = 0.0;
  if (m.sea_resistance != sweep::SeaResistanceModel::kNone && wind_kt > 0.0) {
    // As sweep::expand_sweep: strip theory in the sea of the wind, in head
    // seas or at the question's heading (EQ-SWEEP-1).
    sweep::SeaSpec sea;
    sea.wind_kt = wind_kt;
    const double mu_deg = m.sea_resistance == sweep::SeaResistanceModel::kStripTheoryHead ? 180.0 : heading_deg;
    rs_n = sweep::strip_theory_sea_resistance(build_case_options())(tow, speed_kt, sea, mu_deg);
  }
  CalculatedMeanTension out;
  out.breakdown = sweep::calculated_mean_tension(tow, speed_kt, wind_kt, heading_deg, rs_n, m);
  out.total_lbf = units::n_to_lbf(out.breakdown.total_n);
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  if (recorded_ship_file(db, tow) != RecordedShipFile::kThisFile) {
    out.ship_file_note = "the ship file of " + tow.name + " (" + tow.source_path +
                         ") is not the one the database was built with; the calculated mean tension differs from "
                         "the database's own";
  }
  return out;
}

nlohmann::ordered_json basis_json(const DatabaseBasis& basis) {
  const sweep::MeanTensionModel& m = basis.model;
  return {{"source", basis.source},
          {"hull_margin", m.hull_margin},
          {"propeller", propeller_name(m.propeller)},
          {"mean_tension_wind", m.wind == sweep::MeanTensionWind::kHead ? "head" : "heading"},
          {"sea_resistance", sea_resistance_name(m.sea_resistance)}};
}

std::string basis_text(const DatabaseBasis& basis) {
  const sweep::MeanTensionModel& m = basis.model;
  return "hull margin " + format_value(m.hull_margin) + ", tow propeller " + propeller_name(m.propeller) +
         ", wind " + (m.wind == sweep::MeanTensionWind::kHead ? "from ahead" : "along the heading") +
         ", sea resistance " + sea_resistance_name(m.sea_resistance) + "; from " + basis.source;
}

nlohmann::ordered_json breakdown_json(const CalculatedMeanTension& t) {
  const propulsion::MeanTensionBreakdown& b = t.breakdown;
  return {{"hull_lbf", units::n_to_lbf(b.hull_n)},
          {"propeller_lbf", units::n_to_lbf(b.propeller_n)},
          {"wind_lbf", units::n_to_lbf(b.wind_n)},
          {"sea_lbf", units::n_to_lbf(b.sea_n)},
          {"tow_resistance_lbf", units::n_to_lbf(b.tow_resistance_n)},
          {"towline_lbf", units::n_to_lbf(b.towline_n)},
          {"total_lbf", t.total_lbf},
          {"relative_wind_kt", units::m_s_to_kt(b.relative_wind_m_s)}};
}

}  // namespace towdb::cli
