// One towing case of the database: every input (CaseSpec), everything the
// physics chain returns for it (CaseOutcome), and the injected function that
// computes one case (CaseRunner).
//
// Units. CaseSpec keeps the sweep file's user units (kt, ft, lbf, deg, s),
// exactly as they are written to the database's `cases` columns, so that a
// query such as `speed_kt = 5` matches bit-for-bit; the *_si() helpers give
// the SI values the physics needs. CaseOutcome is SI (N, m, s, rad); the
// database writer (sweep/build/writer.hpp) converts it to the schema's lbf, ft,
// kips and deg.
//
// Sign and axis conventions: heading_deg is the wave heading relative to the
// tow's course, 0 = following (trailing) seas, 180 = head seas (thesis and
// schema convention); the swell heading uses the same convention. Dynamic
// tension = total towline tension minus the mean tension (>= -mean: a slack
// line has dynamic tension -mean).
#ifndef TOWDB_SWEEP_CASE_HPP
#define TOWDB_SWEEP_CASE_HPP

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/ship_file.hpp"
#include "model/towline.hpp"

namespace towdb::sweep {

enum class SpectrumKind {
  kPiersonMoskowitz,  // one parameter: wind_kt (fully developed sea)
  kBretschneider,     // two parameters: hs_ft, tp_s (thesis eq. 6.1)
  kJonswap,           // hs_ft, tp_s, gamma (peak enhancement)
};

// "pierson-moskowitz", "bretschneider", "jonswap".
const char* to_string(SpectrumKind kind);
// Inverse of to_string; throws InputError naming `field` for an unknown name.
SpectrumKind spectrum_kind_from_string(const std::string& name, const std::string& field);

// A second, independent wave system (thesis 7.2: swell plus wind sea). Its
// spectrum is Bretschneider with its own heading.
struct SwellSpec {
  double hs_ft = 0.0;        // significant height [ft], > 0
  double tp_s = 0.0;         // peak period [s], > 0
  double heading_deg = 0.0;  // 0 = following, 180 = head, [0, 360]
};

struct SeaSpec {
  SpectrumKind kind = SpectrumKind::kPiersonMoskowitz;
  std::optional<double> wind_kt;  // PM: required; two-parameter seas: optional (mean-tension wind drag)
  std::optional<double> hs_ft;    // two-parameter seas only
  std::optional<double> tp_s;     // two-parameter seas only
  std::optional<double> gamma;    // JONSWAP only
  std::optional<SwellSpec> swell;

  // The schema's `cases.spectrum` text: kind, plus "+swell" when there is one.
  std::string spectrum_text() const;
};

struct CaseSpec {
  std::string tug;                 // canonical vessel name (catalog), role tug
  std::string tow;                 // canonical vessel name (catalog)
  double speed_kt = 0.0;           // tow speed actually simulated [kt], > 0
  double nominal_speed_kt = 0.0;   // the sweep's speed before any reduction (= speed_kt if none) [kt]
  SeaSpec sea;
  double heading_deg = 0.0;        // wave heading [deg], 0 following, 180 head, [0, 360]
  model::LineKind line = model::LineKind::kWire;  // hawser: wire or fiber (chain is not a hawser)
  double length_ft = 0.0;          // hawser length [ft] (the tug's pendant is added), > 0
  double mean_tension_lbf = 0.0;   // mean towline tension [lbf], > 0
  std::string mean_tension_label;  // how it was chosen: "calculated+15%", "given", ...
  // T_calc of EQ-SWEEP-1 at this case's speed, wind and heading [lbf], > 0,
  // when the sweep computed one (a wind sea in a grid); a description of the
  // case (stored for the query's mean-tension axis), not a simulation input.
  std::optional<double> calculated_mean_tension_lbf;
  int days = 0;                    // simulated days used for the statistics, >= 1
  std::int64_t seed = 0;           // random seed, >= 0: the case is bit-reproducible from its inputs and seed
  std::string sweep_label;         // label of the sweep entry that made it
  std::string condition_key;       // set by the expander: identity of the sweep cell (see sweep.hpp EQ-SWEEP-5)

  // Throws InputError naming the field, value and what is allowed.
  void validate() const;

  double speed_m_s() const;
  double heading_rad() const;
  double length_m() const;
  double mean_tension_n() const;
};

// The towline polynomial of thesis eq. 3.4 for one towline at one mean
// tension, with the static catenary it linearises about (SI).
struct TowlineFitOutcome {
  std::string towline_model = "polynomial";  // "polynomial" or "polynomial+spring"
  double span_m = 0.0;
  double sag_m = 0.0;
  double lowest_elevation_m = 0.0;  // of the lowest point; negative below the waterline
  double end_angle_tug_rad = 0.0;  // below horizontal
  double end_angle_tow_rad = 0.0;  // below horizontal
  double static_stiffness_n_per_m = 0.0;
  double breaking_strength_n = 0.0;
  // a_mn of tau = sum a_mn xi^m xi_t^n, order a10, a01, a20, a11, a02, a30,
  // a21, a12, a03; units N s^n / m^(m+n).
  std::array<double, 9> coefficients_si{};
  double fit_rms_n = 0.0;
  double fit_max_error_n = 0.0;
  int fit_samples = 0;
};

// One simulated day (start-up days excluded).
struct DayOutcome {
  double max_dynamic_n = 0.0;  // the day's largest dynamic tension
  double slack_time_s = 0.0;   // time the line was slack
  int snatch_events = 0;       // slack-to-taut transitions
};

// Statistics of the daily maxima (thesis ch. 4), SI.
struct CaseStatistics {
  double gumbel_u_n = 0.0;              // Type I location (method of moments)
  double gumbel_alpha_per_n = 0.0;      // Type I scale parameter alpha [1/N]
  double daily_max_mean_n = 0.0;
  double daily_max_variance_n2 = 0.0;
  double dynamic_999_n = 0.0;           // Type I at F = 0.999 per day
  double dynamic_99_n = 0.0;            // Type I at F = 0.99 per day
  std::optional<double> empirical_999_n;
  std::optional<double> empirical_99_n;
  double ci_level = 0.9;                // confidence level of [ci_low, ci_high]
  double ci_low_n = 0.0;
  double ci_high_n = 0.0;
  std::optional<double> gumbel_ml_u_n;
  std::optional<double> gumbel_ml_alpha_per_n;
  std::optional<double> gev_mu_n;
  std::optional<double> gev_sigma_n;
  std::optional<double> gev_xi;
  std::optional<double> anderson_darling;
  std::optional<double> ppcc;
  double max_daily_max_n = 0.0;
  double breaking_strength_n = 0.0;
  bool above_breaking_strength = false;  // mean + dynamic_999 > breaking strength
  double slack_fraction = 0.0;           // of the simulated time, [0, 1]
  double snatch_events_per_day = 0.0;
};

struct CaseOutcome {
  TowlineFitOutcome fit;
  CaseStatistics statistics;
  std::vector<DayOutcome> days;

  // Throws NumericalError naming the first non-finite or out-of-range value
  // (a runner must never hand the writer a NaN).
  void validate() const;
};

// Computes one case. Must be deterministic (same spec and catalog -> the same
// bits) and thread-safe (called concurrently from worker threads). Failures
// are exceptions (NumericalError, InputError, ...): the builder records the
// message in cases.error_message.
using CaseRunner = std::function<CaseOutcome(const CaseSpec&, const io::ShipCatalog&)>;
// The static catenary's lowest point of a case's towline [m above the still
// waterline, negative below]: what a build fills in for fits stored before
// schema 6 (the runner's fit carries it for new ones).
using LowestPointFn = std::function<double(const CaseSpec&, const io::ShipCatalog&)>;
// The linear dynamic-tension standard deviation [N] of a case's line at each
// of `headings_deg` (the spec's heading replaced; simulation EQ-CASE-3, which
// the build's function evaluates without the wave-induced surge damping): the
// heading profiles a build stores for the query (sweep/build/profiles.hpp).
using HeadingProfileFn =
    std::function<std::vector<double>(const CaseSpec&, const io::ShipCatalog&, const std::vector<double>& headings_deg)>;

// One point of a speed profile (EQ-SWEEP-9): a speed and the mean tension
// that goes with it there.
struct SpeedPoint {
  double speed_kt = 0.0;          // > 0
  double mean_tension_lbf = 0.0;  // > 0
};
// The linear dynamic-tension standard deviation [N] of a case's line at each
// of `points` (the spec's speed and mean tension replaced, every other input
// as in the spec; simulation EQ-CASE-3, which the build's function evaluates
// without the wave-induced surge damping): the speed profiles a build stores
// for the query (sweep/build/speed_profiles.hpp).
using SpeedProfileFn =
    std::function<std::vector<double>(const CaseSpec&, const io::ShipCatalog&, const std::vector<SpeedPoint>& points)>;

// The production runner is registered once by the CLI (the simulation chain);
// `towdb build` refuses to run while none is registered.
void set_default_case_runner(CaseRunner runner);
// The registered runner, or nullptr.
const CaseRunner* default_case_runner();

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_CASE_HPP
