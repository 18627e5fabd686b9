// Properties of a query answer, shared by the C API and database fuzzers
// (docs/hardening.md): finite and self-consistent (query.h EQ-QUERY-4, -5).
#ifndef TOWDB_TESTS_FUZZ_FUZZ_QUERY_CHECKS_HPP
#define TOWDB_TESTS_FUZZ_FUZZ_QUERY_CHECKS_HPP

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "towdb/query.h"

namespace towdb::fuzz {

// The properties of an answer (run, or a found search's at_value).
inline std::string check_answer(const towdb_query_db* db, const towdb_query_request& r, const towdb_query_result& a) {
  const std::pair<const char*, double> values[] = {
      {"dynamic_tension_kips", a.dynamic_tension_kips}, {"dynamic_999_kips", a.dynamic_999_kips},
      {"mean_tension_lbf", a.mean_tension_lbf},         {"extreme_tension_lbf", a.extreme_tension_lbf},
      {"gumbel_u_kips", a.gumbel_u_kips},               {"gumbel_alpha_per_kip", a.gumbel_alpha_per_kip},
      {"uncertainty_kips", a.uncertainty_kips},         {"interpolation_error_kips", a.interpolation_error_kips}};
  for (const auto& [name, v] : values) {
    if (!std::isfinite(v)) return std::string("an answer has ") + name + " = " + std::to_string(v);
  }
  if (!(a.mean_tension_lbf > 0.0)) return "an answer has mean_tension_lbf = " + std::to_string(a.mean_tension_lbf);
  if (!(a.breaking_strength_lbf > 0.0)) {
    return "an answer has breaking_strength_lbf = " + std::to_string(a.breaking_strength_lbf);
  }
  if (!(a.gumbel_alpha_per_kip > 0.0)) return "an answer has gumbel_alpha_per_kip = " + std::to_string(a.gumbel_alpha_per_kip);
  if (!(a.uncertainty_kips >= 0.0)) return "an answer has uncertainty_kips = " + std::to_string(a.uncertainty_kips);
  const double extreme = a.mean_tension_lbf + 1000.0 * a.dynamic_tension_kips;
  if (std::abs(extreme - a.extreme_tension_lbf) > 1e-9 * std::max(1.0, std::abs(extreme))) {
    return "extreme_tension_lbf != mean + 1000 dynamic (EQ-QUERY-4)";
  }
  if (a.extreme_limit_lbf != a.breaking_strength_lbf / 1.5 ||
      a.mean_limit_lbf != a.breaking_strength_lbf / (r.on_brake ? 5.0 : 3.0)) {
    return "limits are not BS/1.5 and BS/3 or BS/5 (EQ-QUERY-5)";
  }
  if ((a.extreme_check_passed != 0) != (a.extreme_tension_lbf <= a.extreme_limit_lbf) ||
      (a.mean_check_passed != 0) != (a.mean_tension_lbf <= a.mean_limit_lbf)) {
    return "a check's verdict disagrees with its value and limit";
  }
  if (r.extrapolate == 0 && a.extrapolated != 0) return "extrapolated although not asked";
  for (int i = 0; i < a.warning_count; ++i) {
    int kind = 0;
    const char* w = towdb_query_warning(db, i, &kind);
    if (!w || !*w || kind < TOWDB_QUERY_WARN_EXTRAPOLATED || kind > TOWDB_QUERY_WARN_EQUIVALENT_WIND) {
      return "warning " + std::to_string(i) + " of " + std::to_string(a.warning_count) + " is missing or has no kind";
    }
  }
  if (towdb_query_warning(db, a.warning_count, nullptr) != nullptr) return "more warnings than warning_count";
  towdb_query_case nc{};
  for (int i = 0; i < a.nearest_count; ++i) {
    if (towdb_query_nearest(db, i, &nc) != TOWDB_QUERY_OK) return "nearest case " + std::to_string(i) + " missing";
  }
  if (towdb_query_nearest(db, a.nearest_count, &nc) != TOWDB_QUERY_MISUSE) return "more nearest cases than counted";
  const char *tug = nullptr, *tow = nullptr;
  if (towdb_query_names(db, &tug, &tow) != TOWDB_QUERY_OK || !*tug || !*tow) return "no names for an answer";
  return "";
}

}  // namespace towdb::fuzz

#endif  // TOWDB_TESTS_FUZZ_FUZZ_QUERY_CHECKS_HPP
