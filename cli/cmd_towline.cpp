// towdb towline: the towline model of one towing configuration -- static
// elastic catenary, resolution chosen by convergence, the 9-coefficient
// polynomial tau(xi, xi_dot) and its fit errors (generator/towline,
// EQ-TOWLINE-1..14; thesis section 3.2 and Appendix A, programs cabnexp and
// t3fer97).
//
// Units at the edge: lengths ft, forces lbf, angles deg, speeds ft/s. The
// polynomial's coefficients are converted one by one: tau [lbf] =
// sum a_mn xi[ft]^m xi_dot[ft/s]^n, so a_mn [lbf/(ft^m (ft/s)^n)] =
// a_mn,SI [N/(m^m (m/s)^n)] * (m per ft)^(m+n) / (N per lbf).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "output.hpp"
#include "towline/towline.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;

struct TowlineArgs {
  std::string tug, tow, line = "wire";
  double length_ft = 0.0;
  double mean_tension_lbf = 0.0;
  int threads = 0;
  bool json = false;
};

constexpr const char* kCoefficientNames[towline::PolynomialCoefficients::kCount] = {
    "a10", "a01", "a20", "a11", "a02", "a30", "a21", "a12", "a03"};

// Unit text of a_mn for tau in `force`, xi in `length`, xi_dot in `length`/s.
std::string coefficient_unit(int m, int n, const std::string& force, const std::string& length) {
  std::string u = force;
  if (n > 0) u += n == 1 ? " s" : " s^" + std::to_string(n);
  const int p = m + n;
  u += "/" + length;
  if (p > 1) u += "^" + std::to_string(p);
  return u;
}

// a_mn from N/(m^m (m/s)^n) to lbf/(ft^m (ft/s)^n): both xi and xi_dot carry
// one length each, so the factor is (m per ft)^(m+n) / (N per lbf).
double coefficient_to_lbf_ft(double a_si, int m, int n) {
  return units::n_to_lbf(a_si) * std::pow(units::ft_to_m(1.0), m + n);
}

// What the towline command reports: the configuration and its fit.
struct TowlineReport {
  const model::Vessel& tug;
  const model::Vessel& tow;
  const model::Towline& line;
  towline::TowPoints points;
  const towline::FitSummary& s;
  double resolution_tolerance;  // TowlineFitOptions::resolution_tolerance
  double runtime_s;
  std::vector<towline::RunDamping> damping;  // EQ-TOWLINE-19, per run
};

// The tug and tow (checked for their roles) and the towline, whose breaking
// strength the mean tension must stay below.
model::Towline checked_towline(const io::ShipCatalog& cat, const model::Vessel& tug, const model::Vessel& tow,
                               const TowlineArgs& a) {
  if (tug.role != model::VesselRole::kTug) {
    throw InputError("--tug " + a.tug + ": '" + tug.name + "' is not a tug (the towline is the tug's hawser)");
  }
  if (tow.role != model::VesselRole::kTow) {
    throw InputError("--tow " + a.tow + ": '" + tow.name + "' is not a tow (its bow fitting is the far end)");
  }
  const model::LineKind kind = a.line == "wire" ? model::LineKind::kWire : model::LineKind::kFiber;
  model::Towline line = cat.towline(tug, kind, units::ft_to_m(a.length_ft));
  if (!(units::lbf_to_n(a.mean_tension_lbf) < line.breaking_strength_n())) {
    throw InputError("--mean-tension-lbf: value = " + fmt(a.mean_tension_lbf) +
                     ": must be below the towline's breaking strength " +
                     fmt_grouped(units::n_to_lbf(line.breaking_strength_n())) + " lbf");
  }
  return line;
}

void print_towline_json(const TowlineArgs& a, const TowlineReport& r) {
  const towline::FitSummary& s = r.s;
  const auto& powers = towline::PolynomialCoefficients::kPowers;
  ordered_json j;
  j["tug"] = r.tug.name;
  j["tow"] = r.tow.name;
  j["line"] = a.line;
  j["length_ft"] = a.length_ft;
  j["mean_tension_lbf"] = a.mean_tension_lbf;
  j["tug_tow_point_height_ft"] = units::m_to_ft(r.points.tug_height_m);
  j["tow_tow_point_height_ft"] = units::m_to_ft(r.points.tow_height_m);
  ordered_json segs = ordered_json::array();
  for (const auto& seg : r.line.segments) {
    const auto& c = seg.component;
    segs.push_back({{"component", c.name},
                    {"kind", model::to_string(c.kind)},
                    {"length_ft", units::m_to_ft(seg.length_m)},
                    {"ea_lbf", units::n_to_lbf(c.ea_n)},
                    {"weight_in_water_lb_per_ft", units::n_per_m_to_lbf_per_ft(c.weight_in_water_n_m)},
                    {"breaking_strength_lbf", units::n_to_lbf(c.breaking_strength_n)}});
  }
  j["segments"] = segs;
  j["unstretched_length_ft"] = units::m_to_ft(s.unstretched_length_m);
  j["span_ft"] = units::m_to_ft(s.span_m);
  j["chord_ft"] = units::m_to_ft(s.chord_m);
  j["sag_ft"] = units::m_to_ft(s.sag_m);
  j["lowest_elevation_ft"] = units::m_to_ft(s.lowest_elevation_m);
  j["end_angle_tug_deg"] = units::rad_to_deg(s.tug_angle_rad);
  j["end_angle_tow_deg"] = units::rad_to_deg(s.tow_angle_rad);
  j["end_tension_tug_lbf"] = units::n_to_lbf(s.tug_tension_n);
  j["end_tension_tow_lbf"] = units::n_to_lbf(s.tow_tension_n);
  j["static_stiffness_lbf_per_ft"] = units::n_per_m_to_lbf_per_ft(s.static_stiffness_n_m);
  j["shallow_sag_static_stiffness_lbf_per_ft"] = units::n_per_m_to_lbf_per_ft(s.dynamic_static_stiffness_n_m);
  j["straight_spring_lbf_per_ft"] = units::n_per_m_to_lbf_per_ft(s.straight_spring_n_m);
  j["breaking_strength_lbf"] = units::n_to_lbf(s.breaking_strength_n);
  j["spring_onset_extension_ft"] = units::m_to_ft(s.spring_onset_extension_m);
  j["slack_limit_lbf"] = units::n_to_lbf(s.slack_limit_n);
  ordered_json coef, coef_units, coef_si, coef_si_units;
  for (int i = 0; i < towline::PolynomialCoefficients::kCount; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const int m = powers[k][0], n = powers[k][1];
    coef[kCoefficientNames[k]] = coefficient_to_lbf_ft(s.coefficients.a[k], m, n);
    coef_units[kCoefficientNames[k]] = coefficient_unit(m, n, "lbf", "ft");
    coef_si[kCoefficientNames[k]] = s.coefficients.a[k];
    coef_si_units[kCoefficientNames[k]] = coefficient_unit(m, n, "N", "m");
  }
  j["coefficients"] = coef;
  j["coefficient_units"] = coef_units;
  j["coefficients_si"] = coef_si;
  j["coefficient_units_si"] = coef_si_units;
  j["fit_rms_lbf"] = units::n_to_lbf(s.fit_rms_error_n);
  j["fit_max_error_lbf"] = units::n_to_lbf(s.fit_max_error_n);
  j["rms_tension_lbf"] = units::n_to_lbf(s.rms_tension_n);
  j["small_motion_ratio"] = s.small_motion_ratio;
  j["run_weight_exponent"] = s.run_weight_exponent;
  j["samples_used"] = s.samples_used;
  j["samples_excluded"] = s.samples_excluded;
  j["fitted_range"] = {{"xi_min_ft", units::m_to_ft(s.fit_xi_min_m)},
                       {"xi_max_ft", units::m_to_ft(s.fit_xi_max_m)},
                       {"xi_dot_max_ft_s", units::m_to_ft(s.fit_xi_dot_max_m_s)}};
  j["resolution"] = {{"elements", s.n_elements},
                     {"steps_per_period", s.steps_per_period},
                     {"steps_per_line_period", s.steps_per_line_period},
                     {"min_dt_s", s.min_dt_s},
                     {"max_dt_s", s.max_dt_s},
                     {"space_resolution_change", s.space_resolution_change},
                     {"time_resolution_change", s.time_resolution_change},
                     {"criterion", r.resolution_tolerance},
                     {"probes_left_out", s.resolution_probes_left_out}};
  j["runs"] = s.runs;
  j["runs_not_periodic"] = s.runs_not_periodic;
  ordered_json damping = ordered_json::array();
  for (const towline::RunDamping& d : r.damping) {
    damping.push_back({{"omega_rad_s", d.omega_rad_s},
                       {"amplitude_ft", units::m_to_ft(d.amplitude_m)},
                       {"cable_lbf_s_per_ft", units::n_s_per_m_to_lbf_s_per_ft(d.cable_n_s_m)},
                       {"polynomial_lbf_s_per_ft", units::n_s_per_m_to_lbf_s_per_ft(d.polynomial_n_s_m)},
                       {"slack_fraction", d.slack_fraction}});
  }
  j["damping_per_run"] = damping;
  j["runtime_s"] = r.runtime_s;
  std::cout << j.dump(2) << "\n";
}

// EQ-TOWLINE-19 per excitation frequency: the range of the cable's and the
// polynomial's damping over the frequency's amplitudes.
void print_damping_text(const std::vector<towline::RunDamping>& damping) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::cout << "\ndamping of the runs' motion (EQ-TOWLINE-19: energy dissipated per cycle / (pi w A^2), lbf s/ft)\n";
  TextTable t({"w rad/s", "amplitudes ft", "cable", "polynomial", "cable / polynomial"});
  for (std::size_t i = 0; i < damping.size();) {
    std::size_t j = i;
    double c_lo = kInf, c_hi = -kInf, p_lo = kInf, p_hi = -kInf, r_lo = kInf, r_hi = -kInf;
    for (; j < damping.size() && damping[j].omega_rad_s == damping[i].omega_rad_s; ++j) {
      const double c = units::n_s_per_m_to_lbf_s_per_ft(damping[j].cable_n_s_m);
      const double p = units::n_s_per_m_to_lbf_s_per_ft(damping[j].polynomial_n_s_m);
      c_lo = std::min(c_lo, c);
      c_hi = std::max(c_hi, c);
      p_lo = std::min(p_lo, p);
      p_hi = std::max(p_hi, p);
      if (p > 0.0) {
        r_lo = std::min(r_lo, c / p);
        r_hi = std::max(r_hi, c / p);
      }
    }
    t.add_row({fmt(damping[i].omega_rad_s, 2),
               fmt(units::m_to_ft(damping[i].amplitude_m), 2) + " - " + fmt(units::m_to_ft(damping[j - 1].amplitude_m), 2),
               fmt(c_lo, 0) + " - " + fmt(c_hi, 0), fmt(p_lo, 0) + " - " + fmt(p_hi, 0),
               r_lo <= r_hi ? fmt(r_lo, 2) + " - " + fmt(r_hi, 2) : "-"});
    i = j;
  }
  t.print(std::cout);
}

void print_towline_text(const TowlineArgs& a, const TowlineReport& r) {
  const towline::FitSummary& s = r.s;
  const auto& powers = towline::PolynomialCoefficients::kPowers;
  std::cout << r.tug.name << " " << a.line << " hawser, " << fmt(a.length_ft, 0) << " ft (+ pendant), to " << r.tow.name
            << ", mean tension " << fmt_grouped(a.mean_tension_lbf) << " lbf\n\n";
  TextTable seg({"segment (tug -> tow)", "kind", "length ft", "EA lbf", "wet weight lb/ft", "breaking lbf"});
  for (const auto& sg : r.line.segments) {
    const auto& c = sg.component;
    seg.add_row({c.name, model::to_string(c.kind), fmt(units::m_to_ft(sg.length_m), 1),
                 fmt_grouped(units::n_to_lbf(c.ea_n)), fmt(units::n_per_m_to_lbf_per_ft(c.weight_in_water_n_m), 3),
                 fmt_grouped(units::n_to_lbf(c.breaking_strength_n))});
  }
  seg.print(std::cout);
  std::cout << "\nstatic geometry (elastic catenary, tow points " << fmt(units::m_to_ft(r.points.tug_height_m), 1)
            << " ft and " << fmt(units::m_to_ft(r.points.tow_height_m), 1) << " ft above the waterline)\n";
  TextTable g({"quantity", "value"});
  g.add_row({"span", fmt(units::m_to_ft(s.span_m), 1) + " ft"});
  g.add_row({"sag below the chord", fmt(units::m_to_ft(s.sag_m), 2) + " ft"});
  g.add_row({"lowest point", fmt(units::m_to_ft(s.lowest_elevation_m), 2) + " ft (waterline = 0)"});
  g.add_row({"end angle at the tug", fmt(units::rad_to_deg(s.tug_angle_rad), 3) + " deg below horizontal"});
  g.add_row({"end angle at the tow", fmt(units::rad_to_deg(s.tow_angle_rad), 3) + " deg below horizontal"});
  g.add_row({"static stiffness dH/dX", fmt(units::n_per_m_to_lbf_per_ft(s.static_stiffness_n_m), 1) + " lbf/ft"});
  g.add_row({"straight spring EA/L", fmt(units::n_per_m_to_lbf_per_ft(s.straight_spring_n_m), 1) + " lbf/ft"});
  g.add_row({"breaking strength", fmt_grouped(units::n_to_lbf(s.breaking_strength_n)) + " lbf"});
  g.print(std::cout);
  std::cout << "\npolynomial tau(xi, xi_dot) = sum a_mn xi^m xi_dot^n (tau lbf, xi ft, xi_dot ft/s)\n";
  TextTable c({"coefficient", "value", "unit", "SI value", "SI unit"});
  for (int i = 0; i < towline::PolynomialCoefficients::kCount; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const int m = powers[k][0], n = powers[k][1];
    c.add_row({kCoefficientNames[k], fmt(coefficient_to_lbf_ft(s.coefficients.a[k], m, n)),
               coefficient_unit(m, n, "lbf", "ft"), fmt(s.coefficients.a[k]), coefficient_unit(m, n, "N", "m")});
  }
  c.print(std::cout);
  std::cout << "\nfit: RMS error " << fmt_grouped(units::n_to_lbf(s.fit_rms_error_n)) << " lbf, max error "
            << fmt_grouped(units::n_to_lbf(s.fit_max_error_n)) << " lbf (RMS tension "
            << fmt_grouped(units::n_to_lbf(s.rms_tension_n)) << " lbf); " << s.samples_used << " samples used, "
            << s.samples_excluded << " above breaking strength left out\n";
  std::cout << "small motion (" << fmt(units::m_to_ft(towline::kSmallMotionAmplitudeM), 0) << " ft at a "
            << fmt(towline::kSmallMotionPeriodS, 0) << " s period): first harmonic " << fmt(s.small_motion_ratio, 3)
            << " x static stiffness x amplitude (EQ-TOWLINE-16; quasi-static limit 1; run weight exponent "
            << fmt(s.run_weight_exponent, 2) << ")\n";
  std::cout << "fitted range: xi " << fmt(units::m_to_ft(s.fit_xi_min_m), 2) << " to "
            << fmt(units::m_to_ft(s.fit_xi_max_m), 2) << " ft, |xi_dot| up to "
            << fmt(units::m_to_ft(s.fit_xi_dot_max_m_s), 2) << " ft/s (an extrapolation outside)\n";
  std::cout << "resolution: " << s.n_elements << " elements (change N -> 2N " << fmt(100.0 * s.space_resolution_change, 2)
            << " %), " << s.steps_per_period << " steps per period (change dt -> dt/2 "
            << fmt(100.0 * s.time_resolution_change, 2) << " %); criterion "
            << fmt(100.0 * r.resolution_tolerance, 1) << " %; " << s.runs << " runs, " << s.runs_not_periodic
            << " not periodic";
  if (s.resolution_probes_left_out > 0) {
    std::cout << "; " << s.resolution_probes_left_out
              << " probe runs that never became periodic left out of the resolution criterion";
  }
  std::cout << "; " << fmt(r.runtime_s, 2) << " s\n";
  print_damping_text(r.damping);
}

int run_towline(const Context& ctx, const TowlineArgs& a) {
  const io::ShipCatalog cat = load_catalog(ctx);
  const model::Vessel& tug = cat.vessel(a.tug).vessel;
  const model::Vessel& tow = cat.vessel(a.tow).vessel;
  const model::Towline line = checked_towline(cat, tug, tow, a);
  const double mean_n = units::lbf_to_n(a.mean_tension_lbf);
  const towline::TowPoints points{tug.tow_point.z_m, tow.tow_point.z_m};
  towline::TowlineFitOptions options;
  options.num_threads = a.threads;
  const auto start = std::chrono::steady_clock::now();
  const std::shared_ptr<const towline::TowlineFit> fit = towline::build_towline_fit(line, points, mean_n, options);
  const double runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const TowlineReport report{tug,       tow,        line, points, fit->summary(), options.resolution_tolerance,
                             runtime_s, towline::run_damping(*fit)};
  if (a.json) {
    print_towline_json(a, report);
  } else {
    print_towline_text(a, report);
  }
  return 0;
}

}  // namespace

void add_towline_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<TowlineArgs>();
  CLI::App* c = app.add_subcommand(
      "towline", "Towline model of one configuration: static catenary, polynomial coefficients, fit errors");
  c->add_option("--tug", a->tug, "Tug name (T-ATF, ARS50): it rigs the hawser and its pendant")->required();
  c->add_option("--tow", a->tow,
                "Tow name (LHA1, AE26, CG47, FFG7, YRBM). Required: the catenary runs between the tug's tow point "
                "and the tow's bow fitting, so the shape, end angles and stiffness depend on both heights")
      ->required();
  c->add_option("--line", a->line, "Hawser: wire or fiber")->required()->check(CLI::IsMember({"wire", "fiber"}));
  c->add_option("--length-ft", a->length_ft, "Hawser length [ft] (the pendant is added)")
      ->required()
      ->check(number_in(100.0, 10000.0));
  c->add_option("--mean-tension-lbf", a->mean_tension_lbf,
                "Mean (horizontal) towline tension [lbf], below the breaking strength")
      ->required()
      ->check(number_in(100.0, 2.0e6));
  c->add_option("--threads", a->threads, "Threads for the 56 dynamics runs (default: all cores)")
      ->check(CLI::Range(0, 1024));
  c->add_flag("--json", a->json, "JSON output");
  c->callback([&ctx, a] { ctx.action = [&ctx, a] { return run_towline(ctx, *a); }; });
}

}  // namespace towdb::cli
