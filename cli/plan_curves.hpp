// The planner's three curves for one tug, tow, line and sea, computed with the
// query library (towdb/query.hpp, EQ-QUERY-* in towdb/query.h) and shared by
// `towdb plan` (gnuplot PNGs) and `towdb serve` (JSON for the page's charts):
//   (a) extreme tension against speed, one curve per heading, with the
//       fastest speed that passes the Navy Towing Manual checks on each;
//   (b) extreme tension against heading at the chosen speed (0-360 deg,
//       the port side mirrors the starboard: EQ-QUERY-6 folds headings);
//   (c) extreme tension against towline length at the chosen speed and
//       heading, with the shortest length that passes.
// Every point carries the answer's uncertainty_kips (EQ-QUERY-7): the band is
// extreme +/- uncertainty. Points the database cannot answer (outside the
// stored data at that speed, e.g. where the sweep reduced the speed) are left
// out and counted; a curve with no point is an InputError.
#ifndef TOWDB_CLI_PLAN_CURVES_HPP
#define TOWDB_CLI_PLAN_CURVES_HPP

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "towdb/query.hpp"

namespace towdb::cli {

// The question behind the three plots: the chosen speed, heading and length
// are where the other two curves are cut. Units in every name.
struct PlanQuestion {
  std::string tug, tow, line;
  double wind_kt = std::numeric_limits<double>::quiet_NaN();
  double hs_ft = std::numeric_limits<double>::quiet_NaN();
  double tp_s = std::numeric_limits<double>::quiet_NaN();
  double speed_kt = std::numeric_limits<double>::quiet_NaN();
  double heading_deg = std::numeric_limits<double>::quiet_NaN();
  double length_ft = std::numeric_limits<double>::quiet_NaN();
  double mean_tension_lbf = std::numeric_limits<double>::quiet_NaN();  // NaN: the calculated one (EQ-QUERY-9)
  double probability = 0.001;
  double tow_days = 1.0;
  bool brake = false;
  std::vector<double> curve_headings_deg = {0.0, 45.0, 90.0, 135.0, 180.0};  // plot (a)
  int samples = 41;  // points per curve of (a) and (c); plot (b) has one every 5 deg
};

struct PlanPoint {
  double x = 0.0;  // speed_kt, heading_deg or length_ft
  double extreme_kips = 0.0;
  double uncertainty_kips = 0.0;  // of the dynamic tension, EQ-QUERY-7
  double mean_tension_lbf = 0.0;
  bool passed = false;  // both Towing Manual checks (EQ-QUERY-5)
};

struct PlanCurve {
  double heading_deg = 0.0;  // (a): the curve's heading
  std::vector<PlanPoint> points;
  int refused = 0;  // samples outside the stored data, left out
  // (a): the fastest passing speed [kt]; (c): the shortest passing length [ft].
  std::optional<double> passing_limit;
  double passing_limit_extreme_kips = std::numeric_limits<double>::quiet_NaN();
};

struct Plan {
  query::QueryRequest request;  // the chosen point's request
  query::QueryResult chosen;    // the answer there (canonical names in .tug, .tow)
  double extreme_limit_kips = 0.0;  // BS / 1.5
  std::vector<PlanCurve> by_speed;  // (a), one per curve heading
  PlanCurve by_heading;             // (b)
  PlanCurve by_length;              // (c)
};

// The query library's request for the question's chosen point.
query::QueryRequest to_request(const PlanQuestion& q);

// Answers the chosen point first (its errors are the question's: the library's
// InputError names the field), then samples the three curves.
Plan make_plan(query::Database& db, const PlanQuestion& q);

// The plan as JSON: units in every key; the chosen answer as `towdb query --json`.
nlohmann::ordered_json plan_json(const Plan& plan);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_PLAN_CURVES_HPP
