// towdb simulate: one towing case through the whole chain (towline fit,
// seakeeping, 12-DOF coupling, long random-sea simulation, statistics).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"
#include "common/units.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "simulation/case_runner.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;

struct SimulateArgs {
  std::string tug, tow, line = "wire";
  double speed_kt = 0.0, heading_deg = 0.0, length_ft = 0.0, mean_tension_lbf = 0.0;
  double wind_kt = 0.0, hs_ft = 0.0, tp_s = 0.0, gamma = 3.3;
  std::string spectrum;  // "" = PM by wind, else bretschneider | jonswap
  double swell_hs_ft = 0.0, swell_tp_s = 0.0, swell_heading_deg = 0.0;
  bool gamma_given = false, swell_heading_given = false;  // flags whose default is a valid value
  int days = 500;
  std::uint64_t seed = 1;
  int threads = 0;
  bool json = false;
  std::string plot;
  std::string above_breaking = "polynomial";
  std::string tow_propeller = "removed";
};

// The sea of the flags; a flag the chosen sea would ignore is an error.
sea::SeaState sea_state(const SimulateArgs& a) {
  const double mu = units::deg_to_rad(a.heading_deg);
  sea::Spectrum wind_sea = sea::Spectrum::pierson_moskowitz(1.0);
  const bool two_parameter = a.hs_ft > 0.0 || a.tp_s > 0.0;  // 0 = not given (their ranges exclude 0)
  if (two_parameter && a.wind_kt > 0.0) {
    throw InputError("--wind-kt " + format_value(a.wind_kt) +
                     " with --hs-ft/--tp-s: give one sea, a wind speed (Pierson-Moskowitz) or Hs and Tp");
  }
  if (!two_parameter && !a.spectrum.empty()) {
    throw InputError("--spectrum " + a.spectrum +
                     ": needs --hs-ft and --tp-s (with --wind-kt the sea is Pierson-Moskowitz)");
  }
  if (a.gamma_given && a.spectrum != "jonswap" && !(a.swell_hs_ft > 0.0)) {
    throw InputError("--gamma " + format_value(a.gamma) +
                     ": only a JONSWAP sea (--spectrum jonswap) or a swell uses it");
  }
  if (!(a.swell_hs_ft > 0.0) && (a.swell_tp_s > 0.0 || a.swell_heading_given)) {
    throw InputError("--swell-tp-s / --swell-heading-deg: need --swell-hs-ft (the swell's height)");
  }
  if (two_parameter) {
    if (!(a.hs_ft > 0.0 && a.tp_s > 0.0)) {
      throw InputError(std::string(a.hs_ft > 0.0 ? "--tp-s is missing" : "--hs-ft is missing") +
                       ": --hs-ft and --tp-s must be given together (a two-parameter sea)");
    }
    if (a.spectrum == "jonswap") {
      wind_sea = sea::Spectrum::jonswap(units::ft_to_m(a.hs_ft), a.tp_s, a.gamma);
    } else {
      wind_sea = sea::Spectrum::bretschneider_peak_period(units::ft_to_m(a.hs_ft), a.tp_s);
    }
  } else {
    if (!(a.wind_kt > 0.0)) throw InputError("give --wind-kt (Pierson-Moskowitz sea) or --hs-ft with --tp-s");
    wind_sea = sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(a.wind_kt));
  }
  if (a.swell_hs_ft > 0.0) {
    if (!(a.swell_tp_s > 0.0)) throw InputError("--swell-hs-ft needs --swell-tp-s");
    const sea::Spectrum swell = sea::Spectrum::jonswap(units::ft_to_m(a.swell_hs_ft), a.swell_tp_s, a.gamma);
    return sea::wind_sea_and_swell(wind_sea, mu, swell, units::deg_to_rad(a.swell_heading_deg));
  }
  return sea::single_system(wind_sea, mu);
}

// The days' progress line: "  [###...] d/D days  E s elapsed  ETA R s ".
class DaysProgress {
 public:
  explicit DaysProgress(bool enabled) : line_(enabled) {}
  void update(int done, int total) {
    if (!line_.enabled()) return;
    const double elapsed = line_.elapsed_s();
    const double eta = done > 0 ? elapsed * (total - done) / done : 0.0;
    const int width = 30;
    const int filled = total > 0 ? width * done / total : width;
    char text[256];
    std::snprintf(text, sizeof text, "  [%s] %d/%d days  %.1f s elapsed  ETA %.1f s ",
                  ProgressLine::bar(filled, width, '.').c_str(), done, total, elapsed, eta);
    line_.draw(text, done == total, /*clear_rest=*/false);
  }

 private:
  ProgressLine line_;
};

double kips(double n) { return units::n_to_kips(n); }

// --plot: the daily maxima with the Type I fit, and the worst day's tension.
void write_plot(const SimulateArgs& a, const simulation::CaseInputs& in, const simulation::CaseOptions& o,
                const simulation::CaseResult& r) {
  const auto& st = r.statistics;
  const auto model = simulation::prepare_case(in, o);
  // The day with the largest maximum, for the time-series slice.
  std::size_t worst = 0;
  for (std::size_t i = 1; i < r.days.size(); ++i) {
    if (r.days[i].max_dynamic_tension_n > r.days[worst].max_dynamic_tension_n) worst = i;
  }
  const simulation::DayForcing f = simulation::day_forcing(*model, a.seed, worst);
  std::vector<double> trace;
  simulation::simulate_day(*model, f, o.integrator, &trace);
  std::vector<double> maxima_kips;
  for (const auto& d : r.days) maxima_kips.push_back(kips(d.max_dynamic_tension_n));
  for (double& t : trace) t = kips(t);
  write_simulation_plot(a.plot, maxima_kips, kips(st.gumbel_u_n), st.gumbel_alpha_per_n * units::kips_to_n(1.0),
                        trace, f.dt_s, static_cast<int>(worst));
}

// --json: every input, statistic and diagnostic, units in the keys.
void print_json(const SimulateArgs& a, const simulation::CaseInputs& in, const simulation::CaseResult& r) {
  const auto& st = r.statistics;
  const double extreme_lbf = a.mean_tension_lbf + units::n_to_lbf(st.dynamic_999_n);
  ordered_json j;
  j["tug"] = in.tug->name;
  j["tow"] = in.tow->name;
  j["speed_kt"] = a.speed_kt;
  j["heading_deg"] = a.heading_deg;
  j["line"] = a.line;
  j["length_ft"] = a.length_ft;
  j["mean_tension_lbf"] = a.mean_tension_lbf;
  j["significant_wave_height_ft"] = units::m_to_ft(in.sea.significant_height_m());
  j["dynamic_tension_kips"] = kips(st.dynamic_999_n);
  j["extreme_tension_lbf"] = extreme_lbf;
  j["dynamic_tension_99_kips"] = kips(st.dynamic_99_n);
  j["gumbel_u_kips"] = kips(st.gumbel_u_n);
  j["gumbel_alpha_per_kip"] = st.gumbel_alpha_per_n * units::kips_to_n(1.0);
  j["daily_max_mean_kips"] = kips(st.daily_max_mean_n);
  j["daily_max_variance_kips2"] = kips(kips(st.daily_max_variance_n2));
  j["ci_level"] = st.ci_level;
  j["ci_low_kips"] = kips(st.ci_low_n);
  j["ci_high_kips"] = kips(st.ci_high_n);
  j["gumbel_ml_u_kips"] = kips(st.gumbel_ml_u_n);
  j["gumbel_ml_alpha_per_kip"] = st.gumbel_ml_alpha_per_n * units::kips_to_n(1.0);
  j["gev_mu_kips"] = kips(st.gev_mu_n);
  j["gev_sigma_kips"] = kips(st.gev_sigma_n);
  j["gev_xi"] = st.gev_xi;
  j["anderson_darling"] = st.anderson_darling;
  j["ppcc"] = st.ppcc;
  if (std::isfinite(st.empirical_999_n)) j["empirical_999_kips"] = kips(st.empirical_999_n);
  if (std::isfinite(st.empirical_99_n)) j["empirical_99_kips"] = kips(st.empirical_99_n);
  j["max_daily_max_kips"] = kips(st.max_daily_max_n);
  j["breaking_strength_lbf"] = units::n_to_lbf(r.towline.breaking_strength_n);
  j["above_breaking_strength"] = r.above_breaking_strength;
  j["days"] = a.days;
  j["seed"] = a.seed;
  j["slack_fraction"] = r.slack_fraction;
  j["snatch_events_per_day"] = r.snatch_events_per_day;
  j["towline"] = {{"span_ft", units::m_to_ft(r.towline.span_m)},
                  {"sag_ft", units::m_to_ft(r.towline.sag_m)},
                  {"end_angle_tug_deg", units::rad_to_deg(r.towline.tug_angle_rad)},
                  {"end_angle_tow_deg", units::rad_to_deg(r.towline.tow_angle_rad)},
                  {"static_stiffness_lbf_per_ft", units::n_per_m_to_lbf_per_ft(r.towline.static_stiffness_n_m)},
                  {"a10_lbf_per_ft", units::n_per_m_to_lbf_per_ft(r.towline.coefficients.a10())},
                  {"a01_lbf_s_per_ft", units::n_s_per_m_to_lbf_s_per_ft(r.towline.coefficients.a01())},
                  {"fit_rms_lbf", units::n_to_lbf(r.towline.fit_rms_error_n)}};
  // Where the days took the line, against the polynomial's fitted range
  // (outside it the tension is a linear continuation: case_runner.hpp).
  j["extension_ft"] = {{"mean", units::m_to_ft(r.extension.mean_m)},
                       {"sd", units::m_to_ft(r.extension.sd_m)},
                       {"min", units::m_to_ft(r.extension.min_m)},
                       {"max", units::m_to_ft(r.extension.max_m)},
                       {"fit_min", units::m_to_ft(r.towline.fit_xi_min_m)},
                       {"fit_max", units::m_to_ft(r.towline.fit_xi_max_m)},
                       {"days_outside_fit", r.extension.days_outside_fit}};
  j["surge_damping_lbf_s_per_ft"] = {
      {"tug_hull", units::n_s_per_m_to_lbf_s_per_ft(r.tug_hull_damping_n_s_m)},
      {"tug_propeller", units::n_s_per_m_to_lbf_s_per_ft(r.tug_propeller_damping_n_s_m)},
      {"tug_wave", units::n_s_per_m_to_lbf_s_per_ft(r.tug_wave_damping_n_s_m)},
      {"tow_hull", units::n_s_per_m_to_lbf_s_per_ft(r.tow_hull_damping_n_s_m)},
      {"tow_propeller", units::n_s_per_m_to_lbf_s_per_ft(r.tow_propeller_damping_n_s_m)},
      {"tow_wave", units::n_s_per_m_to_lbf_s_per_ft(r.tow_wave_damping_n_s_m)}};
  j["added_resistance_lbf"] = {{"tug", units::n_to_lbf(r.tug_added_resistance_n)},
                               {"tow", units::n_to_lbf(r.tow_added_resistance_n)}};
  j["record"] = {{"time_step_s", r.record_time_step_s},
                 {"samples", r.record_samples},
                 {"wave_components", r.wave_components},
                 {"retained_variance_fraction", r.retained_variance_fraction},
                 {"fft_plan", r.fft_plan_from_stored_wisdom ? "stored wisdom" : "estimate"}};
  j["integrator_vectors"] = simulation::lane_isa_name(r.lane_isa);  // no effect on any number
  j["runtime_s"] = r.timings.total_s;
  j["timings_s"] = {{"towline", r.timings.towline_s},
                    {"hydrodynamics", r.timings.hydrodynamics_s},
                    {"synthesis_cpu", r.timings.synthesis_s},
                    {"integration_cpu", r.timings.integration_s},
                    {"statistics", r.timings.statistics_s}};
  std::cout << j.dump(2) << "\n";
}

// The planner's table, with warnings for a broken line or a left fit range.
void print_table(const SimulateArgs& a, const simulation::CaseInputs& in, const simulation::CaseResult& r) {
  const auto& st = r.statistics;
  const double extreme_lbf = a.mean_tension_lbf + units::n_to_lbf(st.dynamic_999_n);
  std::cout << in.tug->name << " towing " << in.tow->name << " at " << fmt(a.speed_kt, 1) << " kt, "
            << "Hs " << fmt(units::m_to_ft(in.sea.significant_height_m()), 1) << " ft, heading "
            << fmt(a.heading_deg, 0) << " deg, " << fmt(a.length_ft, 0) << " ft of " << a.line << " + pendant, mean "
            << fmt_grouped(a.mean_tension_lbf) << " lbf\n\n";
  TextTable t({"quantity", "value"});
  t.add_row({"dynamic tension, 0.001 per day (Type I)", fmt(kips(st.dynamic_999_n), 1) + " kips"});
  t.add_row({"  " + fmt(100 * st.ci_level, 0) + " % confidence interval",
             fmt(kips(st.ci_low_n), 1) + " - " + fmt(kips(st.ci_high_n), 1) + " kips"});
  t.add_row({"extreme tension (mean + dynamic)", fmt_grouped(extreme_lbf) + " lbf"});
  t.add_row({"towline breaking strength", fmt_grouped(units::n_to_lbf(r.towline.breaking_strength_n)) + " lbf"});
  t.add_row({"dynamic tension, 0.01 per day", fmt(kips(st.dynamic_99_n), 1) + " kips"});
  t.add_row({"daily maxima: mean, variance",
             fmt(kips(st.daily_max_mean_n), 2) + " kips, " + fmt(kips(kips(st.daily_max_variance_n2)), 2) + " kips^2"});
  t.add_row({"Gumbel u, alpha", fmt(kips(st.gumbel_u_n), 2) + " kips, " +
                                    fmt(st.gumbel_alpha_per_n * units::kips_to_n(1.0), 4) + " 1/kip"});
  t.add_row({"fit: Anderson-Darling A^2, PPCC", fmt(st.anderson_darling, 3) + ", " + fmt(st.ppcc, 4)});
  t.add_row({"slack time, snatch events per day",
             fmt(100 * r.slack_fraction, 3) + " %, " + fmt(r.snatch_events_per_day, 2)});
  t.add_row({"line extension: sd, range",
             fmt(units::m_to_ft(r.extension.sd_m), 2) + " ft, " + fmt(units::m_to_ft(r.extension.min_m), 1) + " to " +
                 fmt(units::m_to_ft(r.extension.max_m), 1) + " ft (fitted " +
                 fmt(units::m_to_ft(r.towline.fit_xi_min_m), 1) + " to " +
                 fmt(units::m_to_ft(r.towline.fit_xi_max_m), 1) + " ft)"});
  t.add_row({"days, seed", std::to_string(a.days) + ", " + std::to_string(a.seed)});
  t.add_row({"run time", fmt(r.timings.total_s, 2) + " s"});
  t.print(std::cout);
  if (r.above_breaking_strength) {
    std::cout << "\nwarning: mean + dynamic tension exceeds the towline's breaking strength; the towline model is "
                 "not valid there (thesis 6.1)\n";
  }
  if (r.extension.days_outside_fit > 0) {
    std::cout << "\nnote: on " << r.extension.days_outside_fit << " of " << a.days
              << " days the line's extension left the range the towline polynomial was fitted over; the tension "
                 "there is a linear continuation of the fit, not cable dynamics\n";
  }
}

int run_simulate(const Context& ctx, const SimulateArgs& a) {
  if (!a.plot.empty()) check_output_file("--plot", a.plot);
  const io::ShipCatalog cat = load_catalog(ctx);
  const model::Vessel& tug = cat.vessel(a.tug).vessel;
  const model::Vessel& tow = cat.vessel(a.tow).vessel;
  if (tug.role != model::VesselRole::kTug) throw InputError("--tug " + a.tug + ": '" + tug.name + "' is not a tug");
  if (tow.role != model::VesselRole::kTow) throw InputError("--tow " + a.tow + ": '" + tow.name + "' is not a tow");
  simulation::CaseInputs in;
  in.tug = &tug;
  in.tow = &tow;
  const model::LineKind kind = a.line == "wire" ? model::LineKind::kWire : model::LineKind::kFiber;
  in.towline = cat.towline(tug, kind, units::ft_to_m(a.length_ft));
  in.speed_m_s = units::kt_to_m_s(a.speed_kt);
  in.sea = sea_state(a);
  in.mean_tension_n = units::lbf_to_n(a.mean_tension_lbf);
  in.days = a.days;
  in.seed = a.seed;
  simulation::CaseOptions o;
  o.num_threads = a.threads;
  o.above_breaking = a.above_breaking == "spring" ? towline::AboveBreakingModel::kStraightSpring
                                                  : towline::AboveBreakingModel::kPolynomial;
  o.tow_propeller.state = a.tow_propeller == "locked" ? propulsion::TowPropellerState::kLocked
                          : a.tow_propeller == "free" ? propulsion::TowPropellerState::kFreeSpinning
                                                      : propulsion::TowPropellerState::kRemoved;
  DaysProgress bar(true);
  o.progress = [&bar](int done, int total) { bar.update(done, total); };
  const simulation::CaseResult r = simulation::run_case(in, o);
  if (!a.plot.empty()) write_plot(a, in, o, r);
  if (a.json) {
    print_json(a, in, r);
  } else {
    print_table(a, in, r);
  }
  return 0;
}

}  // namespace

void add_simulate_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<SimulateArgs>();
  CLI::App* c = app.add_subcommand("simulate", "Simulate one towing case and fit the daily maxima");
  c->add_option("--tug", a->tug, "Tug name (T-ATF, ARS50)")->required();
  c->add_option("--tow", a->tow, "Tow name (LHA1, AE26, CG47, FFG7, YRBM)")->required();
  c->add_option("--speed-kt", a->speed_kt, "Tow speed [kt]")->required()->check(number_in(0.5, 20.0));
  c->add_option("--heading-deg", a->heading_deg, "Wave heading [deg], 0 = following seas, 180 = head seas")
      ->required()->check(number_in(0.0, 360.0));
  c->add_option("--line", a->line, "Hawser: wire or fiber")->required()->check(CLI::IsMember({"wire", "fiber"}));
  c->add_option("--length-ft", a->length_ft, "Hawser length [ft] (the pendant is added)")
      ->required()->check(number_in(100.0, 10000.0));
  c->add_option("--mean-tension-lbf", a->mean_tension_lbf, "Mean (horizontal) towline tension [lbf]")
      ->required()->check(number_in(100.0, 2.0e6));
  c->add_option("--wind-kt", a->wind_kt, "Wind speed [kt]: fully developed Pierson-Moskowitz sea")
      ->check(number_in(1.0, 80.0));
  c->add_option("--hs-ft", a->hs_ft, "Significant wave height [ft] (two-parameter sea, with --tp-s)")
      ->check(number_in(0.1, 80.0));
  c->add_option("--tp-s", a->tp_s, "Peak period [s]")->check(number_in(2.0, 30.0));
  c->add_option("--spectrum", a->spectrum, "With --hs-ft: bretschneider (default) or jonswap")
      ->check(CLI::IsMember({"bretschneider", "jonswap"}));
  c->add_option("--gamma", a->gamma, "JONSWAP peak enhancement (default 3.3)")->check(number_in(1.0, 10.0));
  c->add_option("--swell-hs-ft", a->swell_hs_ft, "Swell significant height [ft]")->check(number_in(0.1, 60.0));
  c->add_option("--swell-tp-s", a->swell_tp_s, "Swell peak period [s]")->check(number_in(4.0, 30.0));
  c->add_option("--swell-heading-deg", a->swell_heading_deg, "Swell heading [deg]")->check(number_in(0.0, 360.0));
  c->add_option("--days", a->days, "Simulated days (default 500)")->check(CLI::Range(3, 1000000));
  c->add_option("--seed", a->seed, "Random seed (default 1)")->check(unsigned_integer());
  c->add_option("--threads", a->threads, "Threads (default: all cores)")->check(CLI::Range(0, 1024));
  c->add_option("--above-breaking", a->above_breaking,
                "Towline above breaking strength: polynomial (thesis) or spring (EA/L)")
      ->check(CLI::IsMember({"polynomial", "spring"}));
  c->add_option("--tow-propeller", a->tow_propeller, "Tow propeller: removed (thesis), locked or free")
      ->check(CLI::IsMember({"removed", "locked", "free"}));
  c->add_flag("--json", a->json, "JSON output");
  c->add_option("--plot", a->plot, "Write a PNG: daily maxima vs the fitted Type I, and the worst day's tension");
  c->callback([&ctx, a, c] {
    a->gamma_given = c->count("--gamma") > 0;
    a->swell_heading_given = c->count("--swell-heading-deg") > 0;
    ctx.action = [&ctx, a] { return run_simulate(ctx, *a); };
  });
}

}  // namespace towdb::cli
