#include "sweep/build/simulation_runner.hpp"

#include <cmath>
#include <optional>

#include "common/error.hpp"
#include "common/units.hpp"
#include "seakeeping/seakeeping.hpp"

namespace towdb::sweep {

namespace {

std::optional<double> finite_or_none(double x) {
  return std::isfinite(x) ? std::optional<double>(x) : std::nullopt;
}

double required(const std::optional<double>& x, const char* field) {
  if (!x) throw InputError(std::string("sea: ") + field + " is required for this spectrum");
  return *x;
}

}  // namespace

sea::SeaState sea_state(const SeaSpec& s, double heading_deg) {
  using units::ft_to_m;
  sea::Spectrum wind_sea = sea::Spectrum::pierson_moskowitz(1.0);
  switch (s.kind) {
    case SpectrumKind::kPiersonMoskowitz:
      wind_sea = sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(required(s.wind_kt, "wind_kt")));
      break;
    case SpectrumKind::kBretschneider:
      wind_sea = sea::Spectrum::bretschneider_peak_period(ft_to_m(required(s.hs_ft, "hs_ft")), required(s.tp_s, "tp_s"));
      break;
    case SpectrumKind::kJonswap:
      wind_sea = sea::Spectrum::jonswap(ft_to_m(required(s.hs_ft, "hs_ft")), required(s.tp_s, "tp_s"),
                                        required(s.gamma, "gamma"));
      break;
  }
  const double mu = units::deg_to_rad(heading_deg);
  if (s.swell) {
    const sea::Spectrum swell = sea::Spectrum::bretschneider_peak_period(ft_to_m(s.swell->hs_ft), s.swell->tp_s);
    return sea::wind_sea_and_swell(wind_sea, mu, swell, units::deg_to_rad(s.swell->heading_deg));
  }
  return sea::single_system(wind_sea, mu);
}

namespace {

// The simulation's inputs of a sweep case (the catalog outlives them).
simulation::CaseInputs case_inputs(const CaseSpec& spec, const io::ShipCatalog& catalog) {
  const model::Vessel& tug = catalog.vessel(spec.tug).vessel;
  const model::Vessel& tow = catalog.vessel(spec.tow).vessel;
  simulation::CaseInputs in;
  in.tug = &tug;
  in.tow = &tow;
  in.towline = catalog.towline(tug, spec.line, spec.length_m());
  in.speed_m_s = spec.speed_m_s();
  in.sea = sea_state(spec.sea, spec.heading_deg);
  in.mean_tension_n = spec.mean_tension_n();
  in.days = spec.days;
  in.seed = static_cast<std::uint64_t>(spec.seed);
  return in;
}

}  // namespace

simulation::CaseOptions profile_options(simulation::CaseOptions options) {
  options.wave_surge_damping = false;
  return options;
}

HeadingProfileFn linear_heading_profile(simulation::CaseOptions options) {
  options = profile_options(options);
  options.validate();
  return [options](const CaseSpec& spec, const io::ShipCatalog& catalog, const std::vector<double>& headings_deg) {
    return simulation::linear_tension_sigma_by_heading_n(case_inputs(spec, catalog), options, headings_deg);
  };
}

SpeedProfileFn linear_speed_profile(simulation::CaseOptions options) {
  options = profile_options(options);
  options.validate();
  return [options](const CaseSpec& spec, const io::ShipCatalog& catalog, const std::vector<SpeedPoint>& points) {
    std::vector<double> sigma;
    sigma.reserve(points.size());
    CaseSpec at = spec;
    for (const SpeedPoint& p : points) {
      at.speed_kt = p.speed_kt;
      at.mean_tension_lbf = p.mean_tension_lbf;
      sigma.push_back(std::sqrt(simulation::linear_tension_variance_n2(case_inputs(at, catalog), options)));
    }
    return sigma;
  };
}

CaseRunner simulation_case_runner(simulation::CaseOptions options) {
  options.validate();
  return [options](const CaseSpec& spec, const io::ShipCatalog& catalog) {
    const simulation::CaseResult r = simulation::run_case(case_inputs(spec, catalog), options);

    CaseOutcome out;
    TowlineFitOutcome& f = out.fit;
    f.towline_model = options.above_breaking == towline::AboveBreakingModel::kStraightSpring ? "polynomial+spring"
                                                                                             : "polynomial";
    f.span_m = r.towline.span_m;
    f.sag_m = r.towline.sag_m;
    f.lowest_elevation_m = r.towline.lowest_elevation_m;
    f.end_angle_tug_rad = r.towline.tug_angle_rad;
    f.end_angle_tow_rad = r.towline.tow_angle_rad;
    f.static_stiffness_n_per_m = r.towline.static_stiffness_n_m;
    f.breaking_strength_n = r.towline.breaking_strength_n;
    f.coefficients_si = r.towline.coefficients.a;
    f.fit_rms_n = r.towline.fit_rms_error_n;
    f.fit_max_error_n = r.towline.fit_max_error_n;
    f.fit_samples = r.towline.samples_used;

    const simulation::CaseStatistics& s = r.statistics;
    CaseStatistics& t = out.statistics;
    t.gumbel_u_n = s.gumbel_u_n;
    t.gumbel_alpha_per_n = s.gumbel_alpha_per_n;
    t.daily_max_mean_n = s.daily_max_mean_n;
    t.daily_max_variance_n2 = s.daily_max_variance_n2;
    t.dynamic_999_n = s.dynamic_999_n;
    t.dynamic_99_n = s.dynamic_99_n;
    t.empirical_999_n = finite_or_none(s.empirical_999_n);
    t.empirical_99_n = finite_or_none(s.empirical_99_n);
    t.ci_level = s.ci_level;
    t.ci_low_n = s.ci_low_n;
    t.ci_high_n = s.ci_high_n;
    t.gumbel_ml_u_n = finite_or_none(s.gumbel_ml_u_n);
    t.gumbel_ml_alpha_per_n = finite_or_none(s.gumbel_ml_alpha_per_n);
    t.gev_mu_n = finite_or_none(s.gev_mu_n);
    t.gev_sigma_n = finite_or_none(s.gev_sigma_n);
    t.gev_xi = finite_or_none(s.gev_xi);
    t.anderson_darling = finite_or_none(s.anderson_darling);
    t.ppcc = finite_or_none(s.ppcc);
    t.max_daily_max_n = s.max_daily_max_n;
    t.breaking_strength_n = r.towline.breaking_strength_n;
    t.above_breaking_strength = r.above_breaking_strength;
    t.slack_fraction = r.slack_fraction;
    t.snatch_events_per_day = r.snatch_events_per_day;
    out.days.reserve(r.days.size());
    for (const auto& d : r.days) out.days.push_back({d.max_dynamic_tension_n, d.slack_time_s, d.snatch_events});
    return out;
  };
}

LowestPointFn static_lowest_elevation(simulation::CaseOptions options) {
  options.validate();
  return [options](const CaseSpec& spec, const io::ShipCatalog& catalog) {
    const model::Vessel& tug = catalog.vessel(spec.tug).vessel;
    const model::Vessel& tow = catalog.vessel(spec.tow).vessel;
    const towline::Catenary cat =
        towline::Catenary::solve(catalog.towline(tug, spec.line, spec.length_m()),
                                 towline::TowPoints{tug.tow_point.z_m, tow.tow_point.z_m}, spec.mean_tension_n(),
                                 options.towline.catenary);
    return cat.lowest_elevation_m();
  };
}

SeaResistanceFn strip_theory_sea_resistance(simulation::CaseOptions options) {
  options.validate();
  const std::vector<double> grid = simulation::response_grid(options);
  return [options, grid](const model::Vessel& tow, double speed_kt, const SeaSpec& spec, double heading_deg) {
    const sea::SeaState state = sea_state(spec, heading_deg);
    double total = 0.0;
    for (const auto& system : state.systems) {
      const auto responses =
          simulation::cached_responses(tow, units::kt_to_m_s(speed_kt), system.heading_rad, grid, options.response);
      total += seakeeping::mean_added_resistance_n(*responses,
                                                   [&system](double w) { return system.spectrum.density_m2_s(w); });
    }
    return total;
  };
}

}  // namespace towdb::sweep
