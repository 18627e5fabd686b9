// towdb build | status | sweep calibration: the database generator.
//   build   computes every case of a sweep file into a database (parallel,
//           resumable, incremental; generator/sweep/build/build.hpp)
//   status  summarises a database (builds, cases by status, failures)
//   sweep calibration  writes the Appendix C calibration sweep from its CSV
#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "database_basis.hpp"
#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "output.hpp"
#include "sweep/spec/calibration.hpp"
#include "sweep/build/numerics.hpp"
#include "sweep/build/simulation_runner.hpp"
#include "sweep/sweep.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;

// Set by SIGINT/SIGTERM: stop starting cases, finish the running ones.
std::atomic<bool> g_stop{false};

extern "C" void on_stop_signal(int signal_number) {
  g_stop.store(true);
  std::signal(signal_number, SIG_DFL);  // a second signal ends the process at once
}

struct BuildArgs {
  std::string sweep;
  std::string db;
  int threads = 0;
  bool dry_run = false;
  bool resume = false;
  bool retry_failed = false;
  bool json = false;
};

std::string command_line(const Context& ctx, const BuildArgs& a) {
  std::string c = "towdb";
  if (!ctx.ships_dir.empty()) c += " --ships-dir " + shell_word(ctx.ships_dir);
  c += " build --sweep " + shell_word(a.sweep) + " --db " + shell_word(a.db);
  if (a.threads > 0) c += " --threads " + std::to_string(a.threads);
  if (a.resume) c += " --resume";
  if (a.retry_failed) c += " --retry-failed";
  return c;
}

std::string line_name(model::LineKind k) { return model::to_string(k); }

ordered_json case_json(const sweep::PlannedCase& p) {
  const sweep::CaseSpec& s = p.spec;
  ordered_json j;
  j["sweep_label"] = s.sweep_label;
  j["tug"] = s.tug;
  j["tow"] = s.tow;
  j["speed_kt"] = s.speed_kt;
  j["nominal_speed_kt"] = s.nominal_speed_kt;
  if (s.calculated_mean_tension_lbf) j["calculated_mean_tension_lbf"] = *s.calculated_mean_tension_lbf;
  j["spectrum"] = s.sea.spectrum_text();
  if (s.sea.wind_kt) j["wind_kt"] = *s.sea.wind_kt;
  if (s.sea.hs_ft) j["hs_ft"] = *s.sea.hs_ft;
  if (s.sea.tp_s) j["tp_s"] = *s.sea.tp_s;
  if (s.sea.gamma) j["gamma"] = *s.sea.gamma;
  if (s.sea.swell) {
    j["swell_hs_ft"] = s.sea.swell->hs_ft;
    j["swell_tp_s"] = s.sea.swell->tp_s;
    j["swell_heading_deg"] = s.sea.swell->heading_deg;
  }
  j["heading_deg"] = s.heading_deg;
  j["line"] = line_name(s.line);
  j["length_ft"] = s.length_ft;
  j["mean_tension_lbf"] = s.mean_tension_lbf;
  j["mean_tension_label"] = s.mean_tension_label;
  j["days"] = s.days;
  j["seed"] = s.seed;
  j["case_key"] = p.keys.case_key;
  j["state"] = sweep::to_string(p.state);
  j["rekey"] = p.rekey;
  return j;
}

int run_dry(const Context& ctx, const BuildArgs& a, const sweep::SweepFile& file, const sweep::SweepExpansion& exp,
            const io::ShipCatalog& catalog) {
  (void)ctx;
  std::optional<std::filesystem::path> db;
  if (!a.db.empty()) db = a.db;
  const std::vector<sweep::PlannedCase> plan = sweep::plan_build(db, exp.cases, catalog, kVersion);
  std::map<std::string, int> by_state;
  int to_compute = 0, rekey = 0;
  for (const auto& p : plan) {
    ++by_state[sweep::to_string(p.state)];
    if (sweep::computes(p.state, false)) ++to_compute;
    rekey += p.rekey ? 1 : 0;
  }
  // Whether a build here would be refused for computing with another machine
  // kind's numerics than the database's (sweep/build/numerics.hpp).
  const std::optional<std::string> recorded = db ? sweep::recorded_numerics_fingerprint(*db) : std::nullopt;
  const std::string here = sweep::numerics_fingerprint();
  const bool numerics_refusal = recorded && *recorded != here && to_compute > 0;
  if (a.json) {
    ordered_json j;
    j["sweep_file"] = file.path;
    j["cases"] = plan.size();
    j["to_compute"] = to_compute;
    j["to_rekey"] = rekey;
    j["by_state"] = by_state;
    j["numerics_fingerprint"] = {{"database", recorded ? ordered_json(*recorded) : ordered_json(nullptr)},
                                 {"this_machine", here},
                                 {"build_refused", numerics_refusal}};
    j["case_list"] = ordered_json::array();
    for (const auto& p : plan) j["case_list"].push_back(case_json(p));
    j["skipped_conditions"] = ordered_json::array();
    for (const auto& s : exp.skipped) {
      j["skipped_conditions"].push_back({{"sweep_label", s.sweep_label}, {"tug", s.tug}, {"tow", s.tow},
                                         {"nominal_speed_kt", s.nominal_speed_kt}, {"sea", s.sea},
                                         {"heading_deg", s.heading_deg},
                                         {"reason", s.reason}});
    }
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  TextTable t({"#", "label", "tug", "tow", "kt", "sea", "heading deg", "line", "length ft", "mean lbf",
               "tension label", "days", "state"});
  int n = 0;
  for (const auto& p : plan) {
    const sweep::CaseSpec& s = p.spec;
    std::string speed = fmt(s.speed_kt);
    if (s.speed_kt != s.nominal_speed_kt) speed += " (" + fmt(s.nominal_speed_kt) + ")";
    t.add_row({std::to_string(++n), s.sweep_label, s.tug, s.tow, speed, sweep::sea_text(s.sea), fmt(s.heading_deg),
               line_name(s.line), fmt(s.length_ft), fmt_grouped(s.mean_tension_lbf), s.mean_tension_label,
               std::to_string(s.days), std::string(sweep::to_string(p.state)) + (p.rekey ? " (re-key)" : "")});
  }
  t.print(std::cout);
  for (const auto& s : exp.skipped) {
    std::cout << "skipped: " << s.sweep_label << " " << s.tug << " / " << s.tow << " at " << fmt(s.nominal_speed_kt)
              << " kt, " << s.sea << ", heading " << fmt(s.heading_deg) << " deg: " << s.reason << "\n";
  }
  std::cout << plan.size() << " cases (" << to_compute << " to compute";
  for (const auto& [state, count] : by_state) std::cout << ", " << count << " " << state;
  if (rekey > 0) std::cout << "; " << rekey << " of them to re-key";
  std::cout << "); " << exp.skipped.size() << " conditions skipped\n";
  if (numerics_refusal) {
    std::cout << "note: " << db->string() << " records numerics fingerprint " << *recorded
              << "; this machine computes with " << here
              << ": a build here would be refused (run it on the machine kind that made the database, or into a "
                 "new database)\n";
  }
  return 0;
}

// The physics options of a database build are build_case_options()
// (database_basis.hpp): the case options of the runner registered in main().

sweep::ExpandOptions expand_options() {
  sweep::ExpandOptions e;
  e.sea_resistance = sweep::strip_theory_sea_resistance(build_case_options());
  return e;
}

int run_build_command(const Context& ctx, const BuildArgs& a) {
  if (a.json && !a.dry_run) throw InputError("build --json: only with --dry-run (a build reports progress as text)");
  const sweep::SweepFile file = sweep::load_sweep(a.sweep);
  const io::ShipCatalog catalog = load_catalog(ctx);
  const sweep::SweepExpansion exp = sweep::expand_sweep(file, catalog, expand_options());
  if (a.dry_run) return run_dry(ctx, a, file, exp, catalog);
  if (a.db.empty()) throw InputError("build: --db FILE is required (except with --dry-run)");
  const sweep::CaseRunner* runner = sweep::default_case_runner();
  if (!runner) {
    // main() registers the simulation chain before parsing: a towdb without it is built wrong.
    throw Error("build: no case runner is registered (sweep::set_default_case_runner); nothing was written");
  }
  sweep::distributed::Session session;
  sweep::BuildOptions o;
  o.threads = a.threads > 0 ? a.threads : max_threads();
  o.resume = a.resume;
  o.retry_failed = a.retry_failed;
  o.command_line = command_line(ctx, a);
  o.stop = &g_stop;
  o.session = &session;
  o.coverage_notes = exp.notes;
  o.skipped = exp.skipped;
  o.lowest_elevation_m = sweep::static_lowest_elevation(build_case_options());
  o.heading_profile = sweep::linear_heading_profile(build_case_options());
  o.speed_profile = sweep::linear_speed_profile(build_case_options());
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  const sweep::BuildSummary s = sweep::run_build(a.db, file, exp.cases, catalog, *runner, o);
  if (s.worker) return 0;
  for (const auto& f : s.failures) std::cerr << "towdb: case failed: " << f << "\n";
  for (const auto& f : s.profiles.failures) std::cerr << "towdb: heading profile failed: " << f << "\n";
  for (const auto& f : s.speed_profiles.failures) std::cerr << "towdb: speed profile failed: " << f << "\n";
  for (const auto& k : exp.skipped) {
    std::cerr << "towdb: condition skipped: " << k.sweep_label << " " << k.tug << " / " << k.tow << " at "
              << fmt(k.nominal_speed_kt) << " kt, " << k.sea << ", heading " << fmt(k.heading_deg)
              << " deg: " << k.reason << "\n";
  }
  std::cout << "build " << s.build_id << ": " << s.total << " cases; " << s.up_to_date << " up to date, "
            << s.scheduled << " scheduled, " << s.done << " done, " << s.failed << " failed";
  if (s.previously_failed > 0) std::cout << ", " << s.previously_failed << " failed earlier (--retry-failed)";
  if (s.lowest_points_filled > 0) {
    std::cout << "; the catenary's lowest point added to " << s.lowest_points_filled << " towline fits";
  }
  if (s.slack_snatch_dropped > 0) {
    std::cout << "; the per-day slack and snatch records of " << s.slack_snatch_dropped
              << " cases dropped (day_records = \"maxima\")";
  }
  if (s.maxima_repacked > 0) {
    std::cout << "; the daily maxima of " << s.maxima_repacked << " cases repacked as binary16 (maxima_precision)";
  }
  if (s.rekeyed > 0) {
    std::cout << "; " << s.rekeyed << " stored cases re-keyed (their ship or towline files changed in comments or "
                 "layout only)";
  }
  if (s.profiles.lines > 0) {
    std::cout << "; heading profiles: " << s.profiles.lines << " lines, " << s.profiles.up_to_date << " up to date, "
              << s.profiles.computed << " computed, " << s.profiles.failed << " failed";
  }
  if (s.speed_profiles.lines > 0) {
    std::cout << "; speed profiles: " << s.speed_profiles.lines << " lines, " << s.speed_profiles.up_to_date
              << " up to date, " << s.speed_profiles.computed << " computed, " << s.speed_profiles.failed << " failed";
  }
  std::cout << (s.interrupted ? "; interrupted (run again with the same command to continue)" : "") << "\n";
  return (s.failed > 0 || s.profiles.failed > 0 || s.speed_profiles.failed > 0 || s.interrupted) ? 1 : 0;
}

// meta.last_audit as JSON (null when the database was never audited).
ordered_json last_audit_json(const sweep::StatusReport& r) {
  if (!r.last_audit) return nullptr;
  ordered_json j = ordered_json::parse(*r.last_audit, nullptr, false);
  return j.is_discarded() ? ordered_json(*r.last_audit) : j;  // not JSON: shown as the stored text
}

std::string percent_or_dash(const ordered_json& v) { return v.is_number() ? fmt(100.0 * v.get<double>(), 1) + " %" : "-"; }

// Whether the last audit measured what the database holds now: the audit records the newest
// build that had computed a stored case or profile (content_build_id); a later build that
// computed more makes the audit describe a database that no longer exists.
std::string audit_staleness(const ordered_json& audit, const sweep::StatusReport& r) {
  if (!audit.contains("content_build_id")) {
    return "audited content: not recorded (an audit made before towdb recorded it): run towdb audit again";
  }
  const ordered_json& id = audit.at("content_build_id");
  const std::optional<std::int64_t> audited =
      id.is_number_integer() ? std::optional<std::int64_t>(id.get<std::int64_t>()) : std::nullopt;
  const auto name = [](const std::optional<std::int64_t>& b) {
    return b ? "build " + std::to_string(*b) : std::string("no recorded build");
  };
  const std::string cases = std::to_string(audit.value("cases_done", std::int64_t{0})) + " cases done";
  if (audited != r.content_build_id) {
    return "warning: the audit measured the database as of " + name(audited) + " (" + cases + "); " +
           name(r.content_build_id) + " has computed cases or profiles since: run towdb audit again";
  }
  return "audited content: " + name(audited) + " (" + cases + "), the database as it is";
}

// The stored summary of the last `towdb audit`: how far to trust the answers.
void print_last_audit(const sweep::StatusReport& r) {
  const ordered_json a = last_audit_json(r);
  std::cout << "\nlast audit (towdb audit: database answers vs direct simulation): ";
  if (!a.is_object()) {
    std::cout << (r.last_audit ? "unreadable meta.last_audit" : "never audited") << "\n";
    return;
  }
  const ordered_json& d = a.value("dynamic_999", ordered_json::object());
  const ordered_json& c = a.value("uncertainty_covers_error", ordered_json::object());
  std::cout << a.value("utc", std::string("?")) << ", " << a.value("draws", 0) << " questions, "
            << a.value("days", 0) << " days each\n";
  std::cout << audit_staleness(a, r) << "\n";
  TextTable t({"measure", "value"});
  t.add_row({"answered without extrapolation", std::to_string(a.value("answered", 0)) + " of " +
                                                   std::to_string(a.value("draws", 0))});
  t.add_row({"median / 90th pct / worst error (dynamic 0.001/day)",
             percent_or_dash(d.value("median_rel_error", ordered_json())) + " / " +
                 percent_or_dash(d.value("p90_rel_error", ordered_json())) + " / " +
                 percent_or_dash(d.value("max_rel_error", ordered_json()))});
  t.add_row({"printed +/- covers the error", percent_or_dash(c.value("fraction", ordered_json()))});
  t.print(std::cout);
}

int run_status(const std::string& db, bool json) {
  const sweep::StatusReport r = sweep::read_status(db);
  if (json) {
    ordered_json j;
    j["database"] = db;
    j["schema_version"] = r.schema_version;
    j["cases"] = r.cases;
    j["cases_by_status"] = r.cases_by_status;
    j["cases_by_sweep_label"] = r.cases_by_sweep_label;
    j["results"] = r.results;
    j["daily_maxima"] = r.daily_maxima;
    j["towline_fits"] = r.towline_fits;
    j["heading_profiles"] = r.heading_profiles;
    j["cases_with_heading_profile"] = r.cases_with_profile;
    j["speed_profiles"] = r.speed_profiles;
    j["cases_with_speed_profile"] = r.cases_with_speed_profile;
    j["vessels"] = r.vessels;
    if (r.total_runtime_s) j["total_runtime_s"] = *r.total_runtime_s;
    j["builds"] = ordered_json::array();
    for (const auto& b : r.builds) {
      j["builds"].push_back({{"build_id", b.build_id}, {"status", b.status}, {"code_version", b.code_version},
                             {"sweep_file", b.sweep_file}, {"host", b.host}, {"threads", b.threads},
                             {"mpi_ranks", b.mpi_ranks}, {"started_utc", b.started_utc},
                             {"finished_utc", b.finished_utc}, {"cases_done", b.cases_done},
                             {"cases_failed", b.cases_failed}});
    }
    j["failed_cases"] = ordered_json::array();
    for (const auto& f : r.failed) {
      j["failed_cases"].push_back({{"case_id", f.case_id}, {"sweep_label", f.sweep_label}, {"tug", f.tug},
                                   {"tow", f.tow}, {"error_message", f.error_message}});
    }
    j["content_build_id"] = r.content_build_id ? ordered_json(*r.content_build_id) : ordered_json();
    j["last_audit"] = last_audit_json(r);
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << db << ": towdb database, schema version " << r.schema_version << "\n"
            << "cases: " << r.cases;
  for (const auto& [status, n] : r.cases_by_status) std::cout << ", " << n << " " << status;
  std::cout << "\nresults: " << r.results << ", daily maxima: " << r.daily_maxima
            << ", towline fits: " << r.towline_fits << ", vessels: " << r.vessels
            << "\nheading profiles (query EQ-QUERY-11): " << r.heading_profiles << ", used by " << r.cases_with_profile
            << " cases\nspeed profiles (query EQ-QUERY-12): " << r.speed_profiles << ", used by "
            << r.cases_with_speed_profile << " cases";
  if (r.total_runtime_s) std::cout << ", computing time: " << fmt(*r.total_runtime_s / 3600.0, 2) << " h";
  std::cout << "\n\nsweep labels\n";
  TextTable labels({"sweep label", "cases"});
  for (const auto& [label, n] : r.cases_by_sweep_label) labels.add_row({label, std::to_string(n)});
  labels.print(std::cout);
  std::cout << "\nbuilds (newest first)\n";
  TextTable builds({"build", "status", "started (UTC)", "finished (UTC)", "threads", "ranks", "done", "failed",
                    "version", "sweep"});
  for (const auto& b : r.builds) {
    builds.add_row({std::to_string(b.build_id), b.status, b.started_utc, b.finished_utc, std::to_string(b.threads),
                    std::to_string(b.mpi_ranks), std::to_string(b.cases_done), std::to_string(b.cases_failed),
                    b.code_version, b.sweep_file});
  }
  builds.print(std::cout);
  if (!r.failed.empty()) {
    std::cout << "\nfailed cases\n";
    TextTable failed({"case", "label", "tug", "tow", "reason"});
    for (const auto& f : r.failed) {
      failed.add_row({std::to_string(f.case_id), f.sweep_label, f.tug, f.tow, f.error_message});
    }
    failed.print(std::cout);
  }
  print_last_audit(r);
  return 0;
}

int run_calibration(const Context& ctx, const std::string& csv, const std::string& out) {
  if (!out.empty()) check_output_file("--out", out);
  if (std::filesystem::is_directory(csv)) throw InputError("--csv " + csv + ": is a directory, expected a CSV file");
  std::ifstream in(csv, std::ios::binary);
  if (!in) throw InputError("--csv = " + csv + ": cannot open the CSV file (missing or unreadable)");
  std::ostringstream text;
  text << in.rdbuf();
  const io::ShipCatalog catalog = load_catalog(ctx);
  const auto rows = sweep::parse_calibration_csv(text.str(), csv, catalog);
  const std::string toml = sweep::calibration_sweep_toml(rows, std::filesystem::path(csv).filename().string());
  // The result must read back as a valid sweep whose cases all resolve.
  const sweep::SweepFile check = sweep::parse_sweep(toml, out.empty() ? "<generated>" : out);
  sweep::expand_sweep(check, catalog, expand_options());
  if (out.empty()) {
    std::cout << toml;
  } else {
    std::ofstream os(out, std::ios::binary);
    if (!os) throw InputError("--out = " + out + ": cannot write the sweep file");
    os << toml;
    std::cerr << "wrote " << rows.size() << " cases to " << out << "\n";
  }
  return 0;
}

}  // namespace

void register_case_runner() { sweep::set_default_case_runner(sweep::simulation_case_runner(build_case_options())); }

void add_build_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<BuildArgs>();
  CLI::App* build = app.add_subcommand("build", "Compute every case of a sweep file into a towdb database");
  build->add_option("--sweep", a->sweep, "Sweep file (TOML, docs/sweep-files.md)")->required();
  build->add_option("--db", a->db, "Database file (created if missing; updated incrementally)");
  build->add_option("--threads", a->threads, "OpenMP threads computing cases (default: all cores)")
      ->check(CLI::Range(1, 1024));
  build->add_flag("--dry-run", a->dry_run, "List the cases and their count; write nothing");
  build->add_flag("--resume", a->resume, "Continue after a build that was killed or crashed");
  build->add_flag("--retry-failed", a->retry_failed, "Recompute cases that failed in an earlier build");
  build->add_flag("--json", a->json, "JSON output (with --dry-run)");
  build->callback([&ctx, a] { ctx.action = [&ctx, a] { return run_build_command(ctx, *a); }; });

  struct StatusArgs {
    std::string db;
    bool json = false;
  };
  auto s = std::make_shared<StatusArgs>();
  CLI::App* status = app.add_subcommand("status", "Summarise a towdb database: builds, cases, failures");
  status->add_option("--db", s->db, "Database file")->required();
  status->add_flag("--json", s->json, "JSON output");
  status->callback([&ctx, s] { ctx.action = [s] { return run_status(s->db, s->json); }; });

  struct CalibrationArgs {
    std::string csv;
    std::string out;
  };
  auto c = std::make_shared<CalibrationArgs>();
  CLI::App* sweep_cmd = app.add_subcommand("sweep", "Generate sweep files");
  sweep_cmd->require_subcommand(1);
  CLI::App* calibration = sweep_cmd->add_subcommand(
      "calibration", "Write the sweep of the thesis's Appendix C calibration cases from its CSV");
  calibration->add_option("--csv", c->csv, "appendix_c_calibration.csv")->required();
  calibration->add_option("--out", c->out, "Output sweep file (default: standard output)");
  calibration->callback([&ctx, c] { ctx.action = [&ctx, c] { return run_calibration(ctx, c->csv, c->out); }; });
}

}  // namespace towdb::cli
