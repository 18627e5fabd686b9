// Sweep files (db/sweeps/*.toml, format "towdb-sweep-1", documented in
// docs/sweep-files.md): grids of towing conditions and explicit cases, read
// through the strict TOML layer (unknown keys, wrong types and out-of-range
// numbers are errors with file:line), and their expansion into CaseSpecs.
//
// Expansion order (deterministic, the order of case_id): entries in file
// order; inside a grid: tug, tow, speed, sea, heading, towline, mean tension.
#ifndef TOWDB_SWEEP_SWEEP_FILE_HPP
#define TOWDB_SWEEP_SWEEP_FILE_HPP

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/ship_file.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/spec/grid_tension.hpp"

namespace towdb::sweep {

enum class MeanTensionBasis {
  kCalculated,         // f T_calc (EQ-SWEEP-1, -2)
  kHullHalfPropeller,  // f [(1 + m) R_H + R_P / 2] (EQ-SWEEP-2)
  kGiven,              // value_lbf as written
};

struct MeanTensionLevel {
  std::string label;                // stored in cases.mean_tension_label
  MeanTensionBasis basis = MeanTensionBasis::kCalculated;
  double factor = 1.0;              // f
  std::optional<double> value_lbf;  // kGiven only
};

struct TowlineChoice {
  model::LineKind line = model::LineKind::kWire;
  double length_ft = 0.0;
};

// A grid: the Cartesian product of its lists.
struct GridEntry {
  std::string label;
  int line = 0;  // source line of the entry, for messages
  std::vector<std::string> tugs;
  std::vector<std::string> tows;
  std::vector<double> speeds_kt;
  std::vector<SeaSpec> seas;
  std::vector<double> headings_deg;
  std::vector<TowlineChoice> towlines;
  std::vector<MeanTensionLevel> mean_tensions;
  int days = 0;
  std::int64_t base_seed = 0;
  MeanTensionModel mean_model;
  // What the grid leaves out and why, in the sweep author's words ("" when
  // none): stored in coverage_notes for a refused question to name.
  std::string coverage_note;
};

// One explicit case (given mean tension unless a level says otherwise).
struct CaseEntry {
  std::string label;
  int line = 0;
  CaseSpec spec;                      // seed and condition_key filled at expansion
  std::optional<std::int64_t> seed;   // explicit seed; else EQ-SWEEP-4
  std::int64_t base_seed = 0;
};

// What each case of the sweep keeps of its simulated days (top-level key
// day_records): "all" = the daily maximum, slack time and snatch count;
// "maxima" = the daily maximum only (schema 7; the case's slack fraction and
// snatch rate stay in results), for a database kept to a size budget.
enum class DayRecords { kAll, kMaxima };

// How each daily maximum is stored (top-level key maxima_precision):
// "binary32" (4 bytes a day) or "binary16" (2 bytes, schema 8: 0.05 % relative
// rounding at most; store/packed_days.hpp).
enum class MaximaPrecision { kBinary32, kBinary16 };

struct SweepFile {
  std::string path;
  std::string sha256;  // of the file's bytes
  std::string description;
  DayRecords day_records = DayRecords::kAll;
  MaximaPrecision maxima_precision = MaximaPrecision::kBinary32;
  std::vector<GridEntry> grids;
  std::vector<CaseEntry> cases;
};

// Parses a sweep file's text (`path` for messages). Throws InputError
// "path:line: key: problem".
SweepFile parse_sweep(std::string_view text, const std::string& path);
// Reads and parses; a missing file is an InputError.
SweepFile load_sweep(const std::filesystem::path& path);

// A grid cell that could not be towed (EQ-SWEEP-3), reported, never silent.
struct SkippedCondition {
  std::string sweep_label;
  std::string tug;
  std::string tow;
  double nominal_speed_kt = 0.0;
  std::string sea;
  double heading_deg = 0.0;
  std::string reason;
};

// A grid's coverage_note for one of its tug and tow pairs (canonical names).
struct CoverageNote {
  std::string sweep_label;
  std::string tug;
  std::string tow;
  std::string note;
};

struct SweepExpansion {
  std::vector<CaseSpec> cases;
  std::vector<SkippedCondition> skipped;
  std::vector<CoverageNote> notes;
};

// R_S [N] of a tow at speed [kt] in a sea at wave heading [deg]: the hook
// through which strip-theory added resistance enters EQ-SWEEP-1.
using SeaResistanceFn = std::function<double(const model::Vessel& tow, double speed_kt, const SeaSpec& sea,
                                             double heading_deg)>;

struct ExpandOptions {
  // Strip-theory sea-state added resistance, used by entries whose
  // sea_resistance setting is not "none" (towdb has no Towing-Manual R_S
  // curve; see EQ-SWEEP-1). Such entries are refused when it is empty.
  SeaResistanceFn sea_resistance;
};

// Expands every entry into cases, resolving vessel names to the catalog's
// canonical names. Throws InputError naming the entry (file:line) for unknown
// vessels, a tow that is a tug's towline-less vessel, a "calculated" tension
// without a wind, or two entries that give the same case.
SweepExpansion expand_sweep(const SweepFile& sweep, const io::ShipCatalog& catalog, const ExpandOptions& options = {});

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_SWEEP_FILE_HPP
