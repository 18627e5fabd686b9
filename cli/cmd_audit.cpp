// towdb audit: the database's answers between its stored cases against
// direct simulation (audit.hpp), as a table, JSON and a PNG; the summary is
// stored in the database's meta table (key last_audit, schema/README.md) so
// that `towdb status` shows how far to trust the database.
//
//   towdb audit --db FILE --draws N [--seed S] [--days D] [--threads T]
//               [--json] [--plot FILE.png] [--no-store]
//   towdb audit --db FILE --replay EARLIER.json [--json] [--plot FILE.png]
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <utility>

#include <nlohmann/json.hpp>

#include "audit.hpp"
#include "cli.hpp"
#include "common/error.hpp"
#include "common/version.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "store/database.hpp"
#include "sweep/build/status.hpp"
#include "sweep/build/writer.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;

constexpr int kMaxDraws = 100000;

struct AuditArgs {
  std::string db;
  int draws = 0;
  std::uint64_t seed = 1;
  int days = 0;  // 0: the database's own
  int threads = 0;
  bool json = false;
  bool no_store = false;
  std::string plot;
  std::string replay;  // an earlier audit's --json output
};

ordered_json nullable(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); }

// The questions and simulations of an earlier audit's --json output, read
// strictly: a missing or mistyped field is named with its question.
struct ReplayInput {
  AuditOptions options;
  std::vector<AuditOutcome> outcomes;
};

class ReplayReader {
 public:
  explicit ReplayReader(std::string path) : path_(std::move(path)) {}

  ReplayInput read() const {
    std::ifstream in(path_);
    if (!in) throw InputError("--replay " + path_ + ": cannot read the file");
    const ordered_json j = ordered_json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object())
      throw InputError("--replay " + path_ + ": not a JSON object (expected the output of towdb audit --json)");
    ReplayInput r;
    const ordered_json& summary = field(j, "summary", "");
    r.options.seed = unsigned_field(summary, "seed", "summary.");
    r.options.days = small_int(summary, "days", "summary.");
    const ordered_json& questions = field(j, "questions", "");
    if (!questions.is_array() || questions.empty())
      throw InputError("--replay " + path_ + ": questions: expected a non-empty array of questions");
    for (std::size_t i = 0; i < questions.size(); ++i) r.outcomes.push_back(outcome(questions[i], i));
    r.options.draws = static_cast<int>(r.outcomes.size());
    return r;
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw InputError("--replay " + path_ + ": " + where + ": " + what);
  }
  const ordered_json& field(const ordered_json& o, const std::string& key, const std::string& where) const {
    if (!o.is_object() || !o.contains(key)) fail(where + key, "missing");
    return o.at(key);
  }
  double number(const ordered_json& o, const std::string& key, const std::string& where) const {
    const ordered_json& v = field(o, key, where);
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(where + key, "expected a number, found " + v.dump());
    return v.get<double>();
  }
  std::uint64_t unsigned_field(const ordered_json& o, const std::string& key, const std::string& where) const {
    const ordered_json& v = field(o, key, where);
    if (!v.is_number_unsigned()) fail(where + key, "expected a whole number >= 0, found " + v.dump());
    return v.get<std::uint64_t>();
  }
  int small_int(const ordered_json& o, const std::string& key, const std::string& where) const {
    const std::uint64_t v = unsigned_field(o, key, where);
    if (v > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      fail(where + key, std::to_string(v) + " is too large (at most " +
                            std::to_string(std::numeric_limits<int>::max()) + ")");
    return static_cast<int>(v);
  }
  std::string text(const ordered_json& o, const std::string& key, const std::string& where) const {
    const ordered_json& v = field(o, key, where);
    if (!v.is_string()) fail(where + key, "expected a string, found " + v.dump());
    return v.get<std::string>();
  }
  // A number, or null where the earlier audit had none (NaN).
  double nullable_number(const ordered_json& v, const std::string& where) const {
    if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (!v.is_number()) fail(where, "expected a number or null, found " + v.dump());
    return v.get<double>();
  }

  AuditOutcome outcome(const ordered_json& q, std::size_t i) const {
    const std::string where = "questions[" + std::to_string(i) + "].";
    AuditOutcome o;
    o.q.index = small_int(q, "index", where);
    o.q.tug = text(q, "tug", where);
    o.q.tow = text(q, "tow", where);
    o.q.line = text(q, "line", where);
    if (o.q.line != "wire" && o.q.line != "fiber")
      fail(where + "line", "\"" + o.q.line + "\" is not a line type (wire or fiber)");
    o.q.speed_kt = number(q, "speed_kt", where);
    o.q.wind_kt = number(q, "wind_kt", where);
    o.q.heading_deg = number(q, "heading_deg", where);
    o.q.length_ft = number(q, "length_ft", where);
    o.q.mean_tension_lbf = number(q, "mean_tension_lbf", where);
    o.q.seed = unsigned_field(q, "seed", where);
    const ordered_json& simulated = field(q, "simulated", where);
    if (!simulated.is_boolean()) fail(where + "simulated", "expected true or false, found " + simulated.dump());
    o.simulated = simulated.get<bool>();
    if (q.contains("simulation_error")) o.simulation_error = text(q, "simulation_error", where);
    o.simulated_999_kips = o.simulated_ci_low_kips = o.simulated_ci_high_kips = o.simulated_extreme_lbf =
        std::numeric_limits<double>::quiet_NaN();
    if (!o.simulated) return o;
    o.simulated_999_kips = number(q, "simulated_999_kips", where);
    if (!(o.simulated_999_kips > 0.0))
      fail(where + "simulated_999_kips", "expected a positive tension, found " + format_value(o.simulated_999_kips));
    const ordered_json& ci = field(q, "simulated_ci_kips", where);
    if (!ci.is_array() || ci.size() != 2) fail(where + "simulated_ci_kips", "expected [low, high], found " + ci.dump());
    o.simulated_ci_low_kips = nullable_number(ci[0], where + "simulated_ci_kips[0]");
    o.simulated_ci_high_kips = nullable_number(ci[1], where + "simulated_ci_kips[1]");
    // As the audit computed it: mean + dynamic (1 kip = 1,000 lbf).
    o.simulated_extreme_lbf = o.q.mean_tension_lbf + 1000.0 * o.simulated_999_kips;
    return o;
  }

  std::string path_;
};

// Refused before any work: the summary could not be stored afterwards.
void require_writable(const std::string& db) {
  namespace fs = std::filesystem;
  const fs::path p(db);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (access(p.c_str(), W_OK) != 0 || access(dir.c_str(), W_OK) != 0) {
    throw InputError("--db " + db +
                     ": the database is read-only (the file or its folder cannot be written); the audit stores its "
                     "summary in the database's meta table (key last_audit). Make it writable, or add --no-store to "
                     "audit without storing");
  }
}

ordered_json stats_json(const ErrorStats& s) {
  return {{"samples", s.samples},
          {"median_rel_error", nullable(s.median)},
          {"p90_rel_error", nullable(s.p90)},
          {"max_rel_error", nullable(s.max)},
          {"worst_question", s.worst_index >= 0 ? ordered_json(s.worst_index) : ordered_json(nullptr)}};
}

// The summary: the JSON's "summary" object and the stored meta value.
ordered_json summary_json(const AuditSummary& s, const AuditOptions& o, const std::string& mean_tension_method) {
  ordered_json j;
  j["draws"] = s.draws;
  j["seed"] = o.seed;
  j["days"] = o.days;
  j["mean_tension"] = mean_tension_method;
  j["answered"] = s.answered;
  j["not_answered"] = s.not_answered;
  j["simulation_failed"] = s.simulation_failed;
  j["quantity"] = "dynamic tension exceeded with probability 0.001 in one day (dynamic_999_kips)";
  j["dynamic_999"] = stats_json(s.dynamic_999);
  j["extreme_tension"] = stats_json(s.extreme);
  j["uncertainty_covers_error"] = {{"covered", s.covered}, {"fraction", nullable(s.coverage)}};
  j["extrapolated_dynamic_999"] = stats_json(s.extrapolated_999);
  return j;
}

ordered_json question_json(const AuditOutcome& o) {
  const AuditQuestion& q = o.q;
  ordered_json j;
  j["index"] = q.index;
  j["tug"] = q.tug;
  j["tow"] = q.tow;
  j["line"] = q.line;
  j["speed_kt"] = q.speed_kt;
  j["wind_kt"] = q.wind_kt;
  j["heading_deg"] = q.heading_deg;
  j["length_ft"] = q.length_ft;
  j["mean_tension_lbf"] = q.mean_tension_lbf;
  j["seed"] = q.seed;
  j["answered"] = o.answered;
  if (!o.answered) j["refusal"] = o.refusal;
  j["answer_999_kips"] = o.answered ? nullable(o.answer_999_kips) : ordered_json(nullptr);
  j["uncertainty_kips"] = o.answered ? nullable(o.uncertainty_kips) : ordered_json(nullptr);
  j["extrapolated_999_kips"] = nullable(o.extrapolated_999_kips);
  j["simulated"] = o.simulated;
  if (!o.simulation_error.empty()) j["simulation_error"] = o.simulation_error;
  j["simulated_999_kips"] = nullable(o.simulated_999_kips);
  j["simulated_ci_kips"] = {nullable(o.simulated_ci_low_kips), nullable(o.simulated_ci_high_kips)};
  j["rel_error_999"] = nullable(o.rel_error_999);
  j["rel_error_extreme"] = nullable(o.rel_error_extreme);
  j["rel_error_extrapolated_999"] = nullable(o.rel_error_extrapolated_999);
  j["covered"] = o.answered && o.simulated ? ordered_json(o.covered) : ordered_json(nullptr);
  return j;
}

std::string pct(double v) { return std::isfinite(v) ? fmt(100.0 * v, 1) + " %" : "-"; }
std::string kips_or_dash(double v) { return std::isfinite(v) ? fmt(v, 1) : "-"; }

void print_questions(const std::vector<AuditOutcome>& outcomes) {
  TextTable t({"#", "tug", "tow", "line", "length ft", "speed kt", "wind kt", "heading deg", "mean lbf",
               "database kips", "+/- kips", "simulated kips", "error", "covered", "extrapolated kips", "error"});
  for (const AuditOutcome& o : outcomes) {
    const AuditQuestion& q = o.q;
    t.add_row({std::to_string(q.index), q.tug, q.tow, q.line, fmt(q.length_ft, 0), fmt(q.speed_kt, 2),
               fmt(q.wind_kt, 2), fmt(q.heading_deg, 1), fmt_grouped(q.mean_tension_lbf),
               o.answered ? fmt(o.answer_999_kips, 1) : "refused", o.answered ? fmt(o.uncertainty_kips, 1) : "-",
               o.simulated ? fmt(o.simulated_999_kips, 1) : "failed", pct(o.rel_error_999),
               o.answered && o.simulated ? (o.covered ? "yes" : "no") : "-", kips_or_dash(o.extrapolated_999_kips),
               pct(o.rel_error_extrapolated_999)});
  }
  t.print(std::cout);
}

void print_summary(const AuditSummary& s, const AuditOptions& o, const std::string& mean_text) {
  std::cout << "\n"
            << s.draws << " questions (seed " << o.seed << ", " << o.days
            << " simulated days each; mean tension: " << mean_text << ")\n"
            << "compared: dynamic tension exceeded with probability 0.001 in one day, and the extreme tension "
               "(mean + that)\n\n";
  TextTable t({"measure", "value"});
  t.add_row({"answered without extrapolation", std::to_string(s.answered) + " of " + std::to_string(s.draws)});
  t.add_row({"not answered (refused)", std::to_string(s.not_answered)});
  if (s.simulation_failed > 0) t.add_row({"simulation failed", std::to_string(s.simulation_failed)});
  t.add_row({"median error, dynamic 0.001/day", pct(s.dynamic_999.median)});
  t.add_row({"90th percentile error, dynamic", pct(s.dynamic_999.p90)});
  t.add_row(
      {"worst error, dynamic",
       pct(s.dynamic_999.max) +
           (s.dynamic_999.worst_index >= 0 ? " (question " + std::to_string(s.dynamic_999.worst_index) + ")" : "")});
  t.add_row({"median / 90th pct / worst error, extreme",
             pct(s.extreme.median) + " / " + pct(s.extreme.p90) + " / " + pct(s.extreme.max)});
  t.add_row({"printed +/- covers the error", std::isfinite(s.coverage) ? std::to_string(s.covered) + " of " +
                                                                             std::to_string(s.dynamic_999.samples) +
                                                                             " (" + pct(s.coverage) + ")"
                                                                       : "-"});
  t.add_row({"with --extrapolate: median / 90th / worst",
             pct(s.extrapolated_999.median) + " / " + pct(s.extrapolated_999.p90) + " / " +
                 pct(s.extrapolated_999.max) + " (" + std::to_string(s.extrapolated_999.samples) + " answered)"});
  t.print(std::cout);
}

void print_refusals(const std::vector<AuditOutcome>& outcomes) {
  bool header = false;
  for (const AuditOutcome& o : outcomes) {
    if (o.answered && o.simulation_error.empty()) continue;
    if (!header) std::cout << "\nnot answered or not simulated\n";
    header = true;
    if (!o.answered) std::cout << "  question " << o.q.index << ": refused: " << o.refusal << "\n";
    if (!o.simulation_error.empty())
      std::cout << "  question " << o.q.index << ": simulation failed: " << o.simulation_error << "\n";
  }
}

// Answer against simulation (log-log, with the printed +/-), refused questions
// at their extrapolated answer, and the error distribution.
void write_audit_plot(const std::string& png, const std::vector<AuditOutcome>& outcomes) {
  const auto dir = make_plot_data_dir("towdb-audit");
  std::vector<double> errors;
  {
    std::ofstream a(dir / "answered.dat"), r(dir / "refused.dat");
    for (const AuditOutcome& o : outcomes) {
      if (!o.simulated) continue;
      if (o.answered) {
        a << o.simulated_999_kips << " " << o.answer_999_kips << " " << o.uncertainty_kips << "\n";
        errors.push_back(100.0 * o.rel_error_999);
      } else if (std::isfinite(o.extrapolated_999_kips) && o.extrapolated_999_kips > 0.0) {
        r << o.simulated_999_kips << " " << o.extrapolated_999_kips << "\n";
      }
    }
    a << "\n";
    r << "\n";
    std::sort(errors.begin(), errors.end());
    std::ofstream c(dir / "cdf.dat");
    for (std::size_t i = 0; i < errors.size(); ++i)
      c << errors[i] << " " << (static_cast<double>(i) + 1.0) / static_cast<double>(errors.size()) << "\n";
    c << "\n";
  }
  const std::string d = dir.string();
  // clang-format off
  const std::string script =
      "set terminal pngcairo size 1400,560 font 'sans,11'\n"
      "set output '" + png + "'\n"
      "set multiplot layout 1,2\n"
      "set title 'Database answer vs direct simulation (dynamic tension, 0.001/day)'\n"
      "set xlabel 'simulated (kips)'\nset ylabel 'database (kips)'\nset grid\nset logscale xy\nset key top left\n"
      "plot x title 'equal' lw 1 lc 'gray', '" + d + "/answered.dat' using 1:2:3 with yerrorbars pt 7 "
      "title 'answered, +/- printed', '" + d + "/refused.dat' using 1:2 with points pt 6 "
      "title 'refused: extrapolated answer'\n"
      "unset logscale\nset title 'Relative error of the answered questions'\n"
      "set xlabel 'relative error (%)'\nset ylabel 'fraction of answered questions'\nset yrange [0:1]\n"
      "plot '" + d + "/cdf.dat' using 1:2 with steps lw 2 title 'empirical distribution'\n"
      "unset multiplot\n";
  // clang-format on
  run_gnuplot_with_data(script, dir);
}

// True when the SQLite file is in WAL mode: header bytes 18 and 19 (file
// format write and read versions) are 2 for WAL, 1 for a rollback journal
// (sqlite.org/fileformat2.html, "The Database Header").
bool file_in_wal_mode(const std::string& db_path) {
  std::ifstream in(db_path, std::ios::binary);
  char header[20] = {};
  in.read(header, sizeof header);
  return in && header[18] == 2;
}

// One transaction: the summary is stored whole or not at all. Writing opens
// the file in WAL mode (store::Database); a file that used a rollback journal
// (a database shipped in a repository) is put back into it, so the audit
// changes only meta.last_audit.
void store_summary(const std::string& db_path, const ordered_json& summary) {
  const bool was_wal = file_in_wal_mode(db_path);
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadWrite);
  db.transaction([&] {
    store::Statement st = db.prepare("INSERT OR REPLACE INTO meta (key, value) VALUES ('last_audit', ?)");
    st.bind(1, summary.dump()).run();
  });
  if (!was_wal) db.exec("PRAGMA journal_mode = DELETE");
}

// The output of both a fresh audit and a replay.
void report(const AuditArgs& a, const std::vector<AuditOutcome>& outcomes, const AuditSummary& s,
            const AuditOptions& o, const ordered_json& summary, const ordered_json& basis_json_value,
            const std::string& mean_text) {
  if (!a.plot.empty()) write_audit_plot(a.plot, outcomes);
  if (a.json) {
    ordered_json j;
    j["database"] = a.db;
    if (!a.replay.empty()) j["replay_of"] = a.replay;
    j["mean_tension_basis"] = basis_json_value;
    j["summary"] = summary;
    j["questions"] = ordered_json::array();
    for (const AuditOutcome& x : outcomes) j["questions"].push_back(question_json(x));
    std::cout << j.dump(2) << "\n";
    return;
  }
  print_questions(outcomes);
  print_refusals(outcomes);
  print_summary(s, o, mean_text);
}

// Replay (audit.hpp): the earlier audit's questions and simulations, this
// database's answers. Nothing is stored: the stored summary describes a
// database against its own chain's simulations.
int run_replay_command(const AuditArgs& a) {
  ReplayInput in = ReplayReader(a.replay).read();
  replay_audit(a.db, &in.outcomes);
  const AuditSummary s = summarise(in.outcomes);
  ordered_json summary = summary_json(s, in.options, "replayed");
  const std::string text = "as in " + a.replay + " (its questions and " + std::to_string(in.options.days) +
                           "-day simulations, answered again from " + a.db + ")";
  report(a, in.outcomes, s, in.options, summary, ordered_json({{"replay_of", a.replay}}), text);
  if (!a.json) std::cout << "replay: nothing simulated, nothing stored\n";
  return 0;
}

int run_audit_command(const Context& ctx, const AuditArgs& a) {
  if (!std::filesystem::is_regular_file(a.db)) throw InputError("--db " + a.db + ": no such database file");
  if (!a.plot.empty()) check_output_file("--plot", a.plot);
  if (!a.replay.empty()) return run_replay_command(a);
  if (a.draws == 0) throw InputError("--draws is required (1 to 100000), or --replay FILE.json");
  if (!a.no_store) require_writable(a.db);
  const DatabaseSpan span = read_database_span(a.db);
  const io::ShipCatalog catalog = load_catalog(ctx);
  const BasisLookup basis = read_database_basis(a.db, &catalog);
  if (!basis.basis) {
    // Said on stderr in every output mode: such an audit asks other questions than the calculated basis would.
    std::cerr << "towdb audit: warning: the questions' mean tensions are drawn uniformly in the stored span, not at "
                 "the calculated mean tension: "
              << basis.reason << "\n";
  }
  AuditOptions o;
  o.draws = a.draws;
  o.seed = a.seed;
  o.days = a.days > 0 ? a.days : span.days;
  o.threads = a.threads;
  const auto start = std::chrono::steady_clock::now();
  // Ship files edited since the build: the direct simulations use the files, the stored cases did not.
  std::vector<std::string> names;
  for (const GroupSpan& g : span.groups) {
    for (const std::string& n : {g.tug, g.tow}) {
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
    }
  }
  const std::vector<std::string> changed_ships = vessels_changed_since_build(a.db, catalog, names);
  if (!changed_ships.empty()) {
    std::string list;
    for (const std::string& n : changed_ships) list += (list.empty() ? "" : ", ") + n;
    std::cerr << "towdb audit: warning: the ship files of " << list
              << " are not the ones the database was built with: the direct simulations use the files as they are "
                 "now, so the errors include the change\n";
  }
  // What the audit measures: the stored content as of this build (towdb status compares it).
  const sweep::StatusReport content = sweep::read_status(a.db, 1, 0);
  const std::vector<AuditQuestion> questions = draw_questions(span, basis.basis, catalog, a.db, o);
  const std::vector<AuditOutcome> outcomes = run_audit(a.db, catalog, questions, o);
  const AuditSummary s = summarise(outcomes);
  const double runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string method = basis.basis ? "calculated" : "uniform_in_stored_span";
  const std::string mean_text = basis.basis ? "calculated, " + basis_text(*basis.basis)
                                            : "uniform in the stored span (no calculated basis: " + basis.reason + ")";
  ordered_json summary = summary_json(s, o, method);
  summary["ship_files_changed_since_build"] = changed_ships;
  summary["content_build_id"] = content.content_build_id ? ordered_json(*content.content_build_id) : ordered_json();
  summary["cases_done"] = content.cases_by_status.at("done");
  report(a, outcomes, s, o, summary,
         basis.basis ? basis_json(*basis.basis) : ordered_json({{"reason", basis.reason}}), mean_text);
  if (!a.json) std::cout << "run time " << fmt(runtime_s, 1) << " s\n";
  if (a.no_store) return 0;
  summary["utc"] = sweep::utc_now();
  summary["code_version"] = kVersion;
  store_summary(a.db, summary);
  if (!a.json) std::cout << "summary stored in " << a.db << " (meta key last_audit; shown by towdb status)\n";
  return 0;
}

}  // namespace

void add_audit_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<AuditArgs>();
  CLI::App* c = app.add_subcommand(
      "audit", "Answer random in-range questions from a database and by direct simulation; report the errors");
  c->add_option("--db", a->db, "Database file (its meta table receives the summary)")->required();
  CLI::Option* draws =
      c->add_option("--draws", a->draws, "Number of random questions")->check(CLI::Range(1, kMaxDraws));
  CLI::Option* seed =
      c->add_option("--seed", a->seed, "Seed of the draws and simulations (default 1)")->check(unsigned_integer());
  CLI::Option* days =
      c->add_option("--days", a->days, "Simulated days per question (default: the days of the database's cases)")
          ->check(CLI::Range(3, 1000000));
  c->add_option("--threads", a->threads, "Threads simulating questions (default: all cores); no effect on results")
      ->check(CLI::Range(0, 1024));
  c->add_flag("--json", a->json, "JSON output");
  c->add_option("--plot", a->plot, "Write a PNG: answers vs simulation, and the error distribution");
  c->add_flag("--no-store", a->no_store, "Do not store the summary in the database (e.g. a read-only file)");
  c->add_option("--replay", a->replay,
                "An earlier audit's --json output: its questions answered again from --db, against its "
                "simulations (nothing simulated or stored)")
      ->excludes(draws)
      ->excludes(seed)
      ->excludes(days)
      ->check(CLI::ExistingFile);
  c->callback([&ctx, a] { ctx.action = [&ctx, a] { return run_audit_command(ctx, *a); }; });
}

}  // namespace towdb::cli
