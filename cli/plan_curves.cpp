#include "plan_curves.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "common/error.hpp"
#include "output.hpp"
#include "query_json.hpp"

namespace towdb::cli {

namespace {

using nlohmann::ordered_json;
using query::QueryError;
using query::QueryRequest;
using query::QueryResult;

constexpr double kLbfPerKip = 1000.0;
constexpr double kPolarStepDeg = 5.0;  // plot (b): one point every 5 deg, 73 points over 0-360

// A library error that is the question's (bad input, outside the data) is an
// InputError (exit 2); anything else is a failure (exit 1).
[[noreturn]] void rethrow(const QueryError& e) {
  if (e.is_input()) throw InputError(e.what());
  throw Error(e.what());
}

PlanPoint point(double x, const QueryResult& r) {
  const towdb_query_result& v = r.values;
  return {x, v.extreme_tension_lbf / kLbfPerKip, v.uncertainty_kips, v.mean_tension_lbf,
          v.extreme_check_passed != 0 && v.mean_check_passed != 0};
}

// Samples one curve: `set` puts x into the request. Points outside the stored
// data are counted and left out; other errors propagate.
template <typename Set>
PlanCurve sample(query::Database& db, QueryRequest r, const std::vector<double>& xs, Set set) {
  PlanCurve c;
  for (double x : xs) {
    set(r, x);
    try {
      c.points.push_back(point(x, db.query(r)));
    } catch (const QueryError& e) {
      if (e.code() != TOWDB_QUERY_RANGE) rethrow(e);
      ++c.refused;
    }
  }
  return c;
}

std::vector<double> linspace(double lo, double hi, int n) {
  std::vector<double> xs;
  if (n < 2 || !(hi > lo)) return {lo};
  for (int i = 0; i < n; ++i) xs.push_back(lo + (hi - lo) * i / (n - 1));
  return xs;
}

// Adds x to the sorted samples (a passing limit, the chosen value) unless a
// sample is already there.
void insert_sample(std::vector<double>* xs, double x) {
  if (!std::isfinite(x)) return;
  const auto it = std::lower_bound(xs->begin(), xs->end(), x);
  if (it != xs->end() && std::abs(*it - x) < 1e-9 * std::max(1.0, std::abs(x))) return;
  xs->insert(it, x);
}

void require_points(const PlanCurve& c, const std::string& what) {
  if (c.points.empty()) {
    throw InputError(what + ": no point of the curve is inside the stored data (" + std::to_string(c.refused) +
                     " refused)");
  }
}

PlanCurve speed_curve(query::Database& db, const QueryRequest& chosen, double heading_deg, int samples) {
  QueryRequest r = chosen;
  r.values.heading_deg = heading_deg;
  query::InverseResult s;
  try {
    s = db.max_speed(r);
  } catch (const QueryError& e) {
    rethrow(e);
  }
  std::vector<double> xs = linspace(s.search.range_low, s.search.range_high, samples);
  if (s.search.found) insert_sample(&xs, s.search.value);
  PlanCurve c = sample(db, r, xs, [](QueryRequest& q, double x) { q.values.speed_kt = x; });
  c.heading_deg = heading_deg;
  if (s.search.found) {
    c.passing_limit = s.search.value;
    c.passing_limit_extreme_kips = s.at_value.values.extreme_tension_lbf / kLbfPerKip;
  }
  require_points(c, "tension against speed at heading " + fmt(heading_deg) + " deg");
  return c;
}

PlanCurve length_curve(query::Database& db, const QueryRequest& chosen, int samples) {
  query::InverseResult s;
  try {
    s = db.min_length(chosen);
  } catch (const QueryError& e) {
    rethrow(e);
  }
  std::vector<double> xs = linspace(s.search.range_low, s.search.range_high, samples);
  if (s.search.found) insert_sample(&xs, s.search.value);
  insert_sample(&xs, chosen.values.length_ft);
  PlanCurve c = sample(db, chosen, xs, [](QueryRequest& q, double x) { q.values.length_ft = x; });
  c.heading_deg = chosen.values.heading_deg;
  if (s.search.found) {
    c.passing_limit = s.search.value;
    c.passing_limit_extreme_kips = s.at_value.values.extreme_tension_lbf / kLbfPerKip;
  }
  require_points(c, "tension against towline length");
  return c;
}

ordered_json curve_json(const PlanCurve& c, const char* x_key, const char* limit_key) {
  ordered_json points = ordered_json::array();
  for (const PlanPoint& p : c.points) {
    points.push_back({{x_key, p.x},
                      {"extreme_tension_kips", p.extreme_kips},
                      {"uncertainty_kips", p.uncertainty_kips},
                      {"mean_tension_lbf", p.mean_tension_lbf},
                      {"passed", p.passed}});
  }
  ordered_json j;
  j["heading_deg"] = c.heading_deg;
  j["points"] = points;
  j["refused_points"] = c.refused;
  if (limit_key) {
    j[limit_key] = c.passing_limit ? ordered_json(*c.passing_limit) : ordered_json(nullptr);
    j["at_limit_extreme_tension_kips"] =
        c.passing_limit ? ordered_json(c.passing_limit_extreme_kips) : ordered_json(nullptr);
  }
  return j;
}

}  // namespace

query::QueryRequest to_request(const PlanQuestion& q) {
  query::QueryRequest r;
  r.tug = q.tug;
  r.tow = q.tow;
  r.line = q.line;
  r.values.speed_kt = q.speed_kt;
  r.values.wind_kt = q.wind_kt;
  r.values.hs_ft = q.hs_ft;
  r.values.tp_s = q.tp_s;
  r.values.heading_deg = q.heading_deg;
  r.values.length_ft = q.length_ft;
  r.values.mean_tension_lbf = q.mean_tension_lbf;
  r.values.probability = q.probability;
  r.values.tow_days = q.tow_days;
  r.values.on_brake = q.brake ? 1 : 0;
  return r;
}

Plan make_plan(query::Database& db, const PlanQuestion& q) {
  Plan p;
  p.request = to_request(q);
  try {
    p.chosen = db.query(p.request);
  } catch (const QueryError& e) {
    rethrow(e);
  }
  p.extreme_limit_kips = p.chosen.values.extreme_limit_lbf / kLbfPerKip;
  for (double h : q.curve_headings_deg) p.by_speed.push_back(speed_curve(db, p.request, h, q.samples));

  std::vector<double> headings;
  for (double h = 0.0; h <= 360.0 + 1e-9; h += kPolarStepDeg) headings.push_back(h);
  insert_sample(&headings, q.heading_deg);
  p.by_heading = sample(db, p.request, headings, [](QueryRequest& r, double x) { r.values.heading_deg = x; });
  p.by_heading.heading_deg = q.heading_deg;
  require_points(p.by_heading, "tension against heading");

  p.by_length = length_curve(db, p.request, q.samples);
  return p;
}

ordered_json plan_json(const Plan& plan) {
  ordered_json j;
  j["answer"] = query_answer_json(plan.request, plan.chosen, plan.request.values.on_brake != 0);
  j["extreme_limit_kips"] = plan.extreme_limit_kips;
  ordered_json speed = ordered_json::array();
  for (const PlanCurve& c : plan.by_speed) speed.push_back(curve_json(c, "speed_kt", "fastest_passing_speed_kt"));
  j["tension_vs_speed"] = speed;
  j["tension_vs_heading"] = curve_json(plan.by_heading, "heading_deg", nullptr);
  j["tension_vs_length"] = curve_json(plan.by_length, "length_ft", "shortest_passing_length_ft");
  return j;
}

}  // namespace towdb::cli
