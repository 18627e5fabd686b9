// towdb::sweep: the database generator around the one-case physics chain.
// Sweep files -> list of cases (with mean tensions from the Towing Manual
// method) -> parallel, resumable, incremental build of the SQLite database.
//
// This is the module's main header: it states what the module computes and
// includes the sub-headers that declare it.
//
// ---------------------------------------------------------------------------
// CONVENTIONS (re-derived here; the same at every towdb interface)
// ---------------------------------------------------------------------------
//   Wave and wind headings are relative to the tow's course: 0 deg =
//   following (trailing) seas, 180 deg = head seas. The mean tension's wind
//   term takes a head wind (mu = 180 deg) by default, as the thesis did: its
//   Appendix C lists one mean tension for all four headings of a condition.
//   Dynamic tension = total minus mean; the database value is the one with a
//   0.001 chance of exceedance in one day.
//
// ---------------------------------------------------------------------------
// UNITS
// ---------------------------------------------------------------------------
//   Sweep files, CaseSpec and the database use the user units of the thesis
//   (speed kt, wind kt, heading deg, length ft, tension lbf, period s), each
//   in the name; the mean-tension physics is called in SI (propulsion module)
//   and converted back once (lbf) when a grid tension is formed. CaseOutcome
//   is SI and is converted at the database writer (kips, lbf, ft, deg).
//
// ---------------------------------------------------------------------------
// EQUATIONS AND RULES
// ---------------------------------------------------------------------------
// EQ-SWEEP-1  Calculated mean tension of a condition (thesis ch. 2 and 5,
//   U.S. Navy Towing Manual App. G; EQ-PROPULSION-12):
//     T_calc(V, U) = (1 + m) R_H(V) + R_P(V) + R_W(V, U, mu_w) + R_S + R_line
//   m = 0.10 (thesis; the manual's 0.25 as an option), R_P the tow's locked
//   propeller (manual, eq. 2.5), R_W with the wind from ahead (mu_w = 180
//   deg, thesis Appendix C) or along the wave heading (option),
//   R_line = 0.10 (R_H' + R_P + R_W + R_S). R_S: the sea-state added
//   resistance. towdb has no Towing-Manual added-resistance curve, so R_S = 0
//   unless a strip-theory hook is given (ExpandOptions::sea_resistance); the
//   thesis itself (ch. 2) found the manual's R_S unreliable.
// EQ-SWEEP-2  Grid mean tensions of a condition (thesis ch. 5 and 7.2 item 3):
//     "calculated" basis:          T = f T_calc,   f = 1.15 and 0.85
//                                  (CG-47: f = 1.00 and 0.60)
//     "hull+half-propeller" basis: T = f [(1 + m) R_H(V) + R_P,locked(V) / 2]
//                                  (the thesis's lower third tension, T-ATF/FFG-7)
//     "given" basis:               T = the value written in the sweep file.
// EQ-SWEEP-3  Speed reduction (thesis ch. 5: "the tow speed is reduced until
//   a reasonable mean tension is achieved" when T_calc > 125,000 lbf):
//     V_k = V_0 - k dV,  k = the smallest integer >= 0 with T_calc(V_k) <= T_max.
//   If V_k would fall below V_min the condition is skipped and reported (it
//   is never dropped silently). dV = 1 kt, V_min = 3 kt by default (the
//   thesis's reduced AE-26 cases ran at 3 kt). A condition whose V_k is not
//   above another (lower) nominal speed of the same grid is skipped too: it
//   would repeat that speed's cases (the thesis "eliminated" such cases).
// EQ-SWEEP-4  Seed of a case (common random numbers):
//     seed = first 60 bits of SHA-256(base_seed | tug | tow | V | sea | mu)
//   The towline and the mean tension are left out on purpose: every towline
//   and mean tension of one condition sees the same random sea, so their
//   differences are not blurred by sampling noise.
// EQ-SWEEP-5  Identity of a sweep cell ("condition_key"):
//     SHA-256(sweep label | tug | tow | V_0 | sea | mu | line | length |
//             mean-tension label [| T when given])
//   It does not change when a ship file, the code version or the number of
//   days changes; the builder uses it to replace a stale case in place.
// EQ-SWEEP-6  Keys (incremental builds):
//     inputs_sha256 = SHA-256(every physical input: tug and tow file hashes,
//                     towline component hashes, V, sea, mu, line, length, T,
//                     days, seed)
//     case_key      = SHA-256(inputs_sha256 | condition_key | code version)
//     fit_key       = SHA-256(tug and tow file hashes | towline component
//                     hashes | line | length | T | code version)
//   A case is recomputed exactly when its case_key changes, except that a
//   stored case whose key is reproduced with the stored hash of an earlier
//   text of the same TOML document (comments or layout edited only) is
//   re-keyed instead (sweep/build/rekey.hpp).
// EQ-SWEEP-7  Determinism: case_id is assigned in sweep order when a case is
//   registered, before any computation; fit_id = the first 60 bits of the
//   fit_key read as an integer. Together with a deterministic runner this
//   makes every result row identical for any thread count, any number of MPI
//   ranks, and for an interrupted-and-resumed build (only the provenance
//   columns builds.*, cases.build_id, cases.updated_utc and
//   results.runtime_s differ).
//
// Literature: Desroches (1997) MIT thesis ch. 2, 5, 7.2; U.S. Navy Towing
// Manual SL740-AA-MAN-010 App. G (as reproduced in TB 55-1900-232-10).
#ifndef TOWDB_SWEEP_SWEEP_HPP
#define TOWDB_SWEEP_SWEEP_HPP

// The specification (spec/, library towdb::sweep_spec): what a sweep is.
#include "sweep/spec/calibration.hpp"   // Appendix C CSV -> sweep file
#include "sweep/spec/case.hpp"          // CaseSpec, CaseOutcome, CaseRunner
#include "sweep/spec/grid_tension.hpp"  // EQ-SWEEP-1..3
#include "sweep/spec/keys.hpp"          // EQ-SWEEP-4..7
#include "sweep/spec/sweep_file.hpp"    // sweep files and their expansion

// The build (build/, library towdb::sweep): how a database is made from it.
// build_lock, build_mpi and build_work are build.cpp's own parts (the file
// lock, the MPI coordinator and workers, the threads' work list).
#include "sweep/build/build.hpp"              // run_build, plan_build, BuildOptions
#include "sweep/build/distributed.hpp"        // the one MPI interface
#include "sweep/build/numerics.hpp"           // the machine's numerics fingerprint
#include "sweep/build/progress.hpp"           // the progress line
#include "sweep/build/serialize.hpp"          // bit-exact messages between ranks
#include "sweep/build/simulation_runner.hpp"  // the physics chain as the case runner
#include "sweep/build/status.hpp"             // towdb status
#include "sweep/build/writer.hpp"             // the one database writer

#endif  // TOWDB_SWEEP_SWEEP_HPP
