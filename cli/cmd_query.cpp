// towdb query | max-speed | min-length: the tow planner's questions, answered
// by the query library (towdb/query.hpp; equations EQ-QUERY-* in towdb/query.h).
//
//   towdb query --db F --tug T --tow W --speed-kt V --wind-kt U --heading-deg H
//               --line wire|fiber --length-ft L [--mean-tension-lbf M]
//               (without M: the calculated mean tension of this speed, wind and
//               heading: interpolated from the values stored at the grid nodes
//               (query.h EQ-QUERY-9), else computed as the database's build
//               did (database_basis.hpp))
//               [--probability P] [--tow-days D] [--extrapolate] [--brake] [--json|--csv]
//   towdb query --db F --batch [--json]     CSV queries on stdin, header = flag names
//   towdb query --db F --leave-one-out      interpolation error of the database
//   towdb max-speed / min-length            the same flags without --speed-kt / --length-ft
//                                           and --extrapolate (a search never extrapolates)
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "database_basis.hpp"
#include "io/csv.hpp"
#include "output.hpp"
#include "query_json.hpp"
#include "towdb/query.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;
using towdb::query::QueryError;
using towdb::query::QueryRequest;
using towdb::query::QueryResult;
using towdb::query::warning_kind_name;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const double kInf = std::numeric_limits<double>::infinity();

struct QueryArgs {
  std::string db;
  std::string tug, tow, line, spectrum;
  double speed_kt = kNaN, wind_kt = kNaN, hs_ft = kNaN, tp_s = kNaN, heading_deg = kNaN;
  double length_ft = kNaN, mean_tension_lbf = kNaN;
  double probability = 0.001, tow_days = 1.0;
  bool extrapolate = false, brake = false, json = false, csv = false, batch = false, loo = false;
  std::string space = "auto";
};

int space_code(const std::string& s) {
  if (s == "linear") return TOWDB_QUERY_SPACE_LINEAR;
  if (s == "log") return TOWDB_QUERY_SPACE_LOG;
  return TOWDB_QUERY_SPACE_AUTO;
}

const char* space_name(int s) { return s == TOWDB_QUERY_SPACE_LOG ? "log" : "linear"; }

// Library errors that are the user's (bad input, range, database) exit 2.
[[noreturn]] void rethrow(const QueryError& e) {
  if (e.is_input()) throw InputError(e.what());
  throw std::runtime_error(e.what());
}

QueryRequest to_request(const QueryArgs& a) {
  QueryRequest r;
  r.tug = a.tug;
  r.tow = a.tow;
  r.line = a.line;
  r.spectrum = a.spectrum;
  r.values.speed_kt = a.speed_kt;
  r.values.wind_kt = a.wind_kt;
  r.values.hs_ft = a.hs_ft;
  r.values.tp_s = a.tp_s;
  r.values.heading_deg = a.heading_deg;
  r.values.length_ft = a.length_ft;
  r.values.mean_tension_lbf = a.mean_tension_lbf;
  r.values.probability = a.probability;
  r.values.tow_days = a.tow_days;
  r.values.extrapolate = a.extrapolate ? 1 : 0;
  r.values.on_brake = a.brake ? 1 : 0;
  return r;
}

void require_flags(const QueryArgs& a, bool need_speed, bool need_length) {
  std::vector<std::string> missing;
  if (a.tug.empty()) missing.push_back("--tug");
  if (a.tow.empty()) missing.push_back("--tow");
  if (a.line.empty()) missing.push_back("--line");
  if (need_speed && std::isnan(a.speed_kt)) missing.push_back("--speed-kt");
  if (std::isnan(a.wind_kt) && std::isnan(a.hs_ft)) missing.push_back("--wind-kt (or --hs-ft)");
  if (std::isnan(a.heading_deg)) missing.push_back("--heading-deg");
  if (need_length && std::isnan(a.length_ft)) missing.push_back("--length-ft");
  if (!missing.empty()) {
    std::string s;
    for (const auto& m : missing) s += (s.empty() ? "" : ", ") + m;
    throw InputError("missing required option(s): " + s);
  }
}

ordered_json nullable(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); }

ordered_json result_json(const QueryRequest& rq, const QueryResult& r, bool on_brake) {
  const towdb_query_result& v = r.values;
  const towdb_query_request& q = rq.values;
  ordered_json j;
  // The database's vessel names (as matched), not the spelling typed.
  j["query"] = {{"tug", r.tug.empty() ? rq.tug : r.tug},
                {"tow", r.tow.empty() ? rq.tow : r.tow},
                {"line", rq.line},
                {"speed_kt", nullable(q.speed_kt)},
                {"wind_kt", nullable(q.wind_kt)},
                {"hs_ft", nullable(q.hs_ft)},
                {"tp_s", nullable(q.tp_s)},
                {"heading_deg", nullable(q.heading_deg)},
                {"length_ft", nullable(q.length_ft)},
                {"mean_tension_lbf", nullable(q.mean_tension_lbf)},
                {"probability", q.probability},
                {"tow_days", q.tow_days},
                {"extrapolate", q.extrapolate != 0},
                {"on_brake", on_brake}};
  j["dynamic_tension_kips"] = v.dynamic_tension_kips;
  j["dynamic_999_kips"] = v.dynamic_999_kips;
  j["mean_tension_lbf"] = v.mean_tension_lbf;
  j["calculated_mean_tension_lbf"] = nullable(v.calculated_mean_tension_lbf);
  j["mean_tension_factor"] = nullable(v.mean_tension_factor);
  j["extreme_tension_lbf"] = v.extreme_tension_lbf;
  j["breaking_strength_lbf"] = v.breaking_strength_lbf;
  j["gumbel_u_kips"] = v.gumbel_u_kips;
  j["gumbel_alpha_per_kip"] = v.gumbel_alpha_per_kip;
  // Margin = limit - value: negative when the check fails; percent of the limit.
  auto check = [](const char* name, const char* rule, double value, double limit, int passed) {
    return ordered_json{{"name", name},
                        {"rule", rule},
                        {"value_lbf", value},
                        {"limit_lbf", limit},
                        {"margin_lbf", limit - value},
                        {"margin_percent", 100.0 * (limit - value) / limit},
                        {"passed", passed != 0}};
  };
  j["checks"] = ordered_json::array(
      {check("extreme_tension", "extreme tension <= breaking strength / 1.5 (Navy Towing Manual)",
             v.extreme_tension_lbf, v.extreme_limit_lbf, v.extreme_check_passed),
       check("mean_tension",
             on_brake ? "mean tension <= breaking strength / 5 (towline on the brake)"
                      : "mean tension <= breaking strength / 3 (automatic towing machine)",
             v.mean_tension_lbf, v.mean_limit_lbf, v.mean_check_passed)});
  j["uncertainty_kips"] = v.uncertainty_kips;
  j["interpolation_error_kips"] = v.interpolation_error_kips;
  j["confidence_interval"] = {{"of", "dynamic_999_kips"},
                              {"level", nullable(v.ci_level)},
                              {"low_kips", nullable(v.ci_low_kips)},
                              {"high_kips", nullable(v.ci_high_kips)}};
  j["slack_fraction"] = v.slack_fraction;
  j["catenary_sag_ft"] = nullable(v.catenary_sag_ft);
  j["catenary_depth_ft"] = nullable(v.catenary_depth_ft);
  j["equivalent_wind_kt"] = nullable(v.equivalent_wind_kt);
  j["interpolation_space"] = space_name(v.interpolation_space);
  j["extrapolated"] = v.extrapolated != 0;
  ordered_json w = ordered_json::array();
  for (const auto& x : r.warnings) w.push_back({{"kind", warning_kind_name(x.kind)}, {"message", x.message}});
  j["warnings"] = w;
  ordered_json n = ordered_json::array();
  for (const auto& c : r.nearest) {
    n.push_back({{"case_id", c.case_id},
                 {"speed_kt", c.speed_kt},
                 {"wind_kt", nullable(c.wind_kt)},
                 {"hs_ft", nullable(c.hs_ft)},
                 {"tp_s", nullable(c.tp_s)},
                 {"heading_deg", c.heading_deg},
                 {"length_ft", c.length_ft},
                 {"mean_tension_lbf", c.mean_tension_lbf},
                 {"days", c.days},
                 {"dynamic_999_kips", c.dynamic_999_kips},
                 {"dynamic_tension_kips", c.dynamic_tension_kips},
                 {"distance", c.distance}});
  }
  j["nearest_cases"] = n;
  return j;
}

const char* const kCsvHeader =
    "tug,tow,line,speed_kt,wind_kt,hs_ft,tp_s,heading_deg,length_ft,mean_tension_lbf,probability,tow_days,"
    "dynamic_tension_kips,dynamic_999_kips,extreme_tension_lbf,breaking_strength_lbf,extreme_check,mean_check,"
    "uncertainty_kips,catenary_sag_ft,catenary_depth_ft,equivalent_wind_kt,extrapolated,warnings,error";

// Text cells go through the one CSV writer (io/csv.hpp).
constexpr auto& csv_cell = io::csv::cell;

std::string csv_num(double v) { return std::isfinite(v) ? fmt(v) : ""; }
// A computed value in CSV, rounded as in the text output (1 lbf, 0.1 kips);
// JSON keeps full precision.
std::string csv_rounded(double v, int decimals) { return std::isfinite(v) ? fmt(v, decimals) : ""; }

std::string csv_row(const QueryRequest& rq, const QueryResult* r, const std::string& error) {
  const towdb_query_request& q = rq.values;
  const bool named = r && !r->tug.empty();
  std::string s = csv_cell(named ? r->tug : rq.tug) + "," + csv_cell(named ? r->tow : rq.tow) + "," +
                  csv_cell(rq.line) + "," + csv_num(q.speed_kt) +
                  "," + csv_num(q.wind_kt) + "," + csv_num(q.hs_ft) + "," + csv_num(q.tp_s) + "," +
                  csv_num(q.heading_deg) + "," + csv_num(q.length_ft) + ",";
  if (r) {
    const towdb_query_result& v = r->values;
    std::string warnings;
    for (const auto& w : r->warnings) warnings += (warnings.empty() ? "" : " | ") + w.message;
    s += csv_rounded(v.mean_tension_lbf, 0) + "," + csv_num(q.probability) + "," + csv_num(q.tow_days) + "," +
         csv_rounded(v.dynamic_tension_kips, 1) + "," + csv_rounded(v.dynamic_999_kips, 1) + "," +
         csv_rounded(v.extreme_tension_lbf, 0) + "," + csv_rounded(v.breaking_strength_lbf, 0) + "," +
         (v.extreme_check_passed ? "pass" : "fail") + "," + (v.mean_check_passed ? "pass" : "fail") + "," +
         csv_rounded(v.uncertainty_kips, 1) + "," + csv_rounded(v.catenary_sag_ft, 1) + "," +
         csv_rounded(v.catenary_depth_ft, 1) + "," +
         csv_rounded(v.equivalent_wind_kt, 2) + "," + (v.extrapolated ? "1" : "0") + "," + csv_cell(warnings) + ",";
  } else {
    s += csv_num(q.mean_tension_lbf) + "," + csv_num(q.probability) + "," + csv_num(q.tow_days) + ",,,,,,,,,,,,," +
         csv_cell(error);
  }
  return s;
}

// ---- default mean tension ------------------------------------------------------

// The mean tension of a question asked without one: the calculated value of
// its own speed, wind and heading on the database's basis when the database
// records one, else the query library's default (each node's highest stored
// mean tension), with the reason.
struct MeanDefault {
  bool calculated = false;
  // The database stores T_calc at its nodes (query.h EQ-QUERY-9): the library's
  // default, interpolated from them, is used (no strip theory at query time),
  // and this is already the answer at it.
  std::optional<QueryResult> at_nodes;
  std::optional<DatabaseBasis> basis;
  CalculatedMeanTension tension;
  std::string reason;  // why the library default is used instead (when !calculated)
};

// Looks the basis up once per command and the ship files once, on first use.
class MeanDefaults {
 public:
  MeanDefaults(const Context& ctx, std::string db) : ctx_(ctx), db_(std::move(db)) {}

  MeanDefault for_question(const QueryArgs& a) {
    MeanDefault d;
    if (!lookup_) lookup_ = read_database_basis(db_);
    if (!lookup_->basis) {
      d.reason = lookup_->reason;
      return d;
    }
    if (std::isnan(a.wind_kt)) {
      d.reason = "the question gives a wave height, not a wind: the calculated mean tension needs a wind speed";
      return d;
    }
    if (!catalog_) catalog_ = load_catalog(ctx_);
    d.tension = calculated_mean_tension(*lookup_->basis, *catalog_, db_, a.tow, a.speed_kt, a.wind_kt, a.heading_deg);
    if (!(d.tension.total_lbf > 0.0)) {
      throw InputError("--mean-tension-lbf not given, and the calculated mean tension at --speed-kt " +
                       fmt(a.speed_kt) + ", --wind-kt " + fmt(a.wind_kt) + ", --heading-deg " + fmt(a.heading_deg) +
                       " is " + fmt(d.tension.total_lbf, 0) +
                       " lbf (wind and sea push the tow); allowed: a positive mean tension, give --mean-tension-lbf");
    }
    d.calculated = true;
    d.basis = lookup_->basis;
    return d;
  }

 private:
  const Context& ctx_;
  std::string db_;
  std::optional<BasisLookup> lookup_;
  std::optional<io::ShipCatalog> catalog_;
};

ordered_json mean_default_json(const MeanDefault& d) {
  ordered_json j;
  if (d.at_nodes) {
    j["method"] = "calculated_at_nodes";
    j["calculated_mean_tension_lbf"] = d.at_nodes->values.mean_tension_lbf;
    return j;
  }
  if (!d.calculated) {
    j["method"] = "node_highest_stored";
    j["reason"] = d.reason;
    return j;
  }
  j["method"] = "calculated";
  j["basis"] = basis_json(*d.basis);
  j["breakdown"] = breakdown_json(d.tension);
  if (!d.tension.ship_file_note.empty()) j["note"] = d.tension.ship_file_note;
  return j;
}

void print_mean_default(const MeanDefault& d) {
  if (d.at_nodes) {
    std::cout << "\nmean tension: not given; the calculated mean tension of this speed and wind on the database's "
                 "basis, interpolated from the values stored at the grid nodes: "
              << fmt_grouped(d.at_nodes->values.mean_tension_lbf) << " lbf (`towdb mean-tension` gives its breakdown)\n";
    return;
  }
  if (!d.calculated) {
    std::cout << "\nmean tension: not given; each stored node's highest mean tension is used, because no calculated "
                 "default is available: "
              << d.reason << "\n";
    return;
  }
  const propulsion::MeanTensionBreakdown& b = d.tension.breakdown;
  std::cout << "\nmean tension: not given; the calculated mean tension of this speed, wind and heading, as the "
               "database's build computes it ("
            << basis_text(*d.basis) << ")\n";
  TextTable t({"component", "lbf"});
  t.add_row({"hull", fmt_grouped(units::n_to_lbf(b.hull_n))});
  t.add_row({"propeller", fmt_grouped(units::n_to_lbf(b.propeller_n))});
  t.add_row({"wind (relative " + fmt(units::m_s_to_kt(b.relative_wind_m_s), 1) + " kt)",
             fmt_grouped(units::n_to_lbf(b.wind_n))});
  t.add_row({"sea", fmt_grouped(units::n_to_lbf(b.sea_n))});
  t.add_row({"tow resistance", fmt_grouped(units::n_to_lbf(b.tow_resistance_n))});
  t.add_row({"towline", fmt_grouped(units::n_to_lbf(b.towline_n))});
  t.add_row({"total", fmt_grouped(d.tension.total_lbf)});
  t.print(std::cout);
  if (!d.tension.ship_file_note.empty()) std::cout << "note: " << d.tension.ship_file_note << "\n";
}

// Fills a missing mean tension; returns what was done (nullopt: it was given).
// Where the database stores T_calc at its nodes the library's own default is
// used (the request keeps NaN) and its answer is kept in at_nodes, so the
// question is not asked twice; a question the library refuses without a mean
// tension is refused with a mean tension too, so its error is passed on.
std::optional<MeanDefault> apply_mean_default(MeanDefaults& defaults, const QueryArgs& a, QueryRequest* rq,
                                              query::Database& db) {
  if (!std::isnan(a.mean_tension_lbf)) return std::nullopt;
  QueryResult probe = db.query(*rq);
  if (std::isfinite(probe.values.mean_tension_factor)) {
    MeanDefault d;
    d.at_nodes = std::move(probe);
    return d;
  }
  MeanDefault d = defaults.for_question(a);
  if (d.calculated) rq->values.mean_tension_lbf = d.tension.total_lbf;
  return d;
}

// "pass (limit L lbf, margin M lbf = P %)" or "FAIL (limit L lbf, exceeded by M lbf = P %)".
std::string check_text(double value, double limit, int passed) {
  const double margin = limit - value;
  return std::string(passed ? "pass" : "FAIL") + " (limit " + fmt_grouped(limit) + " lbf, " +
         (passed ? "margin " : "exceeded by ") + fmt_grouped(std::abs(margin)) + " lbf = " +
         fmt(100.0 * std::abs(margin) / limit, 1) + " %)";
}

void print_text(const QueryRequest& rq, const QueryResult& r, bool on_brake) {
  const towdb_query_result& v = r.values;
  const towdb_query_request& q = rq.values;
  // Speed and length rounded as a planner reads them (a search's value has all its bits).
  std::cout << r.tug << " towing " << r.tow << " on " << rq.line << ", " << fmt(std::round(q.speed_kt * 100.0) / 100.0)
            << " kt, "
            << (std::isnan(q.wind_kt) ? "Hs " + fmt(q.hs_ft) + " ft" : "wind " + fmt(q.wind_kt) + " kt")
            << ", heading " << fmt(q.heading_deg) << " deg, length " << fmt(std::round(q.length_ft)) << " ft\n";
  TextTable t({"quantity", "value"});
  t.add_row({"mean tension lbf", fmt_grouped(v.mean_tension_lbf)});
  if (std::isfinite(v.mean_tension_factor)) {
    t.add_row({"  / calculated at the nodes (" + fmt_grouped(v.calculated_mean_tension_lbf) + " lbf)",
               fmt(v.mean_tension_factor, 3)});
  }
  t.add_row({"dynamic tension kips (p=" + fmt(q.probability) + ", " + fmt(q.tow_days) + " d)",
             fmt(v.dynamic_tension_kips, 1) + " +/- " + fmt(v.uncertainty_kips, 1)});
  t.add_row({"dynamic tension kips (0.001/day)", fmt(v.dynamic_999_kips, 1)});
  t.add_row({"extreme tension lbf", fmt_grouped(v.extreme_tension_lbf)});
  t.add_row({"breaking strength lbf", fmt_grouped(v.breaking_strength_lbf)});
  if (std::isfinite(v.catenary_sag_ft)) {
    t.add_row({"catenary sag ft (below the chord)", fmt(v.catenary_sag_ft, 1)});
  }
  if (std::isfinite(v.catenary_depth_ft)) {
    const double depth = v.catenary_depth_ft;
    t.add_row({"catenary lowest point ft", fmt(std::abs(depth), 1) + (depth >= 0.0 ? " below" : " above") +
                                              " the waterline"});
  }
  if (std::isfinite(v.equivalent_wind_kt)) {
    t.add_row({"equivalent wind kt (fully developed sea of this Hs)", fmt(v.equivalent_wind_kt, 2)});
  }
  t.add_row({"check extreme <= BS/1.5", check_text(v.extreme_tension_lbf, v.extreme_limit_lbf, v.extreme_check_passed)});
  t.add_row({std::string("check mean <= BS/") + (on_brake ? "5 (brake)" : "3 (ATM)"),
             check_text(v.mean_tension_lbf, v.mean_limit_lbf, v.mean_check_passed)});
  t.add_row({"interpolation", std::string(space_name(v.interpolation_space)) + " space, error estimate " +
                                  fmt(v.interpolation_error_kips, 2) + " kips"});
  t.print(std::cout);
  if (!r.nearest.empty()) {
    std::cout << "\nnearest stored cases\n";
    TextTable n({"case", "speed kt", "sea", "heading deg", "length ft", "mean lbf", "days", "dyn 0.001 kips"});
    for (const auto& c : r.nearest) {
      n.add_row({std::to_string(c.case_id), fmt(c.speed_kt), std::isnan(c.wind_kt) ? fmt(c.hs_ft) + " ft" : fmt(c.wind_kt) + " kt",
                 fmt(c.heading_deg), fmt(c.length_ft), fmt_grouped(c.mean_tension_lbf), std::to_string(c.days),
                 fmt(c.dynamic_999_kips, 1)});
    }
    n.print(std::cout);
  }
  for (const auto& w : r.warnings) std::cout << "warning: " << w.message << "\n";
}

// ---- batch ------------------------------------------------------------------

int run_batch(query::Database& db, const QueryArgs& defaults, MeanDefaults& mean_defaults) {
  std::string line;
  int line_no = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(std::cin, line)) {
    ++line_no;
    bool unterminated = false;
    if (!line.empty() && line.find_first_not_of(" \r") != std::string::npos) {
      header = io::csv::split_quoted(line, &unterminated);
    }
    if (unterminated) {
      throw InputError("stdin line " + std::to_string(line_no) + ": the header row has a quoted cell without its "
                       "closing '\"'");
    }
  }
  if (header.empty()) throw InputError("--batch: stdin has no CSV header row (e.g. tug,tow,speed_kt,...)");
  static const std::vector<std::string> kColumns = {
      "tug",        "tow",       "line",             "spectrum",    "speed_kt", "wind_kt",     "hs_ft", "tp_s",
      "heading_deg", "length_ft", "mean_tension_lbf", "probability", "tow_days", "extrapolate", "brake"};
  for (const auto& h : header) {
    if (std::find(kColumns.begin(), kColumns.end(), h) == kColumns.end()) {
      std::string known;
      for (const auto& k : kColumns) known += (known.empty() ? "" : ",") + k;
      throw InputError("stdin line " + std::to_string(line_no) + ": unknown column '" + h + "'; known: " + known);
    }
    if (std::count(header.begin(), header.end(), h) > 1) {
      throw InputError("stdin line " + std::to_string(line_no) + ": column '" + h + "' appears more than once");
    }
  }
  ordered_json all = ordered_json::array();
  if (!defaults.json) std::cout << kCsvHeader << "\n";
  int failures = 0;
  while (std::getline(std::cin, line)) {
    ++line_no;
    if (line.find_first_not_of(" \r") == std::string::npos) continue;
    // A row that cannot be read is reported on its own row like a bad question
    // (the output keeps one row per input row; tests/fuzz/regressions/batch).
    bool unterminated = false;
    const auto cells = io::csv::split_quoted(line, &unterminated);
    std::string row_error;
    if (unterminated) {
      row_error = "a quoted cell has no closing '\"'";
    } else if (cells.size() != header.size()) {
      row_error = std::to_string(cells.size()) + " cells, the header has " + std::to_string(header.size());
    }
    QueryArgs a = defaults;
    for (std::size_t i = 0; row_error.empty() && i < header.size(); ++i) {
      const std::string& h = header[i];
      const std::string& v = cells[i];
      if (v.empty()) continue;
      if (h == "tug") { a.tug = v; continue; }
      if (h == "tow") { a.tow = v; continue; }
      if (h == "line") { a.line = v; continue; }
      if (h == "spectrum") { a.spectrum = v; continue; }
      double x = 0;
      if (!parse_number(v, &x)) {
        row_error = "column " + h + ": '" + v + "' is not a finite number";
        break;
      }
      if (h == "speed_kt") a.speed_kt = x;
      if (h == "wind_kt") a.wind_kt = x;
      if (h == "hs_ft") a.hs_ft = x;
      if (h == "tp_s") a.tp_s = x;
      if (h == "heading_deg") a.heading_deg = x;
      if (h == "length_ft") a.length_ft = x;
      if (h == "mean_tension_lbf") a.mean_tension_lbf = x;
      if (h == "probability") a.probability = x;
      if (h == "tow_days") a.tow_days = x;
      if (h == "extrapolate") a.extrapolate = x != 0.0;
      if (h == "brake") a.brake = x != 0.0;
    }
    QueryRequest rq = to_request(a);
    try {
      if (!row_error.empty()) throw QueryError(TOWDB_QUERY_INPUT, row_error);
      std::optional<MeanDefault> mean_default;
      try {
        mean_default = apply_mean_default(mean_defaults, a, &rq, db);
      } catch (const InputError& e) {
        throw QueryError(TOWDB_QUERY_INPUT, e.what());  // reported on its row like any bad row
      }
      const QueryResult r = mean_default && mean_default->at_nodes ? *mean_default->at_nodes : db.query(rq);
      if (defaults.json) {
        all.push_back(result_json(rq, r, a.brake));
        if (mean_default) all.back()["mean_tension_default"] = mean_default_json(*mean_default);
      } else {
        std::cout << csv_row(rq, &r, "") << "\n";
      }
    } catch (const QueryError& e) {
      if (!e.is_input()) throw std::runtime_error(e.what());
      ++failures;
      const std::string msg = "line " + std::to_string(line_no) + ": " + e.what();
      if (defaults.json) {
        ordered_json j;
        j["error"] = msg;
        all.push_back(j);
      } else {
        std::cout << csv_row(rq, nullptr, msg) << "\n";
      }
      std::cerr << "towdb: error: stdin " << msg << "\n";
    }
  }
  // Bytes that are not UTF-8 (a name typed in Latin-1, echoed in an error) are
  // written as U+FFFD: dump() would throw on them (an exit 1; regression input
  // tests/fuzz/regressions/batch/invalid-utf8-in-a-name.csv).
  if (defaults.json) std::cout << all.dump(2, ' ', false, ordered_json::error_handler_t::replace) << "\n";
  return failures > 0 ? 2 : 0;
}

// ---- leave-one-out -------------------------------------------------------------

int run_loo(query::Database& db, bool json) {
  static const char* const kAxisNames[] = {"speed", "sea", "period", "heading", "length", "mean_tension"};
  ordered_json j;
  j["cases"] = db.case_count();
  j["chosen_space"] = space_name(db.space());
  ordered_json rows = ordered_json::array();
  TextTable t({"space", "axis", "samples", "median rel err", "p90 rel err", "max rel err", "median abs kips"});
  for (int space : {TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_SPACE_LOG}) {
    for (int axis = TOWDB_QUERY_AXIS_ALL; axis < TOWDB_QUERY_AXIS_COUNT; ++axis) {
      towdb_query_loo s{};
      try {
        s = db.leave_one_out(space, axis);
      } catch (const QueryError& e) {
        if (space == TOWDB_QUERY_SPACE_LOG) break;  // log space impossible (some u <= 0)
        rethrow(e);
      }
      if (axis != TOWDB_QUERY_AXIS_ALL && s.samples == 0) continue;
      const std::string axis_name = axis == TOWDB_QUERY_AXIS_ALL ? "all" : kAxisNames[axis];
      rows.push_back({{"space", space_name(space)},
                      {"axis", axis_name},
                      {"samples", s.samples},
                      {"median_rel_error", nullable(s.median_rel_error)},
                      {"p90_rel_error", nullable(s.p90_rel_error)},
                      {"max_rel_error", nullable(s.max_rel_error)},
                      {"median_abs_error_kips", nullable(s.median_abs_error_kips)}});
      t.add_row({space_name(space), axis_name, std::to_string(s.samples), fmt(s.median_rel_error, 4),
                 fmt(s.p90_rel_error, 4), fmt(s.max_rel_error, 4), fmt(s.median_abs_error_kips, 2)});
    }
  }
  j["leave_one_out"] = rows;
  if (json) {
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << "leave-one-out (EQ-QUERY-8): each stored case predicted from its two neighbours along one axis\n"
              << db.case_count() << " cases; interpolation space chosen: " << space_name(db.space()) << "\n\n";
    t.print(std::cout);
  }
  return 0;
}

// The `towdb simulate` command that computes a question directly: what a
// planner can run when the question lies outside the stored span (the chain
// itself: about 0.5 s per 100 simulated days on one core, after a few seconds
// of the two vessels' strip theory).
std::string simulate_command(const QueryRequest& rq) {
  const towdb_query_request& v = rq.values;
  std::string c = "towdb simulate --tug " + shell_word(rq.tug) + " --tow " + shell_word(rq.tow) + " --speed-kt " +
                  fmt(v.speed_kt);
  if (std::isfinite(v.wind_kt)) c += " --wind-kt " + fmt(v.wind_kt);
  if (std::isfinite(v.hs_ft)) c += " --hs-ft " + fmt(v.hs_ft) + " --tp-s " + fmt(v.tp_s);
  if (rq.spectrum == "jonswap" || rq.spectrum == "bretschneider") c += " --spectrum " + rq.spectrum;
  c += " --heading-deg " + fmt(v.heading_deg) + " --line " + rq.line + " --length-ft " + fmt(v.length_ft) +
       " --mean-tension-lbf " + fmt(v.mean_tension_lbf) + " --days 100";
  return c;
}

// ---- commands ----------------------------------------------------------------

int run_query(const Context& ctx, const QueryArgs& a) {
  if (a.json && a.csv) throw InputError("--json and --csv: choose one output format");
  try {
    query::Database db(a.db, space_code(a.space));
    if (a.loo) return run_loo(db, a.json);
    MeanDefaults mean_defaults(ctx, a.db);
    if (a.batch) return run_batch(db, a, mean_defaults);
    require_flags(a, true, true);
    QueryRequest rq = to_request(a);
    const std::optional<MeanDefault> mean_default = apply_mean_default(mean_defaults, a, &rq, db);
    QueryResult r;
    try {
      r = mean_default && mean_default->at_nodes ? *mean_default->at_nodes : db.query(rq);
    } catch (const QueryError& e) {
      // Outside the stored span: say how to compute the question directly.
      const std::string direct = e.code() == TOWDB_QUERY_RANGE && std::isfinite(rq.values.mean_tension_lbf)
                                     ? "; or compute it directly: " + simulate_command(rq)
                                     : std::string();
      // Name the mean tension the user did not give, and where it came from.
      if (!mean_default || !mean_default->calculated || !e.is_input()) {
        if (direct.empty()) throw;
        throw InputError(e.what() + direct);
      }
      throw InputError("no --mean-tension-lbf given; the calculated mean tension of this speed, wind and heading is " +
                       fmt_grouped(mean_default->tension.total_lbf) + " lbf (" + basis_text(*mean_default->basis) +
                       "): " + e.what() + direct);
    }
    if (a.json) {
      ordered_json j = result_json(rq, r, a.brake);
      if (mean_default) j["mean_tension_default"] = mean_default_json(*mean_default);
      std::cout << j.dump(2) << "\n";
    } else if (a.csv) {
      std::cout << kCsvHeader << "\n" << csv_row(rq, &r, "") << "\n";
    } else {
      print_text(rq, r, a.brake);
      if (mean_default) print_mean_default(*mean_default);
    }
    return r.values.extreme_check_passed && r.values.mean_check_passed ? 0 : kExitCheckFailed;
  } catch (const QueryError& e) {
    rethrow(e);
  }
}

int run_inverse(const QueryArgs& a, bool speed) {
  try {
    require_flags(a, !speed, speed);
    query::Database db(a.db, space_code(a.space));
    const QueryRequest rq = to_request(a);
    const towdb::query::InverseResult r = speed ? db.max_speed(rq) : db.min_length(rq);
    const towdb_query_search& s = r.search;
    const char* key = speed ? "max_speed_kt" : "min_length_ft";
    if (a.json) {
      ordered_json j;
      j["found"] = s.found != 0;
      j[key] = nullable(s.value);
      j[speed ? "searched_speed_kt" : "searched_length_ft"] = {s.range_low, s.range_high};
      j["evaluations"] = s.evaluations;
      QueryRequest at = rq;
      (speed ? at.values.speed_kt : at.values.length_ft) = s.value;
      if (s.found) {
        j["at_value"] = result_json(at, r.at_value, a.brake);
      } else {
        ordered_json w = ordered_json::array();
        for (const auto& x : r.at_value.warnings) w.push_back({{"kind", warning_kind_name(x.kind)}, {"message", x.message}});
        j["warnings"] = w;
      }
      std::cout << j.dump(2) << "\n";
    } else {
      const std::string unit = speed ? " kt" : " ft";
      std::cout << (speed ? "searched speeds " : "searched towline lengths ") << fmt(s.range_low) << " to "
                << fmt(s.range_high) << unit << " (the stored range)\n";
      if (s.found) {
        std::cout << (speed ? "maximum speed passing the Navy Towing Manual checks within the tugs' capacity: "
                            : "minimum towline length passing the Navy Towing Manual checks: ")
                  << fmt(s.value, speed ? 2 : 0) << unit << "\n\n";
        QueryRequest at = rq;
        (speed ? at.values.speed_kt : at.values.length_ft) = s.value;
        print_text(at, r.at_value, a.brake);
      } else {
        std::cout << "none passes: no " << (speed ? "speed" : "towline length")
                  << " in the stored range meets both checks for these conditions\n";
        for (const auto& w : r.at_value.warnings) std::cout << "warning: " << w.message << "\n";
      }
    }
    return 0;
  } catch (const QueryError& e) {
    rethrow(e);
  }
}

void add_common_options(CLI::App* c, QueryArgs& a, bool speed, bool length) {
  c->add_option("--db", a.db, "towdb database file (opened read-only)")->required();
  c->add_option("--tug", a.tug, "Tug name (case, spaces and hyphens ignored; a unique prefix is enough)");
  c->add_option("--tow", a.tow, "Tow name");
  c->add_option("--line", a.line, "Towline type")->check(CLI::IsMember({"wire", "fiber"}));
  c->add_option("--spectrum", a.spectrum, "Sea spectrum family when several are stored (e.g. jonswap)");
  if (speed) c->add_option("--speed-kt", a.speed_kt, "Tow speed [kt]")->check(number_in(0.0, 100.0, true, false));
  c->add_option("--wind-kt", a.wind_kt, "Wind speed [kt] (fully developed Pierson-Moskowitz sea)")
      ->check(number_in(0.0, 200.0, true, false));
  c->add_option("--hs-ft", a.hs_ft, "Significant wave height [ft] (two-parameter seas, instead of --wind-kt)")
      ->check(number_in(0.0, 200.0, true, false));
  c->add_option("--tp-s", a.tp_s, "Peak period [s] with --hs-ft")->check(number_in(0.0, 100.0, true, false));
  c->add_option("--heading-deg", a.heading_deg, "Wave heading [deg], 0 = following seas, 180 = head seas")
      ->check(number_in(0.0, 360.0, false, false));
  if (length) {
    c->add_option("--length-ft", a.length_ft, "Towline (hawser) length [ft]")->check(number_in(0.0, kInf, true, true));
  }
  c->add_option("--mean-tension-lbf", a.mean_tension_lbf,
                speed && length
                    ? "Mean towline tension [lbf] (default: the calculated mean tension of this speed, wind and "
                      "heading on the database's own basis; without one, each grid node's highest stored value)"
                    : "Mean towline tension [lbf] (default: each grid node's highest stored mean tension)")
      ->check(number_in(0.0, kInf, true, true));
  c->add_option("--probability", a.probability,
                "Exceedance probability of the tow's maximum dynamic tension (default 0.001)")
      ->check(number_in(0.0, 1.0, true, true));
  c->add_option("--tow-days", a.tow_days, "Tow duration [days] (default 1)")->check(number_in(1.0, 1e6, false, false));
  if (speed && length) {  // a search never extrapolates (query.h)
    c->add_flag("--extrapolate", a.extrapolate, "Extrapolate outside the stored data (with warnings)");
  }
  c->add_flag("--brake", a.brake, "Towline held on the brake: mean tension limit BS/5 instead of BS/3");
  c->add_option("--space", a.space, "Interpolation space of the Gumbel parameters (default: chosen by leave-one-out)")
      ->check(CLI::IsMember({"auto", "linear", "log"}));
  c->add_flag("--json", a.json, "JSON output");
}

}  // namespace

nlohmann::ordered_json query_answer_json(const query::QueryRequest& request, const query::QueryResult& result,
                                         bool on_brake) {
  return result_json(request, result, on_brake);
}

void add_query_commands(CLI::App& app, Context& ctx) {
  auto qa = std::make_shared<QueryArgs>();
  CLI::App* q = app.add_subcommand("query", "Extreme towline tension for given towing conditions, from a database");
  add_common_options(q, *qa, true, true);
  q->add_flag("--csv", qa->csv, "CSV output (one header row, one row)");
  q->add_flag("--batch", qa->batch,
              "Read many queries as CSV from stdin; header names as the flags: "
              "tug,tow,speed_kt,wind_kt,heading_deg,line,length_ft,mean_tension_lbf[,probability,tow_days,...]");
  q->add_flag("--leave-one-out", qa->loo, "Report the database's leave-one-out interpolation error and exit");
  q->callback([&ctx, qa] { ctx.action = [&ctx, qa] { return run_query(ctx, *qa); }; });

  auto sa = std::make_shared<QueryArgs>();
  CLI::App* s = app.add_subcommand("max-speed", "Highest tow speed that passes the Navy Towing Manual checks");
  add_common_options(s, *sa, false, true);
  s->callback([&ctx, sa] { ctx.action = [sa] { return run_inverse(*sa, true); }; });

  auto la = std::make_shared<QueryArgs>();
  CLI::App* l = app.add_subcommand("min-length", "Shortest towline that passes the Navy Towing Manual checks");
  add_common_options(l, *la, true, false);
  l->callback([&ctx, la] { ctx.action = [la] { return run_inverse(*la, false); }; });
}

}  // namespace towdb::cli
