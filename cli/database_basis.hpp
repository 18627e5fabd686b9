// The "calculated" mean tension of a database (EQ-SWEEP-1) for a question the
// database does not store: how the database's own build computed it (hull
// margin, tow propeller, wind direction, sea-state resistance), read from
// what the database records, and evaluated at the question's own speed, wind
// and heading. Used by `towdb query` when no --mean-tension-lbf is given and
// by `towdb audit` to draw its questions.
//
// This lives in the CLI, not in the query library: the calculated tension
// needs the generator's physics (resistance curves, strip-theory added
// resistance), and the query library (query/) links only the store.
//
// Where the basis comes from (schema/README.md, table `builds`): the newest
// completed build's sweep file, found at its recorded path (as written, or
// relative to any folder above the database) and only if its SHA-256 still
// equals the recorded `builds.sweep_sha256` or, with the ship catalog at hand,
// its model reproduces a calculated mean tension the database stores (the
// file edited since, e.g. a comment). All of that file's grids with a
// "calculated" mean tension must agree on the model; otherwise the database
// has no single basis and none is used.
#ifndef TOWDB_CLI_DATABASE_BASIS_HPP
#define TOWDB_CLI_DATABASE_BASIS_HPP

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/ship_file.hpp"
#include "propulsion/mean_tension.hpp"
#include "simulation/case_runner.hpp"
#include "sweep/spec/grid_tension.hpp"

namespace towdb::cli {

// The physics options of a database build and of every direct simulation
// compared with one (one thread per case: cases run in parallel).
simulation::CaseOptions build_case_options();

struct DatabaseBasis {
  sweep::MeanTensionModel model;  // hull margin, propeller, wind, sea resistance
  std::string source;             // where it was read, for the output
};

struct BasisLookup {
  std::optional<DatabaseBasis> basis;
  std::string reason;  // why there is none (empty when found)
};

// Reads the basis of the database at db_path (read-only). Never throws for a
// missing or changed sweep file: that is a BasisLookup without a basis. With
// a catalog, a sweep file whose bytes changed since the build (an edited
// comment, say) is still the basis when its model reproduces the calculated
// mean tension the database stores with its first such case (about 2 s of
// strip theory).
BasisLookup read_database_basis(const std::filesystem::path& db_path, const io::ShipCatalog* catalog = nullptr);

// The vessels of `names` whose ship file in the catalog is not the one the
// database was built with (its `vessels` table holds the name with another
// content SHA-256); a name the table does not hold is not checked.
std::vector<std::string> vessels_changed_since_build(const std::filesystem::path& db_path,
                                                     const io::ShipCatalog& catalog,
                                                     const std::vector<std::string>& names);

// The calculated mean tension and its parts at the question's speed [kt],
// wind [kt] and wave heading [deg] (EQ-SWEEP-1 as the sweep evaluates it).
struct CalculatedMeanTension {
  propulsion::MeanTensionBreakdown breakdown;  // SI, every part in N
  double total_lbf = 0.0;
  // Non-empty when the tow's ship file is not one the database was built with
  // (the value then differs from the database's own).
  std::string ship_file_note;
};
CalculatedMeanTension calculated_mean_tension(const DatabaseBasis& basis, const io::ShipCatalog& catalog,
                                              const std::filesystem::path& db_path, const std::string& tow_name,
                                              double speed_kt, double wind_kt, double heading_deg);

// The sweep-file words for the tow propeller ("locked", "free", "removed")
// and the sea resistance ("none", "strip-theory-head", "strip-theory").
const char* propeller_name(propulsion::TowPropellerState s);
const char* sea_resistance_name(sweep::SeaResistanceModel m);

// The model as the sweep-file keys write it, e.g. {"hull_margin": 0.1,
// "propeller": "locked", "mean_tension_wind": "head", "sea_resistance":
// "strip-theory-head"}.
nlohmann::ordered_json basis_json(const DatabaseBasis& basis);
// One line for text output.
std::string basis_text(const DatabaseBasis& basis);
// The breakdown in lbf with unit-suffixed keys (hull_lbf, propeller_lbf, ...).
nlohmann::ordered_json breakdown_json(const CalculatedMeanTension& t);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_DATABASE_BASIS_HPP
