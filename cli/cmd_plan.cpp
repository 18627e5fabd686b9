// towdb plan: the tow planner's pictures for one tug, tow, line and sea
// (issue 18 item 2), drawn by gnuplot (plot.hpp) from the curves of
// plan_curves.hpp:
//   tension-vs-speed.png    extreme tension against speed, one curve per
//                           heading, the band extreme +/- uncertainty, the
//                           BS/1.5 limit and each heading's fastest passing speed;
//   tension-vs-heading.png  polar: extreme tension against heading at the
//                           chosen speed and length, band and BS/1.5 circle;
//   tension-vs-length.png   extreme tension against towline length at the
//                           chosen speed and heading, band, limit, shortest
//                           passing length.
//
//   towdb plan --db F --tug T --tow W --line wire|fiber --wind-kt U (or --hs-ft H [--tp-s P])
//              --speed-kt V --heading-deg H --length-ft L --out-dir DIR
//              [--curve-headings-deg 0,45,90,135,180] [--mean-tension-lbf M]
//              [--probability P] [--tow-days D] [--brake] [--json]
// Every curve is computed before anything is written: a bad question exits 2
// and writes nothing; the three files are renamed into place together.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "common/error.hpp"
#include "output.hpp"
#include "plan_curves.hpp"
#include "plot.hpp"
#include "query_database.hpp"

namespace towdb::cli {

namespace {

struct PlanArgs {
  std::string db, out_dir;
  PlanQuestion q;
  bool json = false;
};

// Shortest round-trip text: gnuplot reads the numbers as computed.
void write_points(const std::filesystem::path& file, const std::vector<PlanPoint>& points) {
  std::ofstream f(file);
  for (const PlanPoint& p : points) {
    f << fmt(p.x) << " " << fmt(p.extreme_kips) << " " << fmt(p.extreme_kips - p.uncertainty_kips) << " "
      << fmt(p.extreme_kips + p.uncertainty_kips) << "\n";
  }
}

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// A two-line gnuplot title in double quotes (where "\n" is a line break).
std::string gnuplot_title(const std::string& line1, const std::string& line2) {
  std::string t = line1 + "\\n" + line2;
  std::replace(t.begin(), t.end(), '"', '\'');
  return "set title \"" + t + "\" noenhanced\n";
}

std::string title_of(const Plan& plan) {
  const towdb_query_request& r = plan.request.values;
  const std::string sea = std::isnan(r.wind_kt) ? "Hs " + fmt(r.hs_ft) + " ft" : "wind " + fmt(r.wind_kt) + " kt";
  return plan.chosen.tug + " towing " + plan.chosen.tow + " on " + plan.request.line + ", " + sea;
}

std::string footnote(const Plan& plan) {
  const towdb_query_request& r = plan.request.values;
  return "p = " + fmt(r.probability) + " in " + fmt(r.tow_days) + " d; mean tension " +
         (std::isnan(r.mean_tension_lbf) ? std::string("calculated for each speed") : fmt_grouped(r.mean_tension_lbf) + " lbf") +
         "; band: +/- uncertainty (EQ-QUERY-7)";
}

// A round step for about four rings between 0 and r_max: 10, 20, 50, 100, 200, ... kips.
double ring_step_kips(double r_max) {
  if (!(r_max > 0.0) || !std::isfinite(r_max)) return 10.0;
  for (double step = 10.0;; step *= 10.0) {
    for (double m : {1.0, 2.0, 5.0}) {
      if (m * step * 4.0 >= r_max) return m * step;
    }
  }
}

const char* const kColors[] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02", "#a6761d", "#666666"};

std::string speed_script(const Plan& plan, const std::filesystem::path& dir, const std::filesystem::path& png) {
  std::string s = "reset\nset terminal pngcairo size 1000,650 font 'sans,11'\nset output " + quoted(png) + "\n" +
                  gnuplot_title(title_of(plan) + ", " + fmt(plan.request.values.length_ft) + " ft", footnote(plan)) +
                  "set xlabel 'tow speed (kt)'\nset ylabel 'extreme tension (kips)'\n"
                  "set grid\nset key below horizontal noenhanced\nset style fill transparent solid 0.18 noborder\n";
  std::string plot = "plot ";
  std::ofstream marks(dir / "speed-marks.dat");
  for (std::size_t i = 0; i < plan.by_speed.size(); ++i) {
    const PlanCurve& c = plan.by_speed[i];
    const std::string color = kColors[i % (sizeof kColors / sizeof kColors[0])];
    const auto file = dir / ("speed-" + std::to_string(i) + ".dat");
    write_points(file, c.points);
    plot += quoted(file) + " using 1:3:4 with filledcurves lc rgb '" + color + "' notitle, " + quoted(file) +
            " using 1:2 with lines lw 2 lc rgb '" + color + "' title 'heading " + fmt(c.heading_deg) + " deg', ";
    if (c.passing_limit) marks << fmt(*c.passing_limit) << " " << fmt(c.passing_limit_extreme_kips) << "\n";
  }
  marks.close();
  plot += fmt(plan.extreme_limit_kips) + " with lines dt 2 lw 2 lc rgb 'red' title 'BS/1.5 = " +
          fmt(plan.extreme_limit_kips, 1) + " kips'";
  if (std::filesystem::file_size(dir / "speed-marks.dat") > 0) {
    plot += ", " + quoted(dir / "speed-marks.dat") +
            " using 1:2 with points pt 7 ps 1.6 lc rgb 'black' title 'fastest passing speed (in the stored range)'";
  }
  return s + plot + "\n";
}

std::string heading_script(const Plan& plan, const std::filesystem::path& dir, const std::filesystem::path& png) {
  const auto file = dir / "heading.dat";
  write_points(file, plan.by_heading.points);
  double r_max = plan.extreme_limit_kips;
  for (const PlanPoint& p : plan.by_heading.points) r_max = std::max(r_max, p.extreme_kips + p.uncertainty_kips);
  const towdb_query_request& r = plan.request.values;
  // 0 deg (following seas) at the top, headings clockwise; the band is drawn as
  // the upper edge filled, the lower edge filled white over it, then the lines.
  return "reset\nset terminal pngcairo size 800,800 font 'sans,11'\nset output " + quoted(png) + "\n" +
         gnuplot_title(title_of(plan) + ", " + fmt(r.speed_kt) + " kt, " + fmt(r.length_ft) + " ft", footnote(plan)) +
         "set polar\nset angles degrees\nset theta top clockwise\nset size square\n"
         "unset border\nunset xtics\nunset ytics\nunset raxis\nset grid polar 30\nset rrange [0:" +
         fmt(std::ceil(r_max * 1.15)) + "]\nset rtics " + fmt(ring_step_kips(r_max)) + "," +
         fmt(ring_step_kips(r_max)) + " format '%g kips'\nset ttics 0,30 format '%g deg'\n"
         "set key bmargin center horizontal noenhanced\nset style fill solid 1.0 noborder\n"
         "plot " + quoted(file) + " using 1:4 with filledcurves lc rgb '#c8dff0' title 'band', " + quoted(file) +
         " using 1:3 with filledcurves lc rgb 'white' notitle, " + quoted(file) +
         " using 1:2 with lines lw 2 lc rgb '#1f5f99' title 'extreme tension', " + fmt(plan.extreme_limit_kips) +
         " with lines dt 2 lw 2 lc rgb 'red' title 'BS/1.5 = " + fmt(plan.extreme_limit_kips, 1) + " kips'\n";
}

std::string length_script(const Plan& plan, const std::filesystem::path& dir, const std::filesystem::path& png) {
  const auto file = dir / "length.dat";
  write_points(file, plan.by_length.points);
  const towdb_query_request& r = plan.request.values;
  std::string s = "reset\nset terminal pngcairo size 1000,650 font 'sans,11'\nset output " + quoted(png) + "\n" +
                  gnuplot_title(title_of(plan) + ", " + fmt(r.speed_kt) + " kt, heading " + fmt(r.heading_deg) + " deg",
                                footnote(plan)) +
                  "set xlabel 'towline length (ft)'\n"
                  "set ylabel 'extreme tension (kips)'\nset grid\nset key below horizontal noenhanced\n"
                  "set style fill transparent solid 0.25 noborder\n"
                  "plot " + quoted(file) + " using 1:3:4 with filledcurves lc rgb '#1f5f99' title 'band', " +
                  quoted(file) + " using 1:2 with lines lw 2 lc rgb '#1f5f99' title 'extreme tension', " +
                  fmt(plan.extreme_limit_kips) + " with lines dt 2 lw 2 lc rgb 'red' title 'BS/1.5 = " +
                  fmt(plan.extreme_limit_kips, 1) + " kips'";
  if (plan.by_length.passing_limit) {
    std::ofstream(dir / "length-mark.dat") << fmt(*plan.by_length.passing_limit) << " "
                                           << fmt(plan.by_length.passing_limit_extreme_kips) << "\n";
    s += ", " + quoted(dir / "length-mark.dat") +
         " using 1:2 with points pt 7 ps 1.6 lc rgb 'black' title 'shortest passing length " +
         fmt(std::ceil(*plan.by_length.passing_limit)) + " ft'";
  }
  return s + "\n";
}

// Draws the three PNGs into a temporary directory, then moves them into
// out_dir: a gnuplot failure leaves out_dir as it was.
void write_plan_pngs(const Plan& plan, const std::filesystem::path& out_dir) {
  namespace fs = std::filesystem;
  const fs::path dir = make_plot_data_dir("towdb-plan");
  const char* const names[] = {"tension-vs-speed.png", "tension-vs-heading.png", "tension-vs-length.png"};
  const std::string script = speed_script(plan, dir, dir / names[0]) + heading_script(plan, dir, dir / names[1]) +
                             length_script(plan, dir, dir / names[2]);
  try {
    run_gnuplot(script);
    fs::create_directories(out_dir);
    for (const char* n : names) {
      fs::copy_file(dir / n, out_dir / n, fs::copy_options::overwrite_existing);  // rename may cross filesystems
    }
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
}

int run_plan(const PlanArgs& a) {
  if (a.out_dir.empty() && !a.json) throw InputError("--out-dir: required (or --json for the curves' numbers)");
  if (!a.out_dir.empty()) check_output_dir("--out-dir", a.out_dir);
  const std::unique_ptr<query::Database> db = open_query_database("--db", a.db);
  const Plan plan = make_plan(*db, a.q);
  if (!a.out_dir.empty()) write_plan_pngs(plan, a.out_dir);
  if (a.json) {
    std::cout << plan_json(plan).dump(2) << "\n";
  } else {
    std::cout << title_of(plan) << "\n";
    for (const PlanCurve& c : plan.by_speed) {
      std::cout << "  heading " << fmt(c.heading_deg) << " deg: fastest passing speed "
                << (c.passing_limit ? fmt(*c.passing_limit, 2) + " kt" : std::string("none in the stored range"))
                << "\n";
    }
    std::cout << "  shortest passing towline: "
              << (plan.by_length.passing_limit ? fmt(std::ceil(*plan.by_length.passing_limit)) + " ft"
                                               : std::string("none in the stored range"))
              << "\nwrote " << (std::filesystem::path(a.out_dir) / "tension-vs-{speed,heading,length}.png").string()
              << "\n";
  }
  return 0;
}

}  // namespace

void add_plan_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<PlanArgs>();
  CLI::App* c = app.add_subcommand(
      "plan", "Pictures for a tow plan: extreme tension against speed (per heading), heading (polar) and length");
  c->add_option("--db", a->db, "towdb database file (opened read-only)")->required();
  c->add_option("--tug", a->q.tug, "Tug name (case, spaces and hyphens ignored; a unique prefix is enough)")
      ->required();
  c->add_option("--tow", a->q.tow, "Tow name")->required();
  c->add_option("--line", a->q.line, "Towline type")->required()->check(CLI::IsMember({"wire", "fiber"}));
  auto* wind = c->add_option("--wind-kt", a->q.wind_kt, "Wind speed [kt] (fully developed Pierson-Moskowitz sea)")
                   ->check(number_in(0.0, 200.0, true, false));
  auto* hs = c->add_option("--hs-ft", a->q.hs_ft, "Significant wave height [ft] (two-parameter seas)")
                 ->check(number_in(0.0, 200.0, true, false));
  wind->excludes(hs);
  c->add_option("--tp-s", a->q.tp_s, "Peak period [s] with --hs-ft")->check(number_in(0.0, 100.0, true, false));
  c->add_option("--speed-kt", a->q.speed_kt, "Tow speed [kt] of the heading and length plots")
      ->required()
      ->check(number_in(0.0, 100.0, true, false));
  c->add_option("--heading-deg", a->q.heading_deg, "Wave heading [deg] of the length plot, 0 = following seas")
      ->required()
      ->check(number_in(0.0, 360.0));
  c->add_option("--length-ft", a->q.length_ft, "Towline length [ft] of the speed and heading plots")
      ->required()
      ->check(number_in(0.0, 1e6, true, false));
  c->add_option("--curve-headings-deg", a->q.curve_headings_deg,
                "Headings [deg] of the speed plot's curves, comma-separated (default 0,45,90,135,180)")
      ->delimiter(',')
      ->expected(1, 8)
      ->check(number_in(0.0, 360.0));
  c->add_option("--mean-tension-lbf", a->q.mean_tension_lbf,
                "Mean towline tension [lbf] (default: the calculated one of each speed, query.h EQ-QUERY-9)")
      ->check(number_in(0.0, 1e7, true, false));
  c->add_option("--probability", a->q.probability, "Exceedance probability of the tow's maximum (default 0.001)")
      ->check(number_in(0.0, 1.0, true, true));
  c->add_option("--tow-days", a->q.tow_days, "Tow duration [days] (default 1)")->check(number_in(1.0, 1e6));
  c->add_flag("--brake", a->q.brake, "Towline held on the brake: mean tension limit BS/5 instead of BS/3");
  c->add_option("--out-dir", a->out_dir,
                "Directory for tension-vs-speed.png, tension-vs-heading.png, tension-vs-length.png (made if new)");
  c->add_flag("--json", a->json, "Print the curves' numbers as JSON");
  c->callback([&ctx, a] { ctx.action = [a] { return run_plan(*a); }; });
}

}  // namespace towdb::cli
