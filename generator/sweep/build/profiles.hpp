// EQ-SWEEP-8, heading profiles: the build's last stage stores, for every line
// of finished cases that differ only in heading (same tug, tow, line type and
// length, speed, sea and mean tension; a wind or two-parameter sea without
// swell), the linear model's dynamic-tension standard deviation sigma(h) on a
// uniform heading grid, 0 to 180 deg every kProfileStepDeg (simulation
// EQ-CASE-3, without the wave-induced surge damping: simulation_runner.hpp
// profile_options). The query interpolates the simulated tension divided by this
// profile across a heading cell (query.h EQ-QUERY-11): near beam seas the
// tension has minima a few degrees wide that the linear model shares.
//
// Keys, resumability, determinism:
//   - profile_key = SHA-256 of "heading-profile/2", the grid and the sorted
//     case keys of the line's finished cases: a profile is recomputed exactly
//     when one of its cases changed (a case key covers every input and the
//     code version, EQ-SWEEP-6), and every case row names its profile;
//   - each profile is written with its cases' profile_id in one transaction:
//     a build killed in this stage resumes it with what is stored;
//   - a profile depends only on its line's inputs (the mean tension is the
//     line's one, the seed its first case's): the same bits for any thread or
//     rank count; lines are spread over threads with parallel_for;
//   - a line whose profile fails (a numerical error of the linear model) keeps
//     no profile and is counted; the query then interpolates its raw values.
#ifndef TOWDB_SWEEP_PROFILES_HPP
#define TOWDB_SWEEP_PROFILES_HPP

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "io/ship_file.hpp"
#include "store/database.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/spec/keys.hpp"

namespace towdb::sweep {

// Heading grid of a profile: 2.5 deg resolves the beam-sea minima (about
// 5-10 deg wide on the bundled grid's lines, docs/audit.md) at 73 strip-theory
// headings per vessel and speed.
inline constexpr double kProfileStepDeg = 2.5;
inline constexpr int kProfileHeadings = 73;  // 0, 2.5, ..., 180 deg

struct ProfileSummary {
  int lines = 0;       // lines of two or more headings among the finished cases
  int up_to_date = 0;  // stored already under the same profile_key
  int computed = 0;    // computed and stored by this run
  int failed = 0;      // the linear model failed: no profile stored
  bool interrupted = false;
  std::vector<std::string> failures;  // "line (first case_id N): reason"
};

// Brings every line's profile up to date for the sweep's `cases` (their
// `keys`); removes the profiles no case uses any more. `stop` as in
// BuildOptions.
ProfileSummary update_heading_profiles(store::Database& db, const std::vector<CaseSpec>& cases,
                                       const std::vector<CaseKeys>& keys, const io::ShipCatalog& catalog,
                                       const HeadingProfileFn& profile, int threads, std::int64_t build_id,
                                       const std::atomic<bool>* stop);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_PROFILES_HPP
