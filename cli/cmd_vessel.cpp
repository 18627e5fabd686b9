// towdb vessel: the seakeeping of one vessel at one speed and wave heading --
// heave and pitch RAOs, wave exciting force and moment, the added resistance
// operator R_aw/zeta^2 (strip theory, generator/seakeeping EQ-STRIP-*,
// EQ-AR-1), and its surge damping split into hull (EQ-PROPULSION-2),
// propeller (EQ-PROPULSION-5/6 for a tug, -9 for a tow) and wave-induced
// (EQ-AR-3, thesis 3.5) contributions in a Pierson-Moskowitz sea.
//
// Units at the edge: speed kt, heading deg (0 = following seas, 180 = head
// seas), wave amplitude ft, forces lbf, damping lbf s/ft, frequencies rad/s.
// A rotation RAO in deg/ft is the pitch amplitude [deg] per foot of wave
// amplitude; a force per foot of wave amplitude is lbf/ft; a moment per foot
// of wave amplitude is lbf ft/ft.
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "propulsion/hull_damping.hpp"
#include "propulsion/tow_propeller.hpp"
#include "propulsion/tug_propeller.hpp"
#include "sea/spectrum.hpp"
#include "seakeeping/seakeeping.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;

struct VesselArgs {
  std::string name;
  double speed_kt = 0.0;
  double heading_deg = 180.0;
  double wind_kt = 20.0;
  double mean_tension_lbf = 0.0;  // tugs only; 0 = not given
  std::string tow_propeller = "removed";
  bool tow_propeller_given = false;
  // Frequency grid: the AddedResistanceOptions defaults (the integrals of
  // EQ-AR-2 and EQ-AR-3 run over the same grid as the printed operator).
  double omega_min_rad_s = seakeeping::AddedResistanceOptions{}.omega_min_rad_s;
  double omega_max_rad_s = seakeeping::AddedResistanceOptions{}.omega_max_rad_s;
  int omega_count = seakeeping::AddedResistanceOptions{}.omega_count;
  int threads = 0;
  bool json = false;
  bool csv = false;
  std::string plot;
};

// One row of the frequency table, in output units.
struct Row {
  double omega_rad_s = 0.0;
  double omega_e_rad_s = 0.0;
  double wavelength_ft = 0.0;
  double heave_rao_ft_per_ft = 0.0;
  double heave_phase_deg = 0.0;
  double pitch_rao_deg_per_ft = 0.0;
  double pitch_phase_deg = 0.0;
  double heave_force_lbf_per_ft = 0.0;
  double pitch_moment_lbf_ft_per_ft = 0.0;
  double heave_damping_lbf_s_per_ft = 0.0;
  double pitch_damping_lbf_ft_s = 0.0;
  double added_resistance_lbf_per_ft2 = 0.0;
};

// Added resistance per wave amplitude squared: N/m^2 -> lbf/ft^2.
double n_per_m2_to_lbf_per_ft2(double x) { return units::n_to_lbf(x * units::ft2_to_m2(1.0)); }

Row to_row(const seakeeping::VesselResponse& r) {
  using seakeeping::kHeave;
  using seakeeping::kPitch;
  Row w;
  w.omega_rad_s = r.omega_rad_s;
  w.omega_e_rad_s = r.omega_e_rad_s;
  w.wavelength_ft = units::m_to_ft(2.0 * kPi / r.wavenumber_rad_m);
  // Translations: m per m of wave amplitude = ft per ft.
  w.heave_rao_ft_per_ft = std::abs(r.rao(kHeave));
  w.heave_phase_deg = units::rad_to_deg(std::arg(r.rao(kHeave)));
  // Rotations: rad per m of wave amplitude -> deg per ft (times m per ft).
  w.pitch_rao_deg_per_ft = units::rad_to_deg(std::abs(r.rao(kPitch)) * units::ft_to_m(1.0));
  w.pitch_phase_deg = units::rad_to_deg(std::arg(r.rao(kPitch)));
  w.heave_force_lbf_per_ft = units::n_per_m_to_lbf_per_ft(std::abs(r.exciting_force_per_m(kHeave)));
  // N m per m of amplitude = N: the lever arm's and the amplitude's feet cancel.
  w.pitch_moment_lbf_ft_per_ft = units::n_to_lbf(std::abs(r.exciting_force_per_m(kPitch)));
  w.heave_damping_lbf_s_per_ft = units::n_s_per_m_to_lbf_s_per_ft(r.damping(kHeave, kHeave));
  w.pitch_damping_lbf_ft_s = units::m_to_ft(units::n_to_lbf(r.damping(kPitch, kPitch)));
  w.added_resistance_lbf_per_ft2 = n_per_m2_to_lbf_per_ft2(r.added_resistance_n_per_m2);
  return w;
}

struct Damping {
  double hull_n_s_m = 0.0;
  double propeller_n_s_m = 0.0;
  double wave_n_s_m = 0.0;
  std::string propeller_note;
};

void write_vessel_plot(const std::string& png_path, const std::string& title, const std::vector<Row>& rows) {
  const auto dir = make_plot_data_dir("towdb-vessel");
  {
    std::ofstream d(dir / "rao.dat");
    for (const Row& r : rows) {
      d << r.omega_rad_s << " " << r.heave_rao_ft_per_ft << " " << r.pitch_rao_deg_per_ft << " "
        << r.added_resistance_lbf_per_ft2 << "\n";
    }
  }
  const std::string f = (dir / "rao.dat").string();
  const std::string script =
      "set terminal pngcairo size 1500,500 font 'sans,11'\n"
      "set output '" + png_path + "'\n"
      "set multiplot layout 1,3 title '" + title + "'\n"
      "set grid\nset xlabel 'wave frequency {/Symbol w} (rad/s)'\n"
      "set title 'Heave RAO'\nset ylabel 'heave / wave amplitude (ft/ft)'\n"
      "plot '" + f + "' using 1:2 with linespoints pt 7 ps 0.5 lw 2 title ''\n"
      "set title 'Pitch RAO'\nset ylabel 'pitch / wave amplitude (deg/ft)'\n"
      "plot '" + f + "' using 1:3 with linespoints pt 7 ps 0.5 lw 2 title ''\n"
      "set title 'Added resistance operator'\nset ylabel 'R_{aw} / {/Symbol z}_a^2 (lbf/ft^2)'\n"
      "plot '" + f + "' using 1:4 with linespoints pt 7 ps 0.5 lw 2 title ''\n"
      "unset multiplot\n";
  run_gnuplot_with_data(script, dir);
}

// Refuses options that do not fit the vessel's role or each other.
void check_vessel_args(const model::Vessel& v, const VesselArgs& a) {
  const bool is_tug = v.role == model::VesselRole::kTug;
  if (is_tug && !(a.mean_tension_lbf > 0.0)) {
    throw InputError("--mean-tension-lbf is required for the tug '" + v.name +
                     "': its propeller damping depends on the thrust it gives (tug resistance + mean tension)");
  }
  if (is_tug && a.tow_propeller_given) {
    throw InputError("--tow-propeller " + a.tow_propeller + ": only for a tow; '" + v.name +
                     "' is a tug (its propeller damping follows from --mean-tension-lbf)");
  }
  if (!is_tug && a.mean_tension_lbf > 0.0) {
    throw InputError("--mean-tension-lbf: value = " + fmt(a.mean_tension_lbf) + ": only for a tug; '" + v.name +
                     "' is a tow (its propeller is set by --tow-propeller)");
  }
  if (!(a.omega_max_rad_s > a.omega_min_rad_s)) {
    throw InputError("--omega-max-rad-s: value = " + fmt(a.omega_max_rad_s) + ": must exceed --omega-min-rad-s (" +
                     fmt(a.omega_min_rad_s) + ")");
  }
}

// The uniform wave-frequency grid of the added-resistance options.
std::vector<double> frequency_grid(const seakeeping::AddedResistanceOptions& ar) {
  std::vector<double> omegas(static_cast<std::size_t>(ar.omega_count));
  for (int i = 0; i < ar.omega_count; ++i) {
    omegas[static_cast<std::size_t>(i)] = ar.omega_min_rad_s + (ar.omega_max_rad_s - ar.omega_min_rad_s) *
                                                                   static_cast<double>(i) /
                                                                   static_cast<double>(ar.omega_count - 1);
  }
  return omegas;
}

// The propeller's surge damping (tug: at the thrust for the mean tension; tow:
// in its --tow-propeller state) into `d`, and its details for the JSON output.
ordered_json propeller_damping(const model::Vessel& v, double u, const VesselArgs& a, Damping& d) {
  if (v.role == model::VesselRole::kTug) {
    const propulsion::TugPropellerDamping p =
        propulsion::tug_propeller_damping(v, u, units::lbf_to_n(a.mean_tension_lbf));
    d.propeller_n_s_m = p.damping_n_s_m;
    d.propeller_note = std::string("one propeller at 80% rpm, P/D ") + fmt(p.pitch_ratio, 3) + ", " +
                       propulsion::to_string(p.status) + (p.floored ? ", floored" : "");
    return {{"status", propulsion::to_string(p.status)},
            {"floored", p.floored},
            {"pitch_ratio", p.pitch_ratio},
            {"advance_ratio", p.advance_ratio},
            {"required_thrust_per_propeller_lbf", units::n_to_lbf(p.required_thrust_per_propeller_n)},
            {"max_thrust_per_propeller_lbf", units::n_to_lbf(p.max_thrust_per_propeller_n)}};
  }
  propulsion::TowPropellerOptions po;
  po.state = a.tow_propeller == "locked" ? propulsion::TowPropellerState::kLocked
             : a.tow_propeller == "free" ? propulsion::TowPropellerState::kFreeSpinning
                                         : propulsion::TowPropellerState::kRemoved;
  d.propeller_n_s_m = propulsion::tow_propeller_damping_n_s_m(v, u, po);
  d.propeller_note = "tow propeller " + a.tow_propeller;
  return {{"state", a.tow_propeller}, {"drag_lbf", units::n_to_lbf(propulsion::tow_propeller_drag_n(v, u, po))}};
}

// What run_vessel computed, in SI, for the three output formats.
struct VesselSummary {
  std::vector<Row> rows;
  double added_resistance_n = 0.0;       // EQ-AR-2 at U
  double added_resistance_step_n = 0.0;  // at U + 1 ft/s
  Damping damping;
  double total_damping_n_s_m = 0.0;
  ordered_json propeller_detail;
};

void print_vessel_csv(const std::vector<Row>& rows) {
  std::cout << "omega_rad_s,omega_e_rad_s,wavelength_ft,heave_rao_ft_per_ft,heave_phase_deg,pitch_rao_deg_per_ft,"
               "pitch_phase_deg,heave_force_lbf_per_ft,pitch_moment_lbf_ft_per_ft,heave_damping_lbf_s_per_ft,"
               "pitch_damping_lbf_ft_s,added_resistance_lbf_per_ft2\n";
  for (const Row& r : rows) {
    std::cout << fmt(r.omega_rad_s) << "," << fmt(r.omega_e_rad_s) << "," << fmt(r.wavelength_ft) << ","
              << fmt(r.heave_rao_ft_per_ft) << "," << fmt(r.heave_phase_deg) << "," << fmt(r.pitch_rao_deg_per_ft)
              << "," << fmt(r.pitch_phase_deg) << "," << fmt(r.heave_force_lbf_per_ft) << ","
              << fmt(r.pitch_moment_lbf_ft_per_ft) << "," << fmt(r.heave_damping_lbf_s_per_ft) << ","
              << fmt(r.pitch_damping_lbf_ft_s) << "," << fmt(r.added_resistance_lbf_per_ft2) << "\n";
  }
}

void print_vessel_json(const model::Vessel& v, const VesselArgs& a, const sea::Spectrum& pm,
                       const VesselSummary& s) {
  const bool is_tug = v.role == model::VesselRole::kTug;
  const std::vector<Row>& rows = s.rows;
  const Damping& d = s.damping;
  ordered_json j;
  j["vessel"] = v.name;
  j["role"] = is_tug ? "tug" : "tow";
  j["speed_kt"] = a.speed_kt;
  j["heading_deg"] = a.heading_deg;
  j["wind_kt"] = a.wind_kt;
  if (is_tug) j["mean_tension_lbf"] = a.mean_tension_lbf;
  auto column = [&rows](double Row::*field) {
    ordered_json c = ordered_json::array();
    for (const Row& r : rows) c.push_back(r.*field);
    return c;
  };
  j["omega_rad_s"] = column(&Row::omega_rad_s);
  j["omega_e_rad_s"] = column(&Row::omega_e_rad_s);
  j["wavelength_ft"] = column(&Row::wavelength_ft);
  j["heave_rao_ft_per_ft"] = column(&Row::heave_rao_ft_per_ft);
  j["heave_phase_deg"] = column(&Row::heave_phase_deg);
  j["pitch_rao_deg_per_ft"] = column(&Row::pitch_rao_deg_per_ft);
  j["pitch_phase_deg"] = column(&Row::pitch_phase_deg);
  j["heave_force_lbf_per_ft"] = column(&Row::heave_force_lbf_per_ft);
  j["pitch_moment_lbf_ft_per_ft"] = column(&Row::pitch_moment_lbf_ft_per_ft);
  j["heave_damping_lbf_s_per_ft"] = column(&Row::heave_damping_lbf_s_per_ft);
  j["pitch_damping_lbf_ft_s"] = column(&Row::pitch_damping_lbf_ft_s);
  j["added_resistance_lbf_per_ft2"] = column(&Row::added_resistance_lbf_per_ft2);
  j["sea"] = {{"spectrum", "pierson-moskowitz"},
              {"wind_kt", a.wind_kt},
              {"significant_wave_height_ft", units::m_to_ft(pm.significant_height_m())},
              {"peak_omega_rad_s", pm.peak_omega_rad_s()}};
  j["mean_added_resistance_lbf"] = units::n_to_lbf(s.added_resistance_n);
  j["mean_added_resistance_plus_1_ft_s_lbf"] = units::n_to_lbf(s.added_resistance_step_n);
  j["surge_damping_lbf_s_per_ft"] = {{"hull", units::n_s_per_m_to_lbf_s_per_ft(d.hull_n_s_m)},
                                     {"propeller", units::n_s_per_m_to_lbf_s_per_ft(d.propeller_n_s_m)},
                                     {"wave", units::n_s_per_m_to_lbf_s_per_ft(d.wave_n_s_m)},
                                     {"total", units::n_s_per_m_to_lbf_s_per_ft(s.total_damping_n_s_m)}};
  j["propeller"] = s.propeller_detail;
  std::cout << j.dump(2) << "\n";
}

void print_vessel_text(const model::Vessel& v, const VesselArgs& a, const sea::Spectrum& pm,
                       const VesselSummary& summary) {
  const Damping& d = summary.damping;
  std::cout << v.name << " at " << fmt(a.speed_kt, 1) << " kt, wave heading " << fmt(a.heading_deg, 0)
            << " deg (0 following, 180 head seas)\n\n";
  TextTable t({"w rad/s", "w_e rad/s", "lambda ft", "heave ft/ft", "pitch deg/ft", "F3 lbf/ft", "M5 lbf ft/ft",
               "Raw lbf/ft^2"});
  for (const Row& r : summary.rows) {
    t.add_row({fmt(r.omega_rad_s, 3), fmt(r.omega_e_rad_s, 3), fmt(r.wavelength_ft, 0), fmt(r.heave_rao_ft_per_ft, 3),
               fmt(r.pitch_rao_deg_per_ft, 3), fmt_grouped(r.heave_force_lbf_per_ft),
               fmt_grouped(r.pitch_moment_lbf_ft_per_ft), fmt(r.added_resistance_lbf_per_ft2, 1)});
  }
  t.print(std::cout);
  std::cout << "\nPierson-Moskowitz sea, wind " << fmt(a.wind_kt, 0) << " kt (Hs "
            << fmt(units::m_to_ft(pm.significant_height_m()), 1) << " ft): mean added resistance "
            << fmt_grouped(units::n_to_lbf(summary.added_resistance_n)) << " lbf\n\n";
  TextTable s({"surge damping", "lbf s/ft", "note"});
  s.add_row({"hull", fmt(units::n_s_per_m_to_lbf_s_per_ft(d.hull_n_s_m), 1), "slope of the drag curve"});
  s.add_row({"propeller", fmt(units::n_s_per_m_to_lbf_s_per_ft(d.propeller_n_s_m), 1), d.propeller_note});
  s.add_row({"wave", fmt(units::n_s_per_m_to_lbf_s_per_ft(d.wave_n_s_m), 1),
             "added resistance at U + 1 ft/s minus at U"});
  s.add_row({"total", fmt(units::n_s_per_m_to_lbf_s_per_ft(summary.total_damping_n_s_m), 1), ""});
  s.print(std::cout);
}

int run_vessel(const Context& ctx, const VesselArgs& a) {
  if (!a.plot.empty()) check_output_file("--plot", a.plot);
  const io::ShipCatalog cat = load_catalog(ctx);
  const model::Vessel& v = cat.vessel(a.name).vessel;
  check_vessel_args(v, a);
  const double u = units::kt_to_m_s(a.speed_kt);
  const double mu = units::deg_to_rad(a.heading_deg);

  seakeeping::AddedResistanceOptions ar;
  ar.omega_min_rad_s = a.omega_min_rad_s;
  ar.omega_max_rad_s = a.omega_max_rad_s;
  ar.omega_count = a.omega_count;
  ar.response.num_threads = a.threads;
  ar.validate();
  const std::vector<double> omegas = frequency_grid(ar);
  const std::vector<seakeeping::VesselResponse> responses = seakeeping::compute_response(v, u, mu, omegas, ar.response);
  VesselSummary summary;
  for (const auto& r : responses) summary.rows.push_back(to_row(r));

  // The sea of the wave-induced surge damping (and of the mean added resistance).
  const sea::Spectrum pm = sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(a.wind_kt));
  const seakeeping::Spectrum spectrum = [&pm](double w) { return pm.density_m2_s(w); };
  // EQ-AR-2 at U, and EQ-AR-3: the same trapezoid rule at U + 1 ft/s on the
  // same grid (what wave_surge_damping_n_s_m computes, without recomputing U).
  summary.added_resistance_n = seakeeping::mean_added_resistance_n(responses, spectrum);
  summary.added_resistance_step_n = seakeeping::mean_added_resistance_n(
      seakeeping::compute_response(v, u + ar.speed_step_m_s, mu, omegas, ar.response), spectrum);

  Damping& d = summary.damping;
  d.hull_n_s_m = propulsion::hull_damping_n_s_m(v, u);
  d.wave_n_s_m = (summary.added_resistance_step_n - summary.added_resistance_n) / ar.speed_step_m_s;
  summary.propeller_detail = propeller_damping(v, u, a, d);
  summary.total_damping_n_s_m = d.hull_n_s_m + d.propeller_n_s_m + d.wave_n_s_m;

  if (!a.plot.empty()) {
    write_vessel_plot(a.plot,
                      v.name + " at " + fmt(a.speed_kt, 1) + " kt, heading " + fmt(a.heading_deg, 0) +
                          " deg (180 = head seas)",
                      summary.rows);
  }
  if (a.csv) {
    print_vessel_csv(summary.rows);
  } else if (a.json) {
    print_vessel_json(v, a, pm, summary);
  } else {
    print_vessel_text(v, a, pm, summary);
  }
  return 0;
}

}  // namespace

void add_vessel_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<VesselArgs>();
  CLI::App* c = app.add_subcommand(
      "vessel", "Seakeeping of one vessel: RAOs, exciting forces, added resistance, surge damping");
  c->add_option("name", a->name, "Vessel name or alias (T-ATF, ARS50, LHA1, AE26, CG47, FFG7, YRBM)")->required();
  c->add_option("--speed-kt", a->speed_kt, "Speed through the water [kt]")->required()->check(number_in(0.0, 20.0));
  c->add_option("--heading-deg", a->heading_deg, "Wave heading [deg], 0 = following seas, 180 = head seas")
      ->required()
      ->check(number_in(0.0, 360.0));
  c->add_option("--wind-kt", a->wind_kt,
                "Wind speed [kt] of the Pierson-Moskowitz sea for the wave-induced damping (default 20)")
      ->check(number_in(1.0, 80.0));
  c->add_option("--mean-tension-lbf", a->mean_tension_lbf,
                "Tugs only, required: mean towline tension [lbf] the propellers must give")
      ->check(number_in(100.0, 2.0e6));
  c->add_option("--tow-propeller", a->tow_propeller, "Tows only: removed (thesis, default), locked or free")
      ->check(CLI::IsMember({"removed", "locked", "free"}));
  c->add_option("--omega-min-rad-s", a->omega_min_rad_s, "Lowest wave frequency [rad/s] (default 0.2)")
      ->check(number_in(0.01, 10.0));
  c->add_option("--omega-max-rad-s", a->omega_max_rad_s, "Highest wave frequency [rad/s] (default 2.5)")
      ->check(number_in(0.02, 10.0));
  c->add_option("--omega-count", a->omega_count, "Number of frequencies, uniform grid (default 48)")
      ->check(CLI::Range(3, 2000));
  c->add_option("--threads", a->threads, "Threads over the frequencies (default: all cores)")
      ->check(CLI::Range(0, 1024));
  CLI::Option* json = c->add_flag("--json", a->json, "JSON output");
  CLI::Option* csv = c->add_flag("--csv", a->csv, "CSV output: one row per wave frequency");
  json->excludes(csv);
  c->add_option("--plot", a->plot, "Write a PNG: heave and pitch RAOs and the added resistance operator vs omega");
  c->callback([&ctx, a, c] {
    a->tow_propeller_given = c->count("--tow-propeller") > 0;
    ctx.action = [&ctx, a] { return run_vessel(ctx, *a); };
  });
}

}  // namespace towdb::cli
