// towdb validate: runs the thesis's Appendix C calibration cases through the
// whole chain and compares our dynamic tension with the thesis's
// (generator/validation/validation.hpp states the measures).
//
// Output directory:
//   cases.csv   one line per case (ours, thesis, ratio, ...); written as each
//               case finishes, so an interrupted run resumes where it stopped
//               (a case is reused when its case number and simulated days match)
//   report.md   median ratio, Spearman, shares within 1.5x and 2x, by group
//   scatter.png log-log scatter of ours vs thesis (gnuplot)
//   run-signature.txt  the options and a hash of the ship files; a journal
//               written under another signature is refused (no silent mixing)
// With --database FILE the cases are not simulated: each is asked of the
// database through the query library at the thesis's inputs (its mean tension
// given), as a planner would ask it, and the same report compares the answers
// with the thesis's; a refused question is listed with the refusal (the run is
// quick and is never resumed: cases.csv is written anew).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "cli.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "query_database.hpp"
#include "sweep/spec/calibration.hpp"
#include "towdb/query.hpp"
#include "validation/validation.hpp"

namespace towdb::cli {

namespace {

namespace fs = std::filesystem;

struct ValidateArgs {
  std::string cases_path;
  std::string out_dir;
  int threads = 1;
  double days_scale = 1.0;
  int min_days = 20;
  int max_cases = 0;
  int response_frequencies = 48;
  std::vector<std::string> filters;
  bool fresh = false;
  bool no_plot = false;
  bool no_second_order = false;
  bool no_wave_damping = false;
  bool thesis_towline_fit = false;
  bool tow_drift_at_tow = false;
  bool added_resistance_aft_of_beam = false;
  bool signed_drift = false;
  bool linear_non_surge_tension = false;
  std::string non_surge_stiffness = "a10";
  bool nonnegative_wave_damping = false;
  double encounter_cutoff_rad_s = simulation::kEncounterCutoff_rad_s;
  bool no_surge_diffraction = false;
  std::string database;  // --database: answers of this database instead of simulations
};

// `what` names the file for the message: a flag ("--cases") or its role.
std::string read_text(const fs::path& path, const std::string& what) {
  if (fs::is_directory(path)) throw InputError(what + " = " + path.string() + ": is a directory, expected a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(what + " = " + path.string() + ": cannot read the file (missing or unreadable)");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// --filter KEY=VALUE: keys tug, tow, line (w|f|wire|fiber), heading, wind,
// speed, case; names compare like the catalog (case, spaces and hyphens ignored).
bool matches(const sweep::CalibrationRow& r, const std::string& filter) {
  const auto eq = filter.find('=');
  if (eq == std::string::npos) throw InputError("--filter '" + filter + "': expected KEY=VALUE");
  const std::string key = filter.substr(0, eq), value = filter.substr(eq + 1);
  const auto number = [&]() {
    double v = 0.0;
    if (!parse_number(value, &v)) {
      throw InputError("--filter '" + filter + "': '" + value + "' is not a finite number (decimal, e.g. 180)");
    }
    return v;
  };
  if (key == "tug") return io::normalize_name(r.tug) == io::normalize_name(value) ||
                           io::normalize_name(r.tug).rfind(io::normalize_name(value), 0) == 0;
  if (key == "tow") return io::normalize_name(r.tow) == io::normalize_name(value) ||
                           io::normalize_name(r.tow).rfind(io::normalize_name(value), 0) == 0;
  if (key == "line") return r.line == value || r.line.substr(0, 1) == value;
  if (key == "heading") return r.heading_deg == number();
  if (key == "wind") return r.wind_kt == number();
  if (key == "speed") return r.speed_kt == number();
  if (key == "case") return r.case_number == static_cast<int>(number());
  throw InputError("--filter '" + filter + "': unknown key '" + key + "' (tug, tow, line, heading, wind, speed, case)");
}

// The --out directory was checked before any work (check_output_dir), so a
// failure here is the system's (disk full, permissions changed): exit 1.
void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw Error("validate: cannot write " + tmp.string() + " (in --out)");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw Error("validate: cannot rename " + tmp.string() + " to " + path.string() + ": " + ec.message());
}

// Everything besides the case rows that decides an outcome: the run options
// and the contents of every ship and towline file. A journal written under
// another signature is not resumed.
std::string run_signature(const validation::RunOptions& o, const io::ShipCatalog& catalog) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(catalog.directory())) {
    if (entry.is_regular_file() && entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::string hashes;
  for (const auto& f : files) hashes += io::sha256_hex(read_text(f, "ship or towline file"));
  std::ostringstream os;
  os << "days_scale=" << fmt(o.days_scale) << " min_days=" << o.min_days
     << " response_frequencies=" << o.response_frequencies << " second_order_forces=" << o.second_order_forces
     << " wave_surge_damping=" << o.wave_surge_damping << " thesis_towline_fit=" << o.thesis_towline_fit
     << " tow_drift_at_tow=" << o.tow_drift_at_tow;
  // The diagnostics, each written only when set, so that journals of the default
  // chain stay valid; surge_diffraction is the default since 0.4.0, so a 0.3.0
  // journal (without it) no longer matches and its cases are computed again.
  if (o.added_resistance_aft_of_beam) os << " added_resistance_aft_of_beam=1";
  if (o.signed_drift) os << " signed_drift=1";
  if (o.linear_non_surge_tension) os << " linear_non_surge_tension=1";
  if (o.non_surge_stiffness != simulation::CaseOptions::NonSurgeStiffness::kA10) {
    os << " non_surge_stiffness=" << static_cast<int>(o.non_surge_stiffness);
  }
  if (o.nonnegative_wave_damping) os << " nonnegative_wave_damping=1";
  if (o.encounter_cutoff_rad_s != simulation::kEncounterCutoff_rad_s) {
    os << " encounter_cutoff_rad_s=" << fmt(o.encounter_cutoff_rad_s);
  }
  if (o.surge_diffraction) os << " surge_diffraction=1";
  os << " ships_sha256=" << io::sha256_hex(hashes) << "\n";
  return os.str();
}

void write_scatter_plot(const fs::path& png, const std::vector<validation::CaseOutcome>& outcomes) {
  const fs::path dir = png.parent_path() / ".plot-data";
  fs::create_directories(dir);
  std::map<std::string, std::ofstream> files;
  double lo = 1e300, hi = 0.0;
  for (const auto& c : outcomes) {
    if (c.status != validation::CaseStatus::kOk) continue;
    std::string key = c.row.tow + " " + c.row.line;
    for (char& ch : key) {
      if (ch == ' ') ch = '_';
    }
    auto& f = files[key];
    if (!f.is_open()) f.open(dir / (key + ".dat"));
    f << c.row.dynamic_999_kips << " " << c.ours_kips << "\n";
    lo = std::min({lo, c.row.dynamic_999_kips, c.ours_kips});
    hi = std::max({hi, c.row.dynamic_999_kips, c.ours_kips});
  }
  if (files.empty()) return;
  for (auto& [k, f] : files) f.close();
  lo = std::pow(10.0, std::floor(std::log10(lo)));
  hi = std::pow(10.0, std::ceil(std::log10(hi)));
  std::ostringstream s;
  s << "set terminal pngcairo size 1000,900 font 'sans,11'\n"
    << "set output '" << png.string() << "'\n"
    << "set logscale xy\nset grid\nset key top left\n"
    << "set xrange [" << lo << ":" << hi << "]\nset yrange [" << lo << ":" << hi << "]\n"
    << "set xlabel 'thesis dynamic tension, Appendix C (kips)'\n"
    << "set ylabel 'towdb dynamic tension (kips)'\n"
    << "set title 'Dynamic tension at 0.001 per day: towdb vs thesis'\n"
    << "set arrow from 300," << lo << " to 300," << hi << " nohead dt 3 lc rgb 'gray40'\n"
    << "set label 'validity limit 300 kips (thesis 6.2)' at 310," << lo * 1.5 << " tc rgb 'gray40'\n"
    << "plot x title 'ours = thesis' lc rgb 'black' lw 2, "
    << "1.5*x title 'factor 1.5' lc rgb 'gray50' dt 2, x/1.5 notitle lc rgb 'gray50' dt 2, "
    << "2*x title 'factor 2' lc rgb 'gray70' dt 4, x/2 notitle lc rgb 'gray70' dt 4";
  int k = 0;
  for (const auto& [key, f] : files) {
    std::string title = key;
    for (char& ch : title) {
      if (ch == '_') ch = ' ';
    }
    const bool fiber = key.find("fiber") != std::string::npos;
    s << ", '" << (dir / (key + ".dat")).string() << "' using 1:2 with points pt " << (fiber ? 6 : 7) << " lc "
      << (k / 2 + 1) << " title '" << title << "'";
    ++k;
  }
  s << "\n";
  run_gnuplot_with_data(s.str(), dir);
}

// The calibration rows selected by --filter and --max-cases (at least one).
std::vector<sweep::CalibrationRow> select_rows(std::vector<sweep::CalibrationRow> rows, const ValidateArgs& a) {
  if (!a.filters.empty()) {
    std::vector<sweep::CalibrationRow> kept;
    for (const auto& r : rows) {
      bool all = true;
      for (const auto& f : a.filters) all = all && matches(r, f);
      if (all) kept.push_back(r);
    }
    rows = std::move(kept);
  }
  if (a.max_cases > 0 && rows.size() > static_cast<std::size_t>(a.max_cases)) {
    rows.resize(static_cast<std::size_t>(a.max_cases));
  }
  if (rows.empty()) throw InputError("no cases selected (check --filter / --max-cases)");
  return rows;
}

// --non-surge-stiffness (its values are checked by CLI11).
simulation::CaseOptions::NonSurgeStiffness non_surge_stiffness(const std::string& name) {
  using S = simulation::CaseOptions::NonSurgeStiffness;
  if (name == "equivalent-non-surge") return S::kEquivalentNonSurge;
  if (name == "equivalent-total") return S::kEquivalentTotal;
  return S::kA10;
}

validation::RunOptions run_options(const ValidateArgs& a) {
  validation::RunOptions options;
  options.days_scale = a.days_scale;
  options.min_days = a.min_days;
  options.num_threads = a.threads;
  options.response_frequencies = a.response_frequencies;
  options.second_order_forces = !a.no_second_order;
  options.wave_surge_damping = !a.no_wave_damping;
  options.thesis_towline_fit = a.thesis_towline_fit;
  options.tow_drift_at_tow = a.tow_drift_at_tow;
  options.added_resistance_aft_of_beam = a.added_resistance_aft_of_beam;
  options.signed_drift = a.signed_drift;
  options.linear_non_surge_tension = a.linear_non_surge_tension;
  options.non_surge_stiffness = non_surge_stiffness(a.non_surge_stiffness);
  options.nonnegative_wave_damping = a.nonnegative_wave_damping;
  options.encounter_cutoff_rad_s = a.encounter_cutoff_rad_s;
  options.surge_diffraction = !a.no_surge_diffraction;
  options.validate();
  return options;
}

// The cases an earlier run journalled in `out` under the same signature (none
// with --fresh); a journal of another signature is refused. Writes the
// signature and rewrites the journal cleanly (drops a half-written last line) for appending.
std::vector<validation::CaseOutcome> resume_journal(const fs::path& out, const std::string& signature, bool fresh) {
  const fs::path journal = out / "cases.csv";
  const fs::path signature_file = out / "run-signature.txt";
  std::vector<validation::CaseOutcome> done;
  if (!fresh && fs::exists(journal)) {
    if (!fs::exists(signature_file) || read_text(signature_file, "--out journal") != signature) {
      throw InputError("--out " + out.string() + " holds cases computed with other options or ship files (" +
                       signature_file.string() + "); use another --out or --fresh");
    }
    done = validation::parse_journal(read_text(journal, "--out journal"));
  }
  write_atomically(signature_file, signature);
  std::string text = validation::journal_header() + "\n";
  for (const auto& c : done) text += validation::journal_line(c) + "\n";
  write_atomically(journal, text);
  return done;
}

// How many of `rows` the journal already holds (same case, same simulated days).
int count_reused(const std::vector<sweep::CalibrationRow>& rows, const std::vector<validation::CaseOutcome>& done,
                 const validation::RunOptions& options) {
  int reused = 0;
  for (const auto& r : rows) {
    const int days = validation::simulated_days(r, options);
    for (const auto& d : done) {
      if (d.status == validation::CaseStatus::kOk && d.row.case_number == r.case_number && d.days_run == days) {
        ++reused;
        break;
      }
    }
  }
  return reused;
}

// One finished case on stderr: a progress bar on a terminal, a line otherwise.
void report_case(const validation::CaseOutcome& c, int finished, int total, double elapsed, double eta,
                 const ProgressLine& line) {
  const std::string what = c.status == validation::CaseStatus::kOk
                               ? "ratio " + fmt(c.ratio(), 2)
                               : "FAILED: " + c.error;
  if (line.enabled()) {
    const int width = 30;
    const int filled = width * finished / total;
    char text[512];
    std::snprintf(text, sizeof text, "  [%s] %d/%d cases  %.0f s elapsed  ETA %.0f s  case %d %s",
                  ProgressLine::bar(filled, width, '.').c_str(), finished, total, elapsed, eta, c.row.case_number,
                  what.substr(0, 60).c_str());
    line.draw(text, finished == total);
  } else {
    std::cerr << "  " << finished << "/" << total << " case " << c.row.case_number << " " << c.row.tug << "/"
              << c.row.tow << " " << fmt(c.row.heading_deg, 0) << " deg " << c.row.line << ": thesis "
              << fmt(c.row.dynamic_999_kips, 1) << " kips, ours " << fmt(c.ours_kips, 1) << " (" << what << ", "
              << c.days_run << " days, " << fmt(c.runtime_s, 1) << " s)\n";
  }
}

// The final journal: this run's cases in input order, then earlier cases not
// selected now.
void write_final_journal(const fs::path& journal, const std::vector<sweep::CalibrationRow>& rows,
                         const std::vector<validation::CaseOutcome>& outcomes,
                         const std::vector<validation::CaseOutcome>& done) {
  std::set<int> selected;
  for (const auto& r : rows) selected.insert(r.case_number);
  std::string text = validation::journal_header() + "\n";
  for (const auto& c : outcomes) text += validation::journal_line(c) + "\n";
  std::set<int> kept;
  for (const auto& d : done) {
    if (!selected.count(d.row.case_number) && kept.insert(d.row.case_number).second) {
      text += validation::journal_line(d) + "\n";
    }
  }
  write_atomically(journal, text);
}

// The report's note on how the run was made: the command line and the times.
std::string run_note(const ValidateArgs& a, const std::vector<validation::CaseOutcome>& outcomes, double wall_s,
                     int reused) {
  double case_time_s = 0.0;
  for (const auto& c : outcomes) case_time_s += c.runtime_s;
  std::ostringstream note;
  note << "Run: `towdb validate --cases " << fs::path(a.cases_path).filename().string() << " --days-scale "
       << fmt(a.days_scale) << " --min-days " << a.min_days << " --response-frequencies " << a.response_frequencies;
  for (const auto& f : a.filters) note << " --filter " << f;
  if (a.max_cases > 0) note << " --max-cases " << a.max_cases;
  if (a.no_second_order) note << " --no-second-order-forces";
  if (a.no_wave_damping) note << " --no-wave-surge-damping";
  if (a.thesis_towline_fit) note << " --thesis-towline-fit";
  if (a.tow_drift_at_tow) note << " --tow-drift-at-tow";
  if (a.added_resistance_aft_of_beam) note << " --added-resistance-aft-of-beam";
  if (a.signed_drift) note << " --signed-drift";
  if (a.linear_non_surge_tension) note << " --linear-non-surge-tension";
  if (a.non_surge_stiffness != "a10") note << " --non-surge-stiffness " << a.non_surge_stiffness;
  if (a.nonnegative_wave_damping) note << " --nonnegative-wave-damping";
  if (a.encounter_cutoff_rad_s != simulation::kEncounterCutoff_rad_s) {
    note << " --encounter-cutoff-rad-s " << fmt(a.encounter_cutoff_rad_s);
  }
  if (a.no_surge_diffraction) note << " --no-surge-diffraction";
  note << "`. Simulated days per case = max(" << a.min_days << ", round(" << fmt(a.days_scale)
       << " x thesis days)); seed = thesis case number. Sum of case run times " << fmt(case_time_s, 0)
       << " s (this invocation: " << fmt(wall_s, 0) << " s wall, " << reused << " cases reused from the journal).";
  return note.str();
}

// The summary table on stdout against the targets.
// `not_ok` names the cases without a value ("failed"; "refused" for a database's answers).
void print_summary(const validation::Report& report, std::size_t cases, const fs::path& report_path,
                   const char* not_ok = "failed") {
  const auto& v = report.valid;
  std::cout << "Validation against thesis Appendix C: " << cases << " cases, " << report.failed << " " << not_ok
            << "\n\n";
  TextTable t({"cases <= 300 kips", "value", "target"});
  t.add_row({"count", std::to_string(v.count), ""});
  t.add_row({"median ratio (ours / thesis)", fmt(v.median_ratio, 3),
             std::string("0.80 - 1.25 ") + (report.median_ok ? "met" : "MISSED")});
  t.add_row({"Spearman rank correlation", fmt(v.spearman, 3),
             std::string(">= 0.80 ") + (report.spearman_ok ? "met" : "MISSED")});
  t.add_row({"within a factor 1.5", fmt(100.0 * v.within_1_5, 0) + " %",
             std::string(">= 70 % ") + (report.within_ok ? "met" : "MISSED")});
  t.add_row({"within a factor 2", fmt(100.0 * v.within_2, 0) + " %", ""});
  t.add_row({"cases > 300 kips: median ratio",
             report.above_limit.count > 0 ? fmt(report.above_limit.median_ratio, 3) : "-",
             std::to_string(report.above_limit.count) + " cases"});
  t.print(std::cout);
  std::cout << "\nreport: " << report_path.string() << "\n";
}

// report.md (with the run's `note`) and, unless `no_plot`, scatter.png in `out`: what
// a simulation run and a database's answers both write; returns the report.
validation::Report write_report_and_plot(const fs::path& out, const std::vector<validation::CaseOutcome>& outcomes,
                                         const std::string& note, bool no_plot) {
  validation::Report report = validation::make_report(outcomes);
  write_atomically(out / "report.md", validation::report_markdown(report, note));
  if (!no_plot) {
    try {
      write_scatter_plot(out / "scatter.png", outcomes);
    } catch (const std::exception& e) {
      std::cerr << "validate: warning: no plot: " << e.what() << "\n";
    }
  }
  return report;
}

int run_validate(const Context& ctx, const ValidateArgs& a) {
  check_output_dir("--out", a.out_dir);
  const io::ShipCatalog catalog = load_catalog(ctx);
  const std::vector<sweep::CalibrationRow> rows =
      select_rows(sweep::parse_calibration_csv(read_text(a.cases_path, "--cases"), a.cases_path, catalog), a);
  const validation::RunOptions options = run_options(a);

  const fs::path out(a.out_dir);
  fs::create_directories(out);
  const fs::path journal = out / "cases.csv";
  const std::vector<validation::CaseOutcome> done = resume_journal(out, run_signature(options, catalog), a.fresh);
  std::ofstream append(journal, std::ios::app);

  const int reused = count_reused(rows, done, options);
  const ProgressLine progress(true);
  std::cerr << "validate: " << rows.size() << " cases (" << reused << " from " << journal.string()
            << "), days scale " << fmt(a.days_scale) << ", " << a.threads << " thread(s)\n";
  const auto start = std::chrono::steady_clock::now();
  int computed = 0;
  const int to_compute = static_cast<int>(rows.size()) - reused;
  const auto on_outcome = [&](const validation::CaseOutcome& c, int finished, int total) {
    append << validation::journal_line(c) << "\n" << std::flush;
    ++computed;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double eta = elapsed * (to_compute - computed) / computed;
    report_case(c, finished, total, elapsed, eta, progress);
  };
  std::vector<validation::CaseOutcome> outcomes = validation::run_all(rows, catalog, options, done, on_outcome);
  append.close();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_final_journal(journal, rows, outcomes, done);

  const validation::Report report =
      write_report_and_plot(out, outcomes, run_note(a, outcomes, wall_s, reused), a.no_plot);
  print_summary(report, outcomes.size(), out / "report.md");
  return report.failed == static_cast<int>(outcomes.size()) ? 1 : 0;
}

// One calibration case asked of the database as a planner would: the thesis's
// tug, tow, line, length, speed, wind, heading and mean tension; no
// extrapolation. A refusal is a failed outcome whose error is the refusal.
validation::CaseOutcome ask_database(query::Database& db, const sweep::CalibrationRow& row) {
  validation::CaseOutcome c;
  c.row = row;
  query::QueryRequest rq;
  rq.tug = row.tug;
  rq.tow = row.tow;
  rq.line = row.line;
  rq.values.speed_kt = row.speed_kt;
  rq.values.wind_kt = row.wind_kt;
  rq.values.heading_deg = row.heading_deg;
  rq.values.length_ft = row.length_ft;
  rq.values.mean_tension_lbf = row.mean_tension_lbf;
  const auto start = std::chrono::steady_clock::now();
  try {
    const query::QueryResult r = db.query(rq);
    c.status = validation::CaseStatus::kOk;
    c.ours_kips = r.values.dynamic_999_kips;
    c.ci_low_kips = r.values.ci_low_kips;
    c.ci_high_kips = r.values.ci_high_kips;
    c.slack_fraction = r.values.slack_fraction;
    c.above_breaking = r.values.extreme_tension_lbf > r.values.breaking_strength_lbf;
  } catch (const query::QueryError& e) {
    if (!e.is_input()) throw;
    c.status = validation::CaseStatus::kFailed;
    c.error = std::string("refused: ") + e.what();
  }
  c.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

// What the refusals name first ("mean_tension_lbf = ..." -> mean_tension_lbf), counted.
std::map<std::string, int> refusals_by_field(const std::vector<validation::CaseOutcome>& outcomes) {
  std::map<std::string, int> out;
  for (const auto& c : outcomes) {
    if (c.status == validation::CaseStatus::kOk) continue;
    const std::size_t colon = c.error.find(": ");
    const std::string text = colon == std::string::npos ? c.error : c.error.substr(colon + 2);
    const std::size_t eq = text.find(" = ");
    ++out[eq == std::string::npos || eq > 40 ? std::string("other") : text.substr(0, eq)];
  }
  return out;
}

int run_validate_database(const Context& ctx, const ValidateArgs& a) {
  check_output_dir("--out", a.out_dir);
  const io::ShipCatalog catalog = load_catalog(ctx);
  const std::vector<sweep::CalibrationRow> rows =
      select_rows(sweep::parse_calibration_csv(read_text(a.cases_path, "--cases"), a.cases_path, catalog), a);
  const std::unique_ptr<query::Database> db = open_query_database("--database", a.database);
  const fs::path out(a.out_dir);
  if (fs::exists(out / "run-signature.txt")) {  // never overwrite the resume state of a simulation run
    throw InputError("--out = " + a.out_dir + ": holds a simulation run's journal (run-signature.txt, cases.csv); " +
                     "give --database answers another directory");
  }
  std::vector<validation::CaseOutcome> outcomes;
  for (const auto& row : rows) outcomes.push_back(ask_database(*db, row));

  fs::create_directories(out);
  std::string journal = validation::journal_header() + "\n";
  for (const auto& c : outcomes) journal += validation::journal_line(c) + "\n";
  write_atomically(out / "cases.csv", journal);

  int answered = 0;
  for (const auto& c : outcomes) answered += c.status == validation::CaseStatus::kOk ? 1 : 0;
  std::ostringstream note;
  note << "Answers of the database `" << fs::path(a.database).filename().string()
       << "` (`towdb validate --database`): each case asked through the query library at the thesis's inputs, "
          "its mean tension given, without extrapolation; nothing simulated. "
       << answered << " of " << outcomes.size() << " cases answered";
  const std::map<std::string, int> refused = refusals_by_field(outcomes);
  if (!refused.empty()) {
    note << "; refused, by the input named first:";
    for (const auto& [field, n] : refused) note << " " << field << " " << n;
  }
  note << " (a refused case is listed among the failures below).";
  const validation::Report report = write_report_and_plot(out, outcomes, note.str(), a.no_plot);
  std::cout << "Database " << a.database << ": " << answered << " of " << outcomes.size()
            << " thesis cases answered\n";
  print_summary(report, outcomes.size(), out / "report.md", "refused");
  return answered == 0 ? 1 : 0;
}

}  // namespace

void add_validate_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<ValidateArgs>();
  CLI::App* c = app.add_subcommand("validate", "Run the thesis calibration cases and compare with the thesis database");
  c->add_option("--cases", a->cases_path,
                "Calibration CSV (case,tug,tow,speed_kt,wind_kt,heading_deg,length_ft,line,mean_lbf,days,dyn_kips)")
      ->required();
  c->add_option("--out", a->out_dir, "Output directory: cases.csv (also the resume state), report.md, scatter.png")
      ->required();
  c->add_option("--threads", a->threads, "Cases run in parallel (default 1; 0 = all cores)")
      ->check(CLI::Range(0, 1024));
  c->add_option("--days-scale", a->days_scale, "Simulated days = this x the thesis's days (default 1)")
      ->check(number_in(1e-4, 10.0));
  c->add_option("--min-days", a->min_days, "At least this many simulated days per case (default 20; >= 10)")
      ->check(CLI::Range(10, 1000000));
  c->add_option("--max-cases", a->max_cases, "Run only the first N selected cases")->check(CLI::Range(1, 1000000));
  c->add_option("--response-frequencies", a->response_frequencies,
                "Frequencies of the transfer-function grid (default 48)")
      ->check(CLI::Range(8, 400));
  c->add_option("--filter", a->filters,
                "KEY=VALUE, repeatable (all must match): tug, tow, line (w|f), heading, wind, speed, case");
  c->add_flag("--fresh", a->fresh, "Ignore an existing cases.csv in --out (recompute every case)");
  c->add_flag("--no-plot", a->no_plot, "Do not write scatter.png");
  c->add_flag("--no-second-order-forces", a->no_second_order,
              "Diagnostic: leave out the slowly varying (Newman) surge forces");
  c->add_flag("--no-wave-surge-damping", a->no_wave_damping, "Diagnostic: leave out the wave-induced surge damping");
  c->add_flag("--thesis-towline-fit", a->thesis_towline_fit,
              "Diagnostic: fit the towline polynomial as the thesis did (a10 fitted, unweighted), not EQ-TOWLINE-16");
  c->add_flag("--tow-drift-at-tow", a->tow_drift_at_tow,
              "Diagnostic: the tow's slowly varying force from the wave envelope at the tow (not the thesis's shared one)");
  c->add_flag("--added-resistance-aft-of-beam", a->added_resistance_aft_of_beam,
              "Diagnostic: Gerritsma-Beukelman added resistance aft of beam too (EQ-AR-4 sets it to 0 there)");
  c->add_flag("--signed-drift", a->signed_drift,
              "Diagnostic: keep the sign of the drift coefficient in Newman's force (a thrust where R_aw < 0)");
  c->add_flag("--linear-non-surge-tension", a->linear_non_surge_tension,
              "Diagnostic: the non-surge extension as a linear tension added to the polynomial's surge tension "
              "(EQ-SURGE-6)");
  c->add_option("--non-surge-stiffness", a->non_surge_stiffness,
                 "Diagnostic, with --linear-non-surge-tension: a10 (the polynomial's linear terms), "
                 "equivalent-non-surge or equivalent-total (Gaussian equivalent linearisation, EQ-SURGE-7)")
      ->check(CLI::IsMember({"a10", "equivalent-non-surge", "equivalent-total"}))
      ->needs("--linear-non-surge-tension");
  c->add_flag("--nonnegative-wave-damping", a->nonnegative_wave_damping,
              "Diagnostic: hold each vessel's wave-induced surge damping at >= 0");
  c->add_option("--encounter-cutoff-rad-s", a->encounter_cutoff_rad_s,
                "Diagnostic: encounter-frequency cutoff of the forcing records (default 3; the thesis's 5D grid "
                "ends at 2)")
      ->check(number_in(1.0, simulation::kEncounterCutoff_rad_s));
  c->add_flag("--no-surge-diffraction", a->no_surge_diffraction,
              "Diagnostic: leave out the surge diffraction force (A11 / rho V)(w_e / w) x Froude-Krylov "
              "(EQ-STRIP-7; the 0.3.0 chain)");
  CLI::Option* database = c->add_option(
      "--database", a->database,
      "Ask each case of a towdb database (query library, the thesis's inputs) instead of simulating it");
  for (const char* simulation_only :
       {"--threads", "--days-scale", "--min-days", "--response-frequencies", "--fresh", "--no-second-order-forces",
        "--no-wave-surge-damping", "--thesis-towline-fit", "--tow-drift-at-tow", "--added-resistance-aft-of-beam",
        "--signed-drift", "--linear-non-surge-tension", "--non-surge-stiffness", "--nonnegative-wave-damping",
        "--encounter-cutoff-rad-s", "--no-surge-diffraction"}) {
    database->excludes(c->get_option(simulation_only));
  }
  c->callback([&ctx, a] {
    ctx.action = [&ctx, a] { return a->database.empty() ? run_validate(ctx, *a) : run_validate_database(ctx, *a); };
  });
}

}  // namespace towdb::cli
