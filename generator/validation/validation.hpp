// Validation against the thesis database: every calibration case of the
// thesis's Appendix C (Desroches 1997; tests/data/validation/
// appendix_c_calibration.csv) is run through the whole chain
// (simulation::run_case) with its given inputs, and our dynamic tension at
// F = 0.999 per day is compared with the thesis's.
//
// Agreement measures (all dimensionless):
//   EQ-VALIDATION-1  ratio   r_i = T_ours,i / T_thesis,i   (dynamic tensions, same units)
//   EQ-VALIDATION-2  median  med(r): the middle value of the sorted r_i (mean of the two
//                    middle values for an even count)
//   EQ-VALIDATION-3  Spearman rank correlation
//                    rho = Pearson correlation of R(x_i) and R(y_i),
//                    R = the rank in ascending order, tied values get the average of
//                    the ranks they span (Spearman 1904; Kendall & Gibbons 1990, ch. 3).
//                    Without ties: rho = 1 - 6 sum d_i^2 / (n (n^2 - 1)), d_i = R(x_i) - R(y_i).
//   EQ-VALIDATION-4  share within a factor f (f >= 1):
//                    s_f = #{ i : 1/f <= r_i <= f } / n
//   EQ-VALIDATION-5  geometric mean ratio  exp( (1/n) sum ln r_i ),
//                    log scatter            sqrt( (1/n) sum (ln r_i)^2 )
// Cases whose thesis tension exceeds the validity limit (300 kips, thesis 6.2:
// "outside the bounds of the towline simulation model") are summarised apart;
// the targets apply to the cases below it.
//
// Inputs of one case (database units, converted to SI at the edge by
// case_inputs): tug, tow (catalog names), speed [kt], wind speed [kt] of a
// fully developed Pierson-Moskowitz sea (EQ-SEA-1, docs/physics.md 1.1), wave heading [deg]
// with 0 = following seas and 180 = head seas (thesis / MIT 5D convention, the
// same as sea::SeaState), hawser length [ft] (the tug's pendant is added by
// ShipCatalog::towline), hawser kind, mean tension [lbf] = the horizontal
// tension H, days. Outputs: dynamic tension [kips] = simulation's
// dynamic_999_n converted with units::n_to_kips. No sign conventions are
// introduced here; tensions are positive magnitudes.
//
// Days: a run may shorten the thesis's simulation length with days_scale
// (simulated days = max(min_days, round(days_scale * days))): the Type I
// estimate of the F = 0.999 value is unbiased in the number of days, only its
// scatter grows (thesis 4: 500-day runs vary 1.22 %, 100 days "reasonably
// accurate").
//
// Determinism: case i uses seed = its thesis case number; every case runs
// single-threaded inside and cases are spread over threads with
// towdb::parallel_for, so the outcomes are bit-identical for any thread count.
#ifndef TOWDB_VALIDATION_VALIDATION_HPP
#define TOWDB_VALIDATION_VALIDATION_HPP

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "io/ship_file.hpp"
#include "simulation/case_runner.hpp"
#include "sweep/spec/calibration.hpp"

namespace towdb::validation {

// The thesis's validity limit of the towline model (thesis 6.2) [kips].
inline constexpr double kThesisValidityLimitKips = 300.0;

struct RunOptions {
  double days_scale = 1.0;         // simulated days = round(days_scale * thesis days); (0, 10]
  int min_days = 20;               // floor on the simulated days: the case's GEV fit needs >= 10 maxima; [10, 1e6]
  int response_frequencies = 48;   // transfer-function frequency grid (CaseOptions); [8, 400]
  int num_threads = 1;             // cases in parallel (each case single-threaded); <= 0 = all cores
  // Diagnostics only (the thesis chain has both on): switch off a piece of
  // physics to see which one a disagreement comes from.
  bool second_order_forces = true;  // Newman slowly varying surge forces (CaseOptions)
  bool wave_surge_damping = true;   // wave-induced surge damping, thesis 3.5 (CaseOptions)
  // The thesis's towline fit (t3fer97: a10 fitted, plain least squares)
  // instead of EQ-TOWLINE-16's small-motion fit.
  bool thesis_towline_fit = false;
  // The tow's slowly varying force from the envelope at the tow
  // (CaseOptions::tow_drift_at_tow) instead of the thesis's shared envelope.
  bool tow_drift_at_tow = false;
  // Diagnostics (issue 17): Gerritsma-Beukelman aft of beam (EQ-AR-4) and the
  // drift coefficient's sign kept in Newman's force (CaseOptions::signed_drift).
  bool added_resistance_aft_of_beam = false;
  bool signed_drift = false;
  // Diagnostic (issue 17): EQ-SURGE-6 (CaseOptions::linear_non_surge_tension).
  bool linear_non_surge_tension = false;
  // With it: CaseOptions::non_surge_stiffness.
  simulation::CaseOptions::NonSurgeStiffness non_surge_stiffness = simulation::CaseOptions::NonSurgeStiffness::kA10;
  // Diagnostic (issue 17): CaseOptions::nonnegative_wave_damping.
  bool nonnegative_wave_damping = false;
  // Diagnostic (issue 17): the encounter-frequency cutoff of the forcing
  // records (CaseOptions::record, thesis eq. 3-22); the chain's is 3 rad/s,
  // the thesis's 5D grid ends at 2 rad/s. [1, 3] rad/s.
  double encounter_cutoff_rad_s = simulation::kEncounterCutoff_rad_s;
  // The surge diffraction force of EQ-STRIP-7 (seakeeping::ResponseOptions::
  // surge_diffraction), on as in the chain; false is issue 17's diagnostic of
  // the 0.3.0 chain (Froude-Krylov alone).
  bool surge_diffraction = true;
  void validate() const;
};

// Simulated days of one row under `options` (see the header comment).
int simulated_days(const sweep::CalibrationRow& row, const RunOptions& options);

// The physics inputs of one row (pointers into `catalog`, which must outlive
// the result): PM sea from wind_kt at heading_deg, hawser + pendant, H, days,
// seed = case number.
simulation::CaseInputs case_inputs(const sweep::CalibrationRow& row, const io::ShipCatalog& catalog, int days);

// The case options the validation uses: the library defaults, one thread
// inside the case, the given response grid.
simulation::CaseOptions case_options(const RunOptions& options);

enum class CaseStatus { kOk, kFailed };

struct CaseOutcome {
  sweep::CalibrationRow row;        // the thesis inputs and its result (dynamic_999_kips)
  int days_run = 0;
  CaseStatus status = CaseStatus::kFailed;
  std::string error;                // the exception text when failed (one line)
  double ours_kips = 0.0;           // our dynamic tension, F = 0.999 per day (Type I) [kips]
  double ci_low_kips = 0.0;         // bootstrap interval of ours [kips]
  double ci_high_kips = 0.0;
  double hs_ft = 0.0;               // significant wave height of the sea [ft]
  double slack_fraction = 0.0;      // of the simulated time
  bool above_breaking = false;      // mean + dynamic above the towline's breaking strength
  double runtime_s = 0.0;           // wall time of the case
  // Where the simulated days took the line (CaseResult::extension) against
  // the polynomial's fitted range [ft]; NaN (and days_outside_fit -1) when
  // the answer did not come from a simulation (a database's answers).
  double extension_sd_ft = std::numeric_limits<double>::quiet_NaN();
  double extension_min_ft = std::numeric_limits<double>::quiet_NaN();
  double extension_max_ft = std::numeric_limits<double>::quiet_NaN();
  double fit_min_ft = std::numeric_limits<double>::quiet_NaN();
  double fit_max_ft = std::numeric_limits<double>::quiet_NaN();
  int days_outside_fit = -1;

  double ratio() const { return ours_kips / row.dynamic_999_kips; }  // EQ-VALIDATION-1
};

// Runs one row. Never throws for a failing case: any exception becomes
// status kFailed with its message.
CaseOutcome run_one(const sweep::CalibrationRow& row, const io::ShipCatalog& catalog, const RunOptions& options);

// Runs `rows` (cases in parallel, options.num_threads). `done` holds outcomes
// of earlier runs (resume): a row whose case number and days_run match an ok
// outcome there is not run again. `on_outcome` is called (serialised) after
// each newly computed case, with the number finished so far and the total.
// Returns the outcomes in the order of `rows`.
using OutcomeCallback = std::function<void(const CaseOutcome& outcome, int finished, int total)>;
std::vector<CaseOutcome> run_all(const std::vector<sweep::CalibrationRow>& rows, const io::ShipCatalog& catalog,
                                 const RunOptions& options, const std::vector<CaseOutcome>& done = {},
                                 const OutcomeCallback& on_outcome = {});

// ---- Agreement statistics ------------------------------------------------------

// EQ-VALIDATION-2; throws InputError for an empty sample.
double median(std::vector<double> values);
// Ranks 1..n in ascending order, ties get their average rank.
std::vector<double> average_ranks(std::span<const double> values);
// EQ-VALIDATION-3; throws InputError when sizes differ or n < 2; NaN when a
// sample is constant.
double spearman_rank_correlation(std::span<const double> x, std::span<const double> y);

struct Agreement {
  std::string group;                // e.g. "all", "tow = FFG 7", "heading = 0 deg"
  int count = 0;
  double median_ratio = 0.0;        // EQ-VALIDATION-2
  double geometric_mean_ratio = 0.0;  // EQ-VALIDATION-5
  double log_rms = 0.0;             // EQ-VALIDATION-5
  double spearman = 0.0;            // EQ-VALIDATION-3 (NaN for n < 3)
  double within_1_5 = 0.0;          // EQ-VALIDATION-4, f = 1.5
  double within_2 = 0.0;            // EQ-VALIDATION-4, f = 2
};

// Agreement of ours vs thesis (positive values). Throws InputError when the
// sizes differ, a value is not positive, or the sample is empty.
Agreement agreement(const std::string& group, std::span<const double> ours, std::span<const double> thesis);

// The targets of the validation (project issue): on the cases below the
// validity limit, median ratio in [0.8, 1.25], Spearman >= 0.8, >= 70 % within
// a factor of 1.5.
struct Targets {
  double median_low = 0.8;
  double median_high = 1.25;
  double spearman_min = 0.8;
  double within_1_5_min = 0.70;
};

struct Report {
  std::vector<CaseOutcome> outcomes;   // all, in input order
  Agreement valid;                     // ok cases with thesis tension <= limit
  Agreement above_limit;               // ok cases with thesis tension > limit (count 0: none)
  Agreement all;                       // every ok case
  std::vector<Agreement> by_tow, by_tug, by_line, by_heading, by_wind;  // valid cases only
  // The line's extension by line type and heading (valid simulated cases).
  struct ExtensionGroup {
    std::string group;             // "wire 000 deg"
    int count = 0;
    double median_ratio = 0.0;
    double median_sd_ft = 0.0;     // median over the cases of the extension's sd
    double median_reach = 0.0;     // median of the largest excursion / the fitted half-range on its side
    int cases_outside_fit = 0;     // with at least one day outside the fitted range
    int cases_slack = 0;           // with any slack time
  };
  std::vector<ExtensionGroup> extension_by_line_heading;
  int failed = 0;
  bool median_ok = false, spearman_ok = false, within_ok = false;
};

Report make_report(std::vector<CaseOutcome> outcomes, const Targets& targets = {});

// The report as markdown: run description (`run_note`), targets met or missed,
// tables of the agreement by group, the cases above the limit, failures, and
// the largest disagreements.
std::string report_markdown(const Report& report, const std::string& run_note, const Targets& targets = {});

// ---- The per-case journal (CSV; also the resume state) ----------------------

// Header line of the journal.
std::string journal_header();
// One line (no newline) for an outcome; doubles with 17 significant digits so
// a resumed run reproduces the report bit for bit. Commas and line breaks in
// an error message are replaced by ';' and ' '.
std::string journal_line(const CaseOutcome& outcome);
// Reads a journal written by journal_line (header first). Lines that do not
// parse are skipped (a half-written last line after an interruption); the
// catalog is not needed, names are kept as written.
std::vector<CaseOutcome> parse_journal(const std::string& text);

}  // namespace towdb::validation

#endif  // TOWDB_VALIDATION_VALIDATION_HPP
