// The query engine behind towdb/query.h (internal; not installed).
//
// The equations (EQ-QUERY-1 .. EQ-QUERY-9), conventions and units are stated
// once, in the public header query/include/towdb/query.h. This file holds the
// C++ types; capi.cpp converts them to the C structs.
//
// Sign checks, re-derived here: EQ-QUERY-2 follows from P(max of D days <= x)
// = F(x)^D = exp(-D exp(-alpha(x - u))) = exp(-exp(-alpha(x - u - ln(D)/alpha))),
// so u_D = u + ln(D)/alpha (larger for longer tows). EQ-QUERY-3 inverts
// 1 - p = exp(-exp(-alpha(x - u_D))): x = u_D - ln(-ln(1 - p))/alpha, and
// -ln(-ln(0.999)) = +6.907 > 0, so the 0.001 value lies above u as it must.
#ifndef TOWDB_QUERY_SRC_ENGINE_HPP
#define TOWDB_QUERY_SRC_ENGINE_HPP

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace towdb::query {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The request is outside the stored data and extrapolation was not asked for.
class OutOfRangeError : public InputError {
 public:
  using InputError::InputError;
};

// The database is missing, corrupt, not a towdb file, or holds no usable case.
class DatabaseError : public InputError {
 public:
  using InputError::InputError;
};

enum class Space { kAuto = 0, kLinear = 1, kLog = 2 };

// Grid axes (EQ-QUERY-6); the mean tension is interpolated per node, not on the grid.
enum Axis : int { kSpeed = 0, kSea = 1, kPeriod = 2, kHeading = 3, kLength = 4 };
inline constexpr int kGridAxes = 5;
inline constexpr int kMeanTensionAxis = 5;  // only for leave-one-out reports
inline constexpr int kAllAxes = -1;

enum class WarningKind : int {
  kExtrapolated = 1,
  kAboveBreaking = 2,
  kSlack = 3,
  kNotMonotone = 4,
  kIncompleteGrid = 5,
  kHighTension = 6,
  kBreakingDiffers = 7,
  kAboveCapacity = 8,
  kEquivalentWind = 9,
};

struct Warning {
  WarningKind kind;
  std::string message;
};

struct QueryOptions {
  // Dynamic tension above which the thesis calls results of "much reduced
  // accuracy" (thesis 6.2: "greater than 300 kips ... outside the bounds").
  double high_tension_warning_kips = 300.0;
  // Slack fraction above which a case is slack-prone and Type I underestimates
  // it (thesis 4.2, YRBM in trailing seas): 0.1 % of the time slack.
  double slack_warning_fraction = 0.001;
  // Navy Towing Manual factors of safety on breaking strength (EQ-QUERY-5).
  double extreme_safety_factor = 1.5;
  double mean_safety_factor_machine = 3.0;
  double mean_safety_factor_brake = 5.0;
  // Mean tension above which the thesis's tugs cannot tow at the speed asked
  // (thesis ch. 5: 125,000 lbf, "beyond the capacity of the tugs"); the
  // answer is given, with a warning that the tow would have to slow down.
  double tug_capacity_lbf = 125000.0;
  // Nearest stored cases reported with an answer.
  int nearest_cases = 4;

  void validate() const;
};

struct Request {
  std::string tug, tow, line;
  std::string spectrum;                // empty: any
  double speed_kt = kNaN;              // > 0
  double wind_kt = kNaN;               // > 0, or NaN when hs_ft is given
  double hs_ft = kNaN;                 // > 0, or NaN for wind seas
  double tp_s = kNaN;                  // > 0 or NaN
  double heading_deg = kNaN;           // [0, 360]
  double length_ft = kNaN;             // > 0
  double mean_tension_lbf = kNaN;      // > 0, NaN: the calculated one (EQ-QUERY-9), else each node's highest
  double probability = 0.001;          // (0, 1): exceedance probability of the tow's maximum
  double tow_days = 1.0;               // >= 1
  bool extrapolate = false;            // refuse outside the data unless true
  bool on_brake = false;               // mean limit BS/5 instead of BS/3

  // Throws InputError naming the field, the value and what is allowed.
  void validate() const;
};

struct NearCase {
  std::int64_t case_id = 0;
  double speed_kt = kNaN, wind_kt = kNaN, hs_ft = kNaN, tp_s = kNaN, heading_deg = kNaN;
  double length_ft = kNaN, mean_tension_lbf = kNaN;
  int days = 0;
  double dynamic_999_kips = kNaN;
  double dynamic_tension_kips = kNaN;  // at the query's p and D
  double distance = kNaN;
};

struct Answer {
  std::string tug, tow;  // the database's names of the vessels matched
  double dynamic_tension_kips = kNaN;
  double dynamic_999_kips = kNaN;
  double mean_tension_lbf = kNaN;
  // EQ-QUERY-9: T_calc at the query's conditions and mean / T_calc (NaN when
  // the database stores no calculated mean tensions).
  double calculated_mean_tension_lbf = kNaN;
  double mean_tension_factor = kNaN;
  double extreme_tension_lbf = kNaN;
  double breaking_strength_lbf = kNaN;
  double extreme_limit_lbf = kNaN;
  double mean_limit_lbf = kNaN;
  bool extreme_check_passed = false;
  bool mean_check_passed = false;
  double gumbel_u_kips = kNaN;
  double gumbel_alpha_per_kip = kNaN;
  double interpolation_error_kips = kNaN;
  double ci_level = kNaN, ci_low_kips = kNaN, ci_high_kips = kNaN;
  double uncertainty_kips = kNaN;
  double slack_fraction = kNaN;
  double catenary_sag_ft = kNaN;
  double catenary_depth_ft = kNaN;  // lowest point below the waterline (negative: above it)
  // EQ-QUERY-10: the wind whose fully developed sea has the asked Hs, when the
  // question gave hs_ft and was answered from wind seas (NaN otherwise).
  double equivalent_wind_kt = kNaN;
  Space space = Space::kLinear;
  bool extrapolated = false;
  std::vector<Warning> warnings;
  std::vector<NearCase> nearest;
};

struct SearchResult {
  bool found = false;
  double value = kNaN;
  double range_low = kNaN, range_high = kNaN;
  int evaluations = 0;
  std::vector<Warning> warnings;
};

struct LooStats {
  Space space = Space::kLinear;
  int axis = kAllAxes;
  int samples = 0;
  double median_rel_error = kNaN, p90_rel_error = kNaN, max_rel_error = kNaN;
  double median_abs_error_kips = kNaN;
};

// EQ-QUERY-10: the wind [kt] whose Pierson-Moskowitz sea has significant height hs_ft.
double equivalent_wind_kt(double hs_ft);

// EQ-QUERY-3: x(p, D) = u + beta (ln D - ln(-ln(1 - p))).
double gumbel_quantile_kips(double u_kips, double beta_kips, double probability, double tow_days);

struct Group;

// A note of the database's builds on what they left out (schema 5
// coverage_notes): a grid's coverage_note, or a condition it could not tow.
struct CoverageNote {
  std::string tug, tow, sweep_label, note;
  bool skipped = false;       // a skipped condition (else a grid note)
  double nominal_speed_kt = kNaN, heading_deg = kNaN;
  std::string sea;
};

class Engine {
 public:
  static Engine open(const std::filesystem::path& path, Space space, QueryOptions options = {});
  Engine(Engine&&) noexcept;
  Engine& operator=(Engine&&) noexcept;
  ~Engine();

  Answer query(const Request& request) const;
  SearchResult max_speed(const Request& request) const;
  SearchResult min_length(const Request& request) const;
  LooStats leave_one_out(Space space, int axis) const;

  Space space() const { return space_; }
  bool log_space_available() const { return log_ok_; }
  int case_count() const { return case_count_; }

 private:
  Engine() = default;
  const Group& find_group(const Request& r) const;
  Request resolve_sea(const Request& r, double* wind_kt) const;
  Answer answer(const Request& asked, const Request& r, const Group& g, double wind_from_hs_kt) const;
  // Why the builds left data out for the group's tug and tow ("" when they say nothing).
  std::string coverage_reason(const Group& g, const Request& r) const;
  SearchResult search(const Request& request, int axis, bool maximise) const;

  std::vector<Group> groups_;
  std::vector<CoverageNote> coverage_;
  Space space_ = Space::kLinear;
  bool log_ok_ = false;
  int case_count_ = 0;
  QueryOptions options_;
};

}  // namespace towdb::query

#endif  // TOWDB_QUERY_SRC_ENGINE_HPP
