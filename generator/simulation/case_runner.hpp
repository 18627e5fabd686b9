// One towing case from start to finish: the whole thesis chain for one tug,
// tow, speed, sea, heading, towline and mean tension (thesis 3.7, Appendix A
// programs cabnexp ... calcstat; docs/physics.md sections 1-7).
//
// Steps (each module states its own equations):
//   1. towline/  static catenary and the polynomial towline tau(xi, xi') fitted
//      to shallow-sag cable dynamics (cached per towline, tow points and H);
//   2. seakeeping/  strip theory of tug and tow at speed U and U + 1 ft/s for
//      each wave system's heading, on a grid of absolute frequencies spanning
//      the sea's components; added resistance and the wave-induced surge
//      damping (R(U + 1 ft/s) - R(U)) / (1 ft/s) in the case's spectrum;
//   3. propulsion/  hull surge damping of both vessels, the tug's propeller
//      damping at constant RPM for this mean tension, optionally the tow's
//      locked or free-spinning propeller;
//   4. coupled/  the 12-DOF model with the linearised line (a10, a01): the
//      first-order surge force on each vessel, the non-surge extension xi_ns
//      and the drift coefficients, per frequency;
//   5. sea/  per day one periodic record in the encounter frame (random
//      phases from (seed, day)) of f1_tug, f1_tow, xi_ns, xi_ns' and the
//      second-order slowly varying forces f2_tug, f2_tow (Newman);
//   6. simulation/surge.hpp  the nonlinear surge of both vessels on the
//      polynomial towline with slack line, the day's maximum dynamic tension;
//   7. statistics/  Gumbel (moments, the thesis's value; maximum likelihood),
//      GEV, a bootstrap confidence interval, goodness of fit, the empirical
//      quantiles when there are enough days.
// Transfer functions are computed on a frequency grid and interpolated
// linearly in frequency onto the record's components; the phase lag of the
// tow, exp(i k G cos mu), is applied per component (coupled EQ-COUPLED-4),
// so only smooth functions are interpolated. With
// CaseOptions::tow_drift_at_tow (a diagnostic, off as in the thesis) the same
// lag places the tow's slowly varying force in the wave envelope at the tow
// (EQ-CASE-2 in case_runner.cpp, sea EQ-SEA-9): wave groups then reach tug
// and tow one group travel time apart, not at once.
// Days are independent (each its own warm-up, simulation/surge.hpp) and run in
// parallel; the result depends only on the inputs and the seed, bit-identical
// for any thread count.
// Units: SI inside; the CLI converts at the edge.
#ifndef TOWDB_SIMULATION_CASE_RUNNER_HPP
#define TOWDB_SIMULATION_CASE_RUNNER_HPP

#include <array>
#include <complex>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "model/towline.hpp"
#include "model/vessel.hpp"
#include "propulsion/tow_propeller.hpp"
#include "propulsion/tug_propeller.hpp"
#include "sea/record.hpp"
#include "sea/spectrum.hpp"
#include "seakeeping/seakeeping.hpp"
#include "simulation/response_cache.hpp"
#include "simulation/surge.hpp"
#include "towline/towline.hpp"

namespace towdb::simulation {

// The tension law the time-domain simulation uses.
enum class TensionLaw {
  kPolynomial,  // the fitted 9-coefficient polynomial (the thesis)
  kLinear,      // tau = a10 xi + a01 xi', no slack limit (for the linear-limit check)
};

struct CaseInputs {
  const model::Vessel* tug = nullptr;
  const model::Vessel* tow = nullptr;
  model::Towline towline;          // tug -> tow (hawser, pendant)
  double speed_m_s = 0.0;          // tow speed U through the water
  sea::SeaState sea;               // wave systems with their headings (0 = following)
  double mean_tension_n = 0.0;     // H, the horizontal mean tension
  int days = 500;                  // simulated days used for the statistics
  std::uint64_t seed = 1;          // day d uses the random stream (seed, d)

  void validate() const;
};

// Encounter frequencies above 3 rad/s do not move ships of these sizes
// (thesis 3.7: "higher frequencies do not effect ship motions"); the chain's
// cutoff of the forcing records (the dropped energy is reported as
// retained_variance_fraction).
inline constexpr double kEncounterCutoff_rad_s = 3.0;

struct CaseOptions {
  towline::TowlineFitOptions towline;  // cable dynamics and polynomial fit
  towline::AboveBreakingModel above_breaking = towline::AboveBreakingModel::kPolynomial;  // thesis default
  TensionLaw tension_law = TensionLaw::kPolynomial;
  bool second_order_forces = true;     // Newman slowly varying surge forces (thesis: on)
  // Diagnostic (issue 17), off as in the thesis: build the tow's slowly
  // varying force from the wave envelope at the tow, G astern (EQ-CASE-2),
  // instead of the envelope both vessels share in sapc97 (docs/physics.md
  // 1.4: one envelope, f2_k = -|sum a_j sqrt(D_k) exp(i(w_e t + phi_j))|^2).
  // Physically the groups reach the tow later, but with the lag the head-sea
  // tensions move further from the thesis (docs/validation.md, "Issue 17").
  bool tow_drift_at_tow = false;
  // Diagnostic (issue 17), off: keep the sign of the drift coefficient
  // D = R_aw / zeta^2 in Newman's construction (EQ-SEA-9 with D < 0: a
  // slowly varying thrust) instead of D = max(0, R_aw / zeta^2). Acts aft of
  // beam only with response.added_resistance_aft_of_beam (EQ-AR-4).
  bool signed_drift = false;
  // Diagnostic (issue 17), off: EQ-SURGE-6, the non-surge extension as a
  // linear tension (a10, a01 of the 12-DOF model's line) added to the
  // polynomial of the surge extension, instead of inside its argument.
  bool linear_non_surge_tension = false;
  // With linear_non_surge_tension: which stiffness and damping carry the
  // non-surge tension. kA10: the polynomial's linear terms (a10, a01);
  // kEquivalentNonSurge / kEquivalentTotal: Gaussian equivalent linearisation
  // (EQ-SURGE-7) over the non-surge extension alone, or over the whole
  // first-order extension of the linear surge system (iterated to a fixed point).
  enum class NonSurgeStiffness { kA10, kEquivalentNonSurge, kEquivalentTotal };
  NonSurgeStiffness non_surge_stiffness = NonSurgeStiffness::kA10;
  // Diagnostic (issue 17), off: the wave-induced surge damping held at >= 0
  // per vessel (the thesis holds only its propeller damping positive).
  bool nonnegative_wave_damping = false;
  seakeeping::ResponseOptions response;  // strip theory
  // Absolute-frequency grid of the transfer functions: uniform on [lo, hi],
  // independent of the sea so that responses are shared between cases
  // (cached per vessel, speed, heading). 64 points resolve the Froude-Krylov
  // surge force's oscillation with hull length (period dk = 2 pi / L, i.e.
  // dw = g dk / 2w = 0.09 rad/s at w = 1.5 rad/s for the LHA 1).
  int response_frequencies = 64;
  double response_omega_min_rad_s = 0.2;   // below it these seas carry no energy
  double response_omega_max_rad_s = 3.0;   // above it no ship of these sizes responds
  propulsion::TugPropellerDampingOptions tug_propeller;  // thesis 3.6
  propulsion::TowPropellerOptions tow_propeller = [] {
    propulsion::TowPropellerOptions o;
    o.state = propulsion::TowPropellerState::kRemoved;  // thesis: tow propeller damping not included
    return o;
  }();
  bool wave_surge_damping = true;      // thesis 3.5
  sea::RecordOptions record = [] {
    sea::RecordOptions o;
    o.encounter_cutoff_rad_s = kEncounterCutoff_rad_s;
    o.max_time_step_s = 1.0;           // forcing sampled at least every second
    return o;
  }();
  IntegratorOptions integrator;
  int num_threads = 0;                 // days in parallel (<= 0: all cores); no effect on results
  double confidence_level = 0.90;      // bootstrap interval of the F = 0.999 value
  int bootstrap_replicates = 1000;
  std::function<void(int done, int total)> progress;  // called after each day (any thread, serialised)

  void validate() const;
};

struct DayResult {
  double max_dynamic_tension_n = 0.0;
  double slack_time_s = 0.0;
  int snatch_events = 0;
  double tension_mean_n = 0.0;      // time mean of tau over the day
  double tension_variance_n2 = 0.0;  // time variance of tau over the day
  // The extension the tension law saw at the forcing samples (surge.hpp
  // DayStatistics): its range, time mean and time variance over the day.
  double extension_min_m = 0.0, extension_max_m = 0.0;
  double extension_mean_m = 0.0, extension_variance_m2 = 0.0;
};

// Where the simulated days took the line, against the range of the samples
// the polynomial was fitted to (towline FitSummary fit_xi_min_m ..
// fit_xi_max_m). Outside it the law continues linearly from the range's edge
// (EQ-CASE-1): a tension read there is an extrapolation of the cable
// dynamics, so a planner and a maintainer should know how often it happens.
struct ExtensionSummary {
  double mean_m = 0.0;         // time mean over all days
  double sd_m = 0.0;           // time standard deviation over all days (pooled)
  double min_m = 0.0, max_m = 0.0;  // over all days
  int days_outside_fit = 0;    // days whose range left [fit_xi_min_m, fit_xi_max_m]
};

struct CaseStatistics {
  double gumbel_u_n = 0.0;           // method of moments (the thesis's value)
  double gumbel_alpha_per_n = 0.0;
  double daily_max_mean_n = 0.0;
  double daily_max_variance_n2 = 0.0;
  double dynamic_999_n = 0.0;        // Type I at F = 0.999
  double dynamic_99_n = 0.0;
  double empirical_999_n = 0.0;      // order statistics, NaN when days < 5 / (1 - F)
  double empirical_99_n = 0.0;
  double ci_level = 0.0;
  double ci_low_n = 0.0;
  double ci_high_n = 0.0;
  double gumbel_ml_u_n = 0.0;
  double gumbel_ml_alpha_per_n = 0.0;
  double gev_mu_n = 0.0, gev_sigma_n = 0.0, gev_xi = 0.0;
  double anderson_darling = 0.0;
  double ppcc = 0.0;
  double max_daily_max_n = 0.0;
};

struct CaseTimings {
  double towline_s = 0.0;
  double hydrodynamics_s = 0.0;
  double synthesis_s = 0.0;       // FFT records, summed over days and threads
  double integration_s = 0.0;     // surge integration, summed over days and threads
  double statistics_s = 0.0;
  double total_s = 0.0;           // wall time of run_case
};

struct CaseResult {
  towline::FitSummary towline;
  double separation_m = 0.0;          // G, tug origin to tow origin
  double tug_mass_kg = 0.0, tow_mass_kg = 0.0;  // with surge added mass
  double tug_hull_damping_n_s_m = 0.0, tug_propeller_damping_n_s_m = 0.0, tug_wave_damping_n_s_m = 0.0;
  double tow_hull_damping_n_s_m = 0.0, tow_propeller_damping_n_s_m = 0.0, tow_wave_damping_n_s_m = 0.0;
  double tug_added_resistance_n = 0.0, tow_added_resistance_n = 0.0;  // mean, in the case's sea
  double record_time_step_s = 0.0;
  std::int64_t record_samples = 0;
  std::size_t wave_components = 0;
  double retained_variance_fraction = 0.0;
  bool fft_plan_from_stored_wisdom = false;  // sea/fft_wisdom.hpp; false: FFTW_ESTIMATE's plan
  LaneIsa lane_isa = LaneIsa::kBaseline;      // vectors of the lock-step integration (same results for any)
  std::vector<DayResult> days;
  CaseStatistics statistics;
  double slack_fraction = 0.0;
  double snatch_events_per_day = 0.0;
  bool above_breaking_strength = false;  // mean + dynamic_999 > breaking strength
  ExtensionSummary extension;
  long substeps = 0;
  CaseTimings timings;
};

// Runs the case. Throws InputError for bad inputs, NumericalError when a
// solver fails. Strip-theory responses are memoised process-wide per
// (vessel file, speed, heading, frequency grid, options), like towline fits.
CaseResult run_case(const CaseInputs& inputs, const CaseOptions& options = {});

// The absolute-frequency grid of CaseOptions (uniform, response_frequencies points).
std::vector<double> response_grid(const CaseOptions& options);

// ---- For tests and tools -----------------------------------------------------

// The linear frequency-domain prediction of the dynamic tension for the same
// case (linear towline a10, a01; first-order forces only): per wave component,
// tau_j solves the 2-DOF surge system of EQ-SURGE-1..3 with forcing f1 and
// xi_ns; variance = sum_j |tau_j|^2 a_j^2 / 2 [N^2].
double linear_tension_variance_n2(const CaseInputs& inputs, const CaseOptions& options = {});

// EQ-CASE-3, the linear heading profile: the standard deviation [N] of the
// linear prediction above at each heading of `headings_deg` (0 = following
// seas, the case's one wave system turned to it; every other input, the mean
// tension included, as in `inputs`). Between two headings where the chain
// was simulated, the query interpolates the ratio of the simulated tension to
// this profile instead of the tension itself (query.h EQ-QUERY-11): near
// beam seas the tension has minima a few degrees wide where the first-order
// surge force (which turns with cos mu) and the heave/pitch extension (which
// does not) cancel in the line; the linear model has the same minima, the
// ratio does not (docs/audit.md). InputError for a sea of more than one system.
std::vector<double> linear_tension_sigma_by_heading_n(const CaseInputs& inputs, const CaseOptions& options,
                                                       const std::vector<double>& headings_deg);

// Computes the surge forcing of one day of the case (for plots and tests):
// tug and tow forces (f1 + f2), xi_ns and its rate.
struct CaseModel;  // the per-case precomputation (opaque)
std::shared_ptr<const CaseModel> prepare_case(const CaseInputs& inputs, const CaseOptions& options);
DayForcing day_forcing(const CaseModel& model, std::uint64_t seed, std::uint64_t day);
// Simulates one day of a prepared case; `trace` as in integrate_day.
DayStatistics simulate_day(const CaseModel& model, const DayForcing& forcing, const IntegratorOptions& options,
                           std::vector<double>* trace = nullptr);

// Days run_case integrates together (surge.hpp integrate_days_fastest): one
// 4-double AVX register where the processor has AVX2, else two 2-double
// vectors. Four: a whole case is fastest with four (eight days' records no
// longer stay in cache; docs/performance.md, "The chain, stage by stage").
inline constexpr std::size_t kLockstepDays = 4;
// kLockstepDays days of a prepared case in lock step (their records
// interleaved), with the vectors `isa` names; day l's statistics equal
// simulate_day on day l alone, bit for bit, for any isa.
std::array<DayStatistics, kLockstepDays> simulate_days(const CaseModel& model,
                                                      const LockstepForcing<kLockstepDays>& forcing,
                                                      const IntegratorOptions& options,
                                                      LaneIsa isa = fastest_lane_isa());

}  // namespace towdb::simulation

#endif  // TOWDB_SIMULATION_CASE_RUNNER_HPP
