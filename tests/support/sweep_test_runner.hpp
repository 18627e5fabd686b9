// Test-only case runner and database comparison for the sweep tests (the
// production runner is the simulation chain, registered by the CLI).
//
// The runner is a small closed-form model, deterministic and cheap:
//   - towline fit: the straight elastic line, k = 1 / sum_i L_i/(EA)_i (the
//     towline's series compliance), a10 = k, every other coefficient 0,
//     span = total length, sag = 0, breaking strength of the weakest segment;
//   - daily maxima: Gumbel samples x_d = u0 - ln(-ln U_d) / alpha0 with U_d the
//     first uniform of RandomStream(seed, d), u0 = 0.2 T_mean (1 + U_wind/40 kt)
//     (1 + |cos mu|) and 1/alpha0 = 0.1 u0;
//   - statistics: the thesis's Type I by the method of moments
//     (statistics::fit_gumbel_moments), x_F at F = 0.999 and 0.99.
// So every stored number is reproducible and checkable, and the runner can be
// told to sleep, to throw, or to return a NaN for chosen cases.
#ifndef TOWDB_TESTS_SUPPORT_SWEEP_TEST_RUNNER_HPP
#define TOWDB_TESTS_SUPPORT_SWEEP_TEST_RUNNER_HPP

#include <sqlite3.h>

#include <bit>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "common/error.hpp"
#include "common/random.hpp"
#include "statistics/fit.hpp"
#include "sweep/spec/case.hpp"

namespace towdb::test {

struct TestRunnerOptions {
  int sleep_ms = 0;                                       // per case, to be killed mid-build
  std::function<bool(const sweep::CaseSpec&)> fail_when;  // throw NumericalError for these
  std::function<bool(const sweep::CaseSpec&)> nan_when;   // return a NaN statistic for these
};

inline TestRunnerOptions sleeping(int ms) {
  TestRunnerOptions o;
  o.sleep_ms = ms;
  return o;
}

// Submerged weight per length of the closed-form outcome's line [N/m].
inline constexpr double kTestLineWeightNPerM = 100.0;

inline sweep::CaseOutcome closed_form_outcome(const sweep::CaseSpec& spec, const io::ShipCatalog& catalog) {
  const model::Vessel& tug = catalog.vessel(spec.tug).vessel;
  const model::Towline line = catalog.towline(tug, spec.line, spec.length_m());
  sweep::CaseOutcome o;
  const double k_n_per_m = 1.0 / line.axial_compliance_m_per_n();
  o.fit.span_m = line.total_length_m();
  // A shallow parabola of a 100 N/m line hanging between the two tow points
  // (sag = w X^2 / (8 H)): known values for the query's sag and depth tests.
  o.fit.sag_m = kTestLineWeightNPerM * o.fit.span_m * o.fit.span_m / (8.0 * spec.mean_tension_n());
  o.fit.lowest_elevation_m =
      0.5 * (tug.tow_point.z_m + catalog.vessel(spec.tow).vessel.tow_point.z_m) - o.fit.sag_m;
  o.fit.static_stiffness_n_per_m = k_n_per_m;
  o.fit.breaking_strength_n = line.breaking_strength_n();
  o.fit.coefficients_si[0] = k_n_per_m;
  o.fit.fit_samples = 56;  // thesis: 56 prescribed extensions
  const double wind_kt = spec.sea.wind_kt.value_or(0.0);
  const double u0_n = 0.2 * spec.mean_tension_n() * (1.0 + wind_kt / 40.0) * (1.0 + std::abs(std::cos(spec.heading_rad())));
  const double scale_n = 0.1 * u0_n;
  std::vector<double> maxima;
  for (int d = 0; d < spec.days; ++d) {
    RandomStream rng(static_cast<std::uint64_t>(spec.seed), static_cast<std::uint64_t>(d));
    const double x = u0_n - scale_n * std::log(-std::log(rng.uniform_open01()));
    maxima.push_back(x);
    o.days.push_back({x, 0.0, 0});
  }
  const statistics::Gumbel g = statistics::fit_gumbel_moments(maxima);
  double mean = 0.0, max_n = maxima.front();
  for (double x : maxima) {
    mean += x;
    max_n = std::max(max_n, x);
  }
  mean /= static_cast<double>(maxima.size());
  double var = 0.0;
  for (double x : maxima) var += (x - mean) * (x - mean);
  var /= static_cast<double>(maxima.size() - 1);
  sweep::CaseStatistics& s = o.statistics;
  s.gumbel_u_n = g.location;
  s.gumbel_alpha_per_n = g.alpha();
  s.daily_max_mean_n = mean;
  s.daily_max_variance_n2 = var;
  s.dynamic_999_n = g.quantile(0.999);
  s.dynamic_99_n = g.quantile(0.99);
  s.ci_level = 0.9;
  s.ci_low_n = 0.95 * s.dynamic_999_n;
  s.ci_high_n = 1.05 * s.dynamic_999_n;
  s.max_daily_max_n = max_n;
  s.breaking_strength_n = line.breaking_strength_n();
  s.above_breaking_strength = spec.mean_tension_n() + s.dynamic_999_n > s.breaking_strength_n;
  return o;
}

inline sweep::CaseRunner make_test_runner(TestRunnerOptions options = {}) {
  return [options](const sweep::CaseSpec& spec, const io::ShipCatalog& catalog) {
    if (options.sleep_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(options.sleep_ms));
    if (options.fail_when && options.fail_when(spec)) {
      throw NumericalError("test runner: catenary solver did not converge (iteration 50, residual 3.5e-2)");
    }
    sweep::CaseOutcome o = closed_form_outcome(spec, catalog);
    if (options.nan_when && options.nan_when(spec)) o.statistics.dynamic_999_n = std::nan("");
    return o;
  };
}

// Every row of every table as text, REAL values as their 64 bits in hex, in
// primary-key order; `excluded` columns ("table.column") are left out.
inline std::string dump_database(const std::filesystem::path& path, const std::set<std::string>& excluded) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    return "cannot open " + path.string();
  }
  std::string out;
  for (const char* table :
       {"vessels", "towline_components", "towline_fits", "cases", "results", "case_days", "heading_profiles",
        "speed_profiles"}) {
    const std::string order = "1";
    const std::string sql = std::string("SELECT * FROM ") + table + " ORDER BY " + order;
    sqlite3_stmt* st = nullptr;
    sqlite3_prepare_v2(db, sql.c_str(), -1, &st, nullptr);
    out += std::string("[") + table + "]\n";
    while (sqlite3_step(st) == SQLITE_ROW) {
      for (int c = 0; c < sqlite3_column_count(st); ++c) {
        const std::string name = std::string(table) + "." + sqlite3_column_name(st, c);
        if (excluded.count(name)) continue;
        out += name.substr(name.find('.') + 1) + "=";
        switch (sqlite3_column_type(st, c)) {
          case SQLITE_NULL: out += "NULL"; break;
          case SQLITE_INTEGER: out += std::to_string(sqlite3_column_int64(st, c)); break;
          case SQLITE_FLOAT: {
            char hex[32];
            std::snprintf(hex, sizeof hex, "%016" PRIx64,
                          std::bit_cast<std::uint64_t>(sqlite3_column_double(st, c)));
            out += hex;
            break;
          }
          case SQLITE_BLOB: {
            const auto* p = static_cast<const unsigned char*>(sqlite3_column_blob(st, c));
            for (int b = 0; b < sqlite3_column_bytes(st, c); ++b) {
              char hex[3];
              std::snprintf(hex, sizeof hex, "%02x", p[b]);
              out += hex;
            }
            break;
          }
          default: out += reinterpret_cast<const char*>(sqlite3_column_text(st, c)); break;
        }
        out += " ";
      }
      out += "\n";
    }
    sqlite3_finalize(st);
  }
  sqlite3_close(db);
  return out;
}

// The provenance columns that legitimately differ between equivalent builds
// (sweep.hpp EQ-SWEEP-7): build ids and times, wall-clock run time.
inline const std::set<std::string>& provenance_columns() {
  static const std::set<std::string> kColumns = {"cases.build_id", "cases.updated_utc", "results.runtime_s",
                                                 "vessels.file_path", "towline_components.file_path",
                                                 "heading_profiles.build_id", "speed_profiles.build_id"};
  return kColumns;
}

// A single integer from a SQL query (read-only connection), or -1.
inline std::int64_t query_int(const std::filesystem::path& path, const std::string& sql) {
  sqlite3* db = nullptr;
  std::int64_t v = -1;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_busy_timeout(db, 2000);
    sqlite3_stmt* st = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &st, nullptr) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW) {
      v = sqlite3_column_int64(st, 0);
    }
    sqlite3_finalize(st);
  }
  sqlite3_close(db);
  return v;
}

// A small sweep over the bundled ships: 16 grid cases and 2 explicit ones.
inline const char* kSmallSweepToml = R"(format = "towdb-sweep-1"
description = "test sweep"

[defaults]
days = 30
base_seed = 7

[[grid]]
label = "small-grid"
tugs = ["T-ATF 166"]
tows = ["FFG 7", "YRBM"]
speeds_kt = [5.0]
winds_kt = [20.0]
headings_deg = [0.0, 180.0]
towlines = [ { line = "wire", length_ft = 1000.0 }, { line = "fiber", length_ft = 800.0 } ]
mean_tensions = [
  { label = "calculated+15%", basis = "calculated", factor = 1.15 },
  { label = "hull+half-propeller", basis = "hull+half-propeller" },
]

[[case]]
label = "explicit-1"
tug = "ARS 50"
tow = "AE 26"
speed_kt = 5.0
wind_kt = 30.0
heading_deg = 60.0
line = "wire"
length_ft = 2000.0
mean_tension_lbf = 84000.0
days = 40

[[case]]
label = "explicit-2"
tug = "ARS 50"
tow = "CG 47"
speed_kt = 6.0
spectrum = "jonswap"
hs_ft = 12.0
tp_s = 9.0
gamma = 3.3
swell_hs_ft = 5.0
swell_tp_s = 14.0
swell_heading_deg = 90.0
heading_deg = 120.0
line = "fiber"
length_ft = 1500.0
mean_tension_lbf = 60000.0
seed = 42
)";

}  // namespace towdb::test

#endif  // TOWDB_TESTS_SUPPORT_SWEEP_TEST_RUNNER_HPP
