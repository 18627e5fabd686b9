// EQ-SWEEP-9, speed profiles: after the heading profiles (EQ-SWEEP-8) the
// build stores, for every line of finished cases that differ only in speed
// (same tug, tow, line type and length, sea and heading, and the same sweep
// entry and mean-tension label; a sea without swell), the linear model's dynamic-tension standard deviation
// sigma(V) on a uniform speed grid from the line's lowest stored speed to its
// highest, at most kSpeedProfileStepKt apart (simulation EQ-CASE-3, without the
// wave-induced surge damping as EQ-SWEEP-8). The query
// interpolates the simulated tension divided by this profile across a speed
// cell (query.h EQ-QUERY-12): in following and quartering seas the encounter
// frequency folds (w_e = g / 4V) through the coupled surge system's response,
// and the tension swings by a factor of 7 within 1 kt; the linear model swings
// with it, the ratio by a factor of 1.7 (docs/audit.md).
//
// The mean tension along a line. A line's cases keep one mean-tension rule
// (its label): an absolute tension (the same at every speed), a factor of the
// calculated tension T_calc of each case's own speed (EQ-SWEEP-1), or a
// resistance at that speed. Between two stored
// speeds V_i < V < V_i+1 the profile's mean tension is
//   m(V) = m_i^(1 - t) m_i+1^t,   t = (V - V_i) / (V_i+1 - V_i),
// the stored cases' own tensions joined geometrically: constant for an
// absolute rule, and for a factor exactly the factor times the query's
// T_calc, which the query interpolates the same way (query.h EQ-QUERY-9).
// At a stored speed the profile point is the case's own linear model without
// the wave-induced surge damping (simulation_runner.hpp profile_options).
//
// Keys, resumability, determinism (as EQ-SWEEP-8):
//   - profile_key = SHA-256 of "speed-profile/2", the step and the sorted
//     case keys of the line: recomputed exactly when one of its cases changed;
//     the keys are read into memory (no index on them: the file's bytes go to
//     cases);
//   - each profile is written with its cases' speed_profile_id in one
//     transaction: a build killed in this stage resumes with what is stored;
//   - a profile depends only on its line's stored cases: the same bits for any
//     thread or rank count;
//   - a line whose profile fails keeps none and is counted; a line with two
//     mean tensions at one speed (a reduced speed meeting a nominal one) gets
//     none, while headings h and 360 - h (one line) share their points.
// Units: kt and lbf as the cases columns, sigma in kips stored as binary16
// (0.05 % rounding at most; the query takes differences of ln sigma).
#ifndef TOWDB_SWEEP_SPEED_PROFILES_HPP
#define TOWDB_SWEEP_SPEED_PROFILES_HPP

#include <atomic>
#include <cstdint>
#include <vector>

#include "io/ship_file.hpp"
#include "store/database.hpp"
#include "sweep/build/profiles.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/spec/keys.hpp"

namespace towdb::sweep {

// Largest speed step of a profile: the fold's features are about 0.5 kt wide
// (the linear sigma of docs/audit.md's following-sea line: 281, 103, 592, 183
// kN at 6.75, 7.0, 7.25, 7.5 kt); 0.25 kt puts 17 points between 5 and 9 kt.
inline constexpr double kSpeedProfileStepKt = 0.25;

// The profile grid of a line with stored speeds `speeds_kt` (ascending,
// distinct) and their mean tensions: n = ceil(span / kSpeedProfileStepKt) + 1
// points from the first speed to the last, each with m(V) as in the header.
std::vector<SpeedPoint> speed_profile_points(const std::vector<double>& speeds_kt,
                                             const std::vector<double>& mean_tensions_lbf);

// Brings every line's speed profile up to date for the sweep's `cases`
// (their `keys`); removes the profiles no case uses any more. `stop` as in
// BuildOptions. The summary counts as ProfileSummary does.
ProfileSummary update_speed_profiles(store::Database& db, const std::vector<CaseSpec>& cases,
                                     const std::vector<CaseKeys>& keys, const io::ShipCatalog& catalog,
                                     const SpeedProfileFn& profile, int threads, std::int64_t build_id,
                                     const std::atomic<bool>* stop);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_SPEED_PROFILES_HPP
