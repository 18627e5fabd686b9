#include "database_basis.hpp"

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

// Whether the database's vessels table holds this exact ship file.
bool database_has_ship_file(const std::filesystem::path& db_path, const model::Vessel& v) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  store::Statement st = db.prepare("SELECT count(*) FROM vessels WHERE name = ? AND content_sha256 = ?");
  st.bind(1, v.name).bind(2, v.content_sha256);
  st.step();
  return st.column_int(0) > 0;
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

BasisLookup read_database_basis(const std::filesystem::path& db_path) {
  const std::optional<RecordedBuild> build = newest_completed_build(db_path);
  if (!build) return {std::nullopt, "the database records no completed build (table builds)"};
  const std::string which = "the sweep file " + build->sweep_file + " of build " + std::to_string(build->build_id);
  bool changed = false;
  for (const auto& p : candidate_paths(db_path, build->sweep_file)) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) continue;
    sweep::SweepFile file;
    try {
      file = sweep::load_sweep(p);
    } catch (const InputError&) {
      changed = true;  // no longer parses: not the file the build read
      continue;
    }
    if (file.sha256 != build->sweep_sha256) {
      changed = true;
      continue;
    }
    return basis_of_sweep(file, which + " (" + p.string() + ")");
  }
  return {std::nullopt, which + (changed ? " has changed since the build (SHA-256 differs)"
                                         : " was not found (looked as written and above the database)")};
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
  if (!database_has_ship_file(db_path, tow)) {
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
