#include "sweep/spec/case.hpp"

#include <cmath>
#include <mutex>
#include <utility>

#include "common/error.hpp"
#include "common/units.hpp"

namespace towdb::sweep {

namespace {

// Accepted ranges of a case's inputs (user units). They bound what the
// physics chain was written for, not what is typical.
constexpr double kMaxSpeed_kt = 30.0;          // faster than any tug can tow
constexpr double kMaxWind_kt = 100.0;          // beyond hurricane force 12
constexpr double kMaxHs_ft = 100.0;            // beyond any recorded Hs
constexpr double kMinTp_s = 1.0;               // shorter waves do not move ships
constexpr double kMaxTp_s = 40.0;              // longer than any ocean swell
constexpr double kMinGamma = 1.0;              // JONSWAP gamma = 1 is Bretschneider
constexpr double kMaxGamma = 10.0;             // far above the North Sea's 3.3
constexpr double kMaxLength_ft = 10000.0;      // longer than any tug's drum
constexpr double kMaxMeanTension_lbf = 2.0e6;  // above any hawser's strength
constexpr int kMaxDays = 1000000;

void check_optional(const std::string& field, const std::optional<double>& value, double lo, double hi) {
  if (value) require_in_range(field, *value, lo, hi);
}

}  // namespace

const char* to_string(SpectrumKind kind) {
  switch (kind) {
    case SpectrumKind::kPiersonMoskowitz: return "pierson-moskowitz";
    case SpectrumKind::kBretschneider: return "bretschneider";
    case SpectrumKind::kJonswap: return "jonswap";
  }
  return "?";
}

SpectrumKind spectrum_kind_from_string(const std::string& name, const std::string& field) {
  for (SpectrumKind k : {SpectrumKind::kPiersonMoskowitz, SpectrumKind::kBretschneider, SpectrumKind::kJonswap}) {
    if (name == to_string(k)) return k;
  }
  throw InputError(field + " = \"" + name + "\": expected \"pierson-moskowitz\", \"bretschneider\" or \"jonswap\"");
}

std::string SeaSpec::spectrum_text() const {
  return std::string(to_string(kind)) + (swell ? "+swell" : "");
}

void CaseSpec::validate() const {
  require_input(!tug.empty(), "CaseSpec.tug", 0.0, "must name a tug");
  require_input(!tow.empty(), "CaseSpec.tow", 0.0, "must name a tow");
  require_in_range("CaseSpec.speed_kt", speed_kt, 1e-3, kMaxSpeed_kt);
  require_in_range("CaseSpec.nominal_speed_kt", nominal_speed_kt, 1e-3, kMaxSpeed_kt);
  require_in_range("CaseSpec.heading_deg", heading_deg, 0.0, 360.0);
  if (calculated_mean_tension_lbf) {
    require_positive("CaseSpec.calculated_mean_tension_lbf", *calculated_mean_tension_lbf);
  }
  require_input(line == model::LineKind::kWire || line == model::LineKind::kFiber, "CaseSpec.line",
                static_cast<double>(static_cast<int>(line)), "must be wire or fiber (a chain is a pendant)");
  require_in_range("CaseSpec.length_ft", length_ft, 1.0, kMaxLength_ft);
  require_in_range("CaseSpec.mean_tension_lbf", mean_tension_lbf, 1.0, kMaxMeanTension_lbf);
  require_input(days >= 1 && days <= kMaxDays, "CaseSpec.days", days, "must be a whole number in [1, 1000000]");
  require_input(seed >= 0, "CaseSpec.seed", static_cast<double>(seed), "must be >= 0");
  check_optional("CaseSpec.sea.wind_kt", sea.wind_kt, 0.0, kMaxWind_kt);
  check_optional("CaseSpec.sea.hs_ft", sea.hs_ft, 1e-3, kMaxHs_ft);
  check_optional("CaseSpec.sea.tp_s", sea.tp_s, kMinTp_s, kMaxTp_s);
  check_optional("CaseSpec.sea.gamma", sea.gamma, kMinGamma, kMaxGamma);
  switch (sea.kind) {
    case SpectrumKind::kPiersonMoskowitz:
      require_input(sea.wind_kt.has_value(), "CaseSpec.sea.wind_kt", 0.0,
                    "is required by a pierson-moskowitz sea");
      require_input(!sea.hs_ft && !sea.tp_s && !sea.gamma, "CaseSpec.sea.hs_ft/tp_s/gamma", 0.0,
                    "must be absent for a pierson-moskowitz sea (the wind sets them)");
      break;
    case SpectrumKind::kBretschneider:
    case SpectrumKind::kJonswap:
      require_input(sea.hs_ft.has_value() && sea.tp_s.has_value(), "CaseSpec.sea.hs_ft/tp_s", 0.0,
                    std::string("are required by a ") + to_string(sea.kind) + " sea");
      require_input(sea.kind == SpectrumKind::kJonswap ? sea.gamma.has_value() : !sea.gamma.has_value(),
                    "CaseSpec.sea.gamma", sea.gamma.value_or(0.0),
                    "is required by a jonswap sea and not allowed otherwise");
      break;
  }
  if (sea.swell) {
    require_in_range("CaseSpec.sea.swell.hs_ft", sea.swell->hs_ft, 1e-3, kMaxHs_ft);
    require_in_range("CaseSpec.sea.swell.tp_s", sea.swell->tp_s, kMinTp_s, kMaxTp_s);
    require_in_range("CaseSpec.sea.swell.heading_deg", sea.swell->heading_deg, 0.0, 360.0);
  }
}

double CaseSpec::speed_m_s() const { return units::kt_to_m_s(speed_kt); }
double CaseSpec::heading_rad() const { return units::deg_to_rad(heading_deg); }
double CaseSpec::length_m() const { return units::ft_to_m(length_ft); }
double CaseSpec::mean_tension_n() const { return units::lbf_to_n(mean_tension_lbf); }

void CaseOutcome::validate() const {
  auto finite = [](const std::string& field, double v) {
    if (!std::isfinite(v)) throw NumericalError("case runner output: " + field + " = " + format_value(v) +
                                                " is not finite");
  };
  auto finite_opt = [&](const std::string& field, const std::optional<double>& v) {
    if (v) finite(field, *v);
  };
  finite("fit.span_m", fit.span_m);
  finite("fit.sag_m", fit.sag_m);
  finite("fit.lowest_elevation_m", fit.lowest_elevation_m);
  finite("fit.end_angle_tug_rad", fit.end_angle_tug_rad);
  finite("fit.end_angle_tow_rad", fit.end_angle_tow_rad);
  finite("fit.static_stiffness_n_per_m", fit.static_stiffness_n_per_m);
  finite("fit.breaking_strength_n", fit.breaking_strength_n);
  for (std::size_t i = 0; i < fit.coefficients_si.size(); ++i) {
    finite("fit.coefficients_si[" + std::to_string(i) + "]", fit.coefficients_si[i]);
  }
  finite("fit.fit_rms_n", fit.fit_rms_n);
  finite("fit.fit_max_error_n", fit.fit_max_error_n);
  if (fit.towline_model != "polynomial" && fit.towline_model != "polynomial+spring") {
    throw NumericalError("case runner output: fit.towline_model = \"" + fit.towline_model +
                         "\": expected \"polynomial\" or \"polynomial+spring\"");
  }
  if (fit.fit_samples < 0) throw NumericalError("case runner output: fit.fit_samples < 0");
  const CaseStatistics& s = statistics;
  finite("statistics.gumbel_u_n", s.gumbel_u_n);
  finite("statistics.gumbel_alpha_per_n", s.gumbel_alpha_per_n);
  finite("statistics.daily_max_mean_n", s.daily_max_mean_n);
  finite("statistics.daily_max_variance_n2", s.daily_max_variance_n2);
  finite("statistics.dynamic_999_n", s.dynamic_999_n);
  finite("statistics.dynamic_99_n", s.dynamic_99_n);
  finite_opt("statistics.empirical_999_n", s.empirical_999_n);
  finite_opt("statistics.empirical_99_n", s.empirical_99_n);
  finite("statistics.ci_level", s.ci_level);
  finite("statistics.ci_low_n", s.ci_low_n);
  finite("statistics.ci_high_n", s.ci_high_n);
  finite_opt("statistics.gumbel_ml_u_n", s.gumbel_ml_u_n);
  finite_opt("statistics.gumbel_ml_alpha_per_n", s.gumbel_ml_alpha_per_n);
  finite_opt("statistics.gev_mu_n", s.gev_mu_n);
  finite_opt("statistics.gev_sigma_n", s.gev_sigma_n);
  finite_opt("statistics.gev_xi", s.gev_xi);
  finite_opt("statistics.anderson_darling", s.anderson_darling);
  finite_opt("statistics.ppcc", s.ppcc);
  finite("statistics.max_daily_max_n", s.max_daily_max_n);
  finite("statistics.breaking_strength_n", s.breaking_strength_n);
  finite("statistics.slack_fraction", s.slack_fraction);
  finite("statistics.snatch_events_per_day", s.snatch_events_per_day);
  if (!(s.ci_level > 0.0 && s.ci_level < 1.0)) {
    throw NumericalError("case runner output: statistics.ci_level = " + format_value(s.ci_level) +
                         ": must be in (0, 1)");
  }
  if (!(s.slack_fraction >= 0.0 && s.slack_fraction <= 1.0)) {
    throw NumericalError("case runner output: statistics.slack_fraction = " + format_value(s.slack_fraction) +
                         ": must be in [0, 1]");
  }
  for (std::size_t d = 0; d < days.size(); ++d) {
    finite("days[" + std::to_string(d) + "].max_dynamic_n", days[d].max_dynamic_n);
    finite("days[" + std::to_string(d) + "].slack_time_s", days[d].slack_time_s);
    if (days[d].snatch_events < 0) {
      throw NumericalError("case runner output: days[" + std::to_string(d) + "].snatch_events < 0");
    }
  }
}

namespace {
std::mutex g_runner_mutex;
CaseRunner g_runner;  // guarded by g_runner_mutex for registration; read after.
}  // namespace

void set_default_case_runner(CaseRunner runner) {
  std::lock_guard<std::mutex> lock(g_runner_mutex);
  g_runner = std::move(runner);
}

const CaseRunner* default_case_runner() {
  std::lock_guard<std::mutex> lock(g_runner_mutex);
  return g_runner ? &g_runner : nullptr;
}

}  // namespace towdb::sweep
