// The production case runner of `towdb build`: a sweep CaseSpec through the
// whole physics chain (simulation::run_case) to a CaseOutcome, and the
// strip-theory sea-state added resistance for the calculated mean tension
// (thesis eq. 2.2 instead of the Towing Manual's direction-blind curve).
//
// Conventions: the sweep's sea is turned into sea::SeaState as
//   Pierson-Moskowitz   wind_kt (fully developed, the thesis's default)
//   Bretschneider       hs_ft, tp_s (peak period)
//   JONSWAP             hs_ft, tp_s, gamma
//   + swell             Bretschneider hs_ft, tp_s at its own heading
// headings 0 = following seas. Units converted here, once.
#ifndef TOWDB_SWEEP_SIMULATION_RUNNER_HPP
#define TOWDB_SWEEP_SIMULATION_RUNNER_HPP

#include "sea/spectrum.hpp"
#include "simulation/case_runner.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/spec/sweep_file.hpp"

namespace towdb::sweep {

// The sea of a case (wind sea at heading_deg, plus its swell if any).
sea::SeaState sea_state(const SeaSpec& sea, double heading_deg);

// run_case with `options` (days and seed from the spec). Within a build the
// cases run in parallel, so options.num_threads should be 1.
CaseRunner simulation_case_runner(simulation::CaseOptions options);

// The lowest point of the static catenary simulation_case_runner's fit of the
// same case stores (towline EQ-TOWLINE-1, same solver options): for fits
// written before schema 6.
LowestPointFn static_lowest_elevation(simulation::CaseOptions options);

// The linear heading profile of a case's line (simulation EQ-CASE-3) with
// `options` (responses shared with the cases through the response cache),
// without the wave-induced surge damping (profile_options).
HeadingProfileFn linear_heading_profile(simulation::CaseOptions options);

// The linear speed profile of a case's line (simulation EQ-CASE-3 at each
// point's speed and mean tension; responses shared through the response
// cache, towline fits through the fit cache), without the wave-induced surge
// damping (profile_options).
SpeedProfileFn linear_speed_profile(simulation::CaseOptions options);

// The case options of a profile: `options` without the wave-induced surge
// damping (EQ-AR-3). A profile is used only through its shape within a cell
// (query.h EQ-QUERY-11, 12: the stored tension divided by the profile), and
// that damping, a derivative of the added resistance by speed, costs a second
// strip theory of both vessels at U + dU: half of the profile stage. Measured
// on five lines (T-ATF with LHA 1, FFG 7, AE 26, YRBM, CG 47): the profile's
// shape within a cell moves by 1.4 % at most (the LHA 1, whose wave damping is
// negative in bow seas) and by 0.01 % on the others (docs/database-history.md,
// version 0.4.0).
simulation::CaseOptions profile_options(simulation::CaseOptions options);

// R_S = 2 int R_aw/zeta^2 S dw of the tow (seakeeping EQ-AR-2), summed over
// the wave systems, on the case grid of `options` (responses shared with the
// cases through simulation::cached_responses).
SeaResistanceFn strip_theory_sea_resistance(simulation::CaseOptions options);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_SIMULATION_RUNNER_HPP
