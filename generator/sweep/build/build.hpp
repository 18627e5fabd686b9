// `towdb build`: computes every case of a sweep into a towdb database.
//
//   - OpenMP over cases (towdb::parallel_for), or MPI ranks (rank 0 writes,
//     the others compute; dynamic scheduling), see distributed.hpp;
//   - ONE writer: results are handed from the workers to a single writer
//     thread through a queue; each case is committed in its own transaction
//     (WAL: a reader never sees half a case);
//   - deterministic: the same rows and bit-identical REAL values for any
//     thread or rank count (EQ-SWEEP-7 in sweep.hpp);
//   - incremental and resumable: a case is skipped when its case_key
//     (EQ-SWEEP-6) is already 'done'; pending or running cases (a killed
//     build) are recomputed; a changed sweep cell is replaced in place;
//   - a failed case is stored with its reason (status 'failed').
#ifndef TOWDB_SWEEP_BUILD_HPP
#define TOWDB_SWEEP_BUILD_HPP

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/version.hpp"
#include "io/ship_file.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/build/distributed.hpp"
#include "sweep/spec/keys.hpp"
#include "sweep/spec/sweep_file.hpp"
#include "sweep/build/profiles.hpp"
#include "sweep/build/speed_profiles.hpp"
#include "sweep/build/writer.hpp"

namespace towdb::sweep {

struct BuildOptions {
  // OpenMP threads computing cases in this process (>= 1).
  int threads = 1;
  // Continue after a build that did not finish (killed, crashed): without it
  // such a database is refused, so an accident is never silently resumed.
  bool resume = false;
  // Recompute cases that failed in an earlier build (default: keep them).
  bool retry_failed = false;
  // Enters every case_key: a new version recomputes everything.
  std::string code_version = kVersion;
  // Provenance: the command that ran (builds.command_line).
  std::string command_line;
  // Progress bar on stderr (only drawn when stderr is a terminal).
  bool progress = true;
  // Set asynchronously (e.g. by SIGINT) to stop starting cases; the build
  // then ends 'interrupted' with the unstarted cases still pending.
  const std::atomic<bool>* stop = nullptr;
  // MPI session; nullptr (or size 1) = one process.
  const distributed::Session* session = nullptr;
  // What the sweep leaves out and why (its expansion's notes and skipped
  // conditions), recorded in coverage_notes for refused questions to name.
  std::vector<CoverageNote> coverage_notes;
  std::vector<SkippedCondition> skipped;
  // Fills the lowest point of fits stored before schema 6 whose case is in
  // this sweep and up to date (nullptr: leaves them NULL).
  LowestPointFn lowest_elevation_m;
  // The last stage: each line's linear heading profile (profiles.hpp,
  // EQ-SWEEP-8) after the cases (nullptr: no profiles are stored or updated).
  HeadingProfileFn heading_profile;
  // Then each line's linear speed profile (speed_profiles.hpp, EQ-SWEEP-9;
  // nullptr: none are stored or updated).
  SpeedProfileFn speed_profile;

  // Throws InputError naming the field: threads in [1, 1024].
  void validate() const;
};

struct BuildSummary {
  std::int64_t build_id = 0;
  int total = 0;              // cases in the sweep
  int up_to_date = 0;         // already done: skipped
  int previously_failed = 0;  // failed in an earlier build and not retried
  int scheduled = 0;          // to compute in this run
  int done = 0;               // computed in this run
  int failed = 0;             // failed in this run
  bool interrupted = false;   // stopped before every scheduled case ran
  bool worker = false;        // an MPI worker rank: computed, wrote nothing
  int lowest_points_filled = 0;  // fits stored before schema 6 given their lowest point
  int maxima_repacked = 0;       // cases whose daily maxima were repacked as binary16 (maxima_precision)
  int rekeyed = 0;  // stored cases moved to new keys: their files changed in comments or layout only (rekey.hpp)
  ProfileSummary profiles;  // the heading-profile stage (lines 0 when it did not run)
  ProfileSummary speed_profiles;  // the speed-profile stage (lines 0 when it did not run)
  int slack_snatch_dropped = 0;  // cases whose per-day slack and snatch were dropped (day_records = "maxima")
  std::vector<std::string> failures;  // "case_id N (label): reason", this run
};

// Runs the build. Every MPI rank calls it with the same arguments. Input
// problems (database not writable, locked, corrupt, not towdb, an unfinished
// build without `resume`, unknown vessels) throw InputError before anything
// is written.
BuildSummary run_build(const std::filesystem::path& db_path, const SweepFile& sweep,
                       const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog, const CaseRunner& runner,
                       const BuildOptions& options);

// The numerics fingerprint (numerics.hpp) a database records in meta: that of
// its first build. None for a missing or empty file, a database written
// before version 0.2.0, or one not readable as a current towdb database.
std::optional<std::string> recorded_numerics_fingerprint(const std::filesystem::path& db_path);

// The dry run: every case with its keys and what a build would do with it
// ("new", "changed", "unfinished", "failed", "done"). Reads the database
// when it exists (never writes; nothing is created).
struct PlannedCase {
  CaseSpec spec;
  CaseKeys keys;
  CaseState state = CaseState::kNew;
  bool rekey = false;  // a stored case under earlier same-TOML file versions (rekey.hpp): re-keyed, not recomputed
};
std::vector<PlannedCase> plan_build(const std::optional<std::filesystem::path>& db_path,
                                    const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                                    const std::string& code_version);

// Keys of every case (InputError for unknown vessels or towlines).
std::vector<CaseKeys> compute_keys(const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                                   const std::string& code_version);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_BUILD_HPP
