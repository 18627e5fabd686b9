// The database writer of a build: the only code that writes towdb's tables.
// It runs on ONE thread (the builder's writer thread, or MPI rank 0); each
// case is committed in its own transaction, so a reader (WAL) sees a case
// either not at all or complete. Converts CaseOutcome (SI) to the schema's
// user units (kips, lbf, ft, deg) once, here.
#ifndef TOWDB_SWEEP_WRITER_HPP
#define TOWDB_SWEEP_WRITER_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/ship_file.hpp"
#include "store/database.hpp"
#include "sweep/build/rekey.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/spec/keys.hpp"
#include "sweep/spec/sweep_file.hpp"

namespace towdb::sweep {

// ISO 8601 UTC "2026-01-31T12:00:00Z" of now.
std::string utc_now();

struct BuildProvenance {
  std::string code_version;
  std::string command_line;
  std::string sweep_file;
  std::string sweep_sha256;
  std::string host;
  int threads = 1;
  int mpi_ranks = 1;
};

// What registration found for one case of the sweep.
enum class CaseState {
  kNew,        // not in the database: inserted as pending
  kChanged,    // same sweep cell, changed inputs (EQ-SWEEP-5/6): replaced in place, pending
  kUnfinished, // pending or running from an earlier build: recomputed
  kFailed,     // failed in an earlier build (recomputed only with retry_failed)
  kDone,       // up to date: skipped
};
const char* to_string(CaseState state);
// The state of a case the database already holds, from its cases.status
// ('done', 'failed'; 'pending' or 'running' are unfinished).
CaseState state_of_stored(std::string_view status);
// Whether a build computes a case in this state (the one rule for builds,
// their dry runs and the checks made before writing).
bool computes(CaseState state, bool retry_failed);

struct RegisteredCase {
  std::int64_t case_id = 0;
  CaseState state = CaseState::kNew;
  bool rekeyed = false;  // a stored case moved to its current keys (rekey.hpp)
};

struct FitWithoutLowestPoint {
  std::int64_t fit_id = 0;
  std::int64_t case_id = 0;  // a finished case that uses it
};

// Whether towline_fits holds the fit of `fit_key` under its EQ-SWEEP-7 id;
// StorageError when another key holds that id (a 60-bit id collision).
bool fit_is_stored(store::Database& db, std::int64_t fit_id, const std::string& fit_key);

class DatabaseWriter {
 public:
  explicit DatabaseWriter(store::Database& db) : db_(db) {}

  // Builds whose status is still 'running' (killed or crashed runs).
  std::vector<std::int64_t> unfinished_builds();
  // Marks them 'interrupted'.
  void mark_interrupted(const std::vector<std::int64_t>& build_ids);

  std::int64_t begin_build(const BuildProvenance& provenance);
  // Replaces the coverage notes of earlier builds of the same sweep file by
  // this build's (schema 5 coverage_notes; one transaction).
  void record_coverage(std::int64_t build_id, const std::string& sweep_file, const std::vector<CoverageNote>& notes,
                       const std::vector<SkippedCondition>& skipped);
  void finish_build(std::int64_t build_id, const std::string& status, int cases_done, int cases_failed);

  // Inserts the vessels, towline components and cases of a sweep (one
  // transaction; case_id in sweep order, EQ-SWEEP-7). `retry_failed` resets
  // failed cases to pending. With `earlier`, a case that is a stored case
  // under earlier same-TOML versions of its files is moved to its current keys
  // (rekey.hpp) and keeps its state.
  std::vector<RegisteredCase> register_cases(const std::vector<CaseSpec>& specs, const std::vector<CaseKeys>& keys,
                                             const io::ShipCatalog& catalog, std::int64_t build_id,
                                             bool retry_failed, EarlierShipFiles* earlier = nullptr);

  // What write_result keeps of each day (the sweep file's day_records).
  void set_day_records(DayRecords records) { day_records_ = records; }
  // day_records = "maxima": drops the per-day slack time and snatch count of
  // the cases already stored (one transaction); returns how many changed.
  int drop_slack_snatch_days();
  // How write_result stores each daily maximum (the sweep file's maxima_precision).
  void set_maxima_precision(MaximaPrecision precision) { maxima_precision_ = precision; }
  // maxima_precision = "binary16": repacks the binary32 maxima of the cases
  // already stored (one transaction); returns how many changed.
  int pack_maxima_binary16();

  void mark_running(std::int64_t case_id, std::int64_t build_id);
  // The fit, the results row, every day and status 'done', in one transaction.
  void write_result(std::int64_t case_id, const CaseSpec& spec, const CaseKeys& keys, const CaseOutcome& outcome,
                    double runtime_s, const std::string& code_version, std::int64_t build_id);
  // status 'failed' with the reason (never dropped).
  void write_failure(std::int64_t case_id, const std::string& message, std::int64_t build_id);

  // Fits written before schema 6 have no lowest point (NULL
  // lowest_elevation_ft): every finished case of such a fit, by fit_id.
  std::vector<FitWithoutLowestPoint> fits_without_lowest_point();
  // Stores the lowest points a build computed for them (one transaction).
  void set_lowest_points(const std::vector<std::pair<std::int64_t, double>>& fit_id_elevation_m);

 private:
  std::int64_t register_vessel(const io::VesselFile& vf);
  void register_component(const model::TowlineComponent& c);
  store::Database& db_;
  DayRecords day_records_ = DayRecords::kAll;
  MaximaPrecision maxima_precision_ = MaximaPrecision::kBinary32;
};

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_WRITER_HPP
