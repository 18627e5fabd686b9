// Small towdb databases for the query tests, written through store::Database
// (Mode::kCreate). Cases carry Gumbel parameters from a known analytic
// function of the inputs, so interpolation errors can be asserted exactly.
#ifndef TOWDB_TESTS_QUERY_SYNTHETIC_DB_HPP
#define TOWDB_TESTS_QUERY_SYNTHETIC_DB_HPP

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/constants.hpp"
#include "store/database.hpp"
#include "store/packed_days.hpp"

namespace towdb::test {

inline constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

struct SyntheticCase {
  std::int64_t case_id = 0;  // 0: assigned by SQLite
  std::string tug = "T-ATF 166", tow = "LHA 1", line = "wire";
  std::string spectrum = "pierson-moskowitz";
  double speed_kt = 5.0, wind_kt = 20.0, hs_ft = kNoValue, tp_s = kNoValue;
  double heading_deg = 0.0, length_ft = 2000.0, mean_tension_lbf = 60000.0;
  double calculated_mean_tension_lbf = kNoValue;  // NaN: NULL (no EQ-QUERY-9 axis)
  int days = 500;
  double u_kips = 50.0, alpha_per_kip = 0.2;
  double ci_level = 0.9, ci_low_kips = kNoValue, ci_high_kips = kNoValue;  // NaN: +-5 % of dynamic_999
  double breaking_strength_lbf = 360000.0;
  double slack_fraction = 0.0;
  double sag_ft = kNoValue;  // NaN: no towline_fits row (fit_id NULL)
  double lowest_elevation_ft = kNoValue;  // NaN: NULL (a fit stored before schema 6)
  std::string status = "done";
};

// -ln(-ln(0.999)): the Gumbel reduced variate of the database value.
inline double reduced_variate_999() { return -std::log(-std::log(0.999)); }

inline void write_synthetic_db(const std::filesystem::path& path, const std::vector<SyntheticCase>& cases) {
  auto db = store::Database::open(path, store::Database::Mode::kCreate);
  db.transaction([&] {
    auto ins_case = db.prepare(
        "INSERT INTO cases (case_id, case_key, inputs_sha256, tug_name, tow_name, speed_kt, spectrum, wind_kt, hs_ft, "
        "tp_s, heading_deg, line_type, length_ft, mean_tension_lbf, days, seed, status, calculated_mean_tension_lbf) "
        "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18)");
    auto ins_result = db.prepare(
        "INSERT INTO results (case_id, gumbel_u_kips, gumbel_alpha_per_kip, daily_max_mean_kips, "
        "daily_max_variance_kips2, dynamic_999_kips, dynamic_99_kips, ci_level, ci_low_kips, ci_high_kips, "
        "max_daily_max_kips, breaking_strength_lbf, above_breaking_strength, slack_fraction, snatch_events_per_day, "
        "runtime_s, code_version) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17)");
    // A fit row carries only what the query reads (sag, lowest point); the rest is 0.
    auto ins_fit = db.prepare(
        "INSERT INTO towline_fits (fit_key, tug_name, line_type, length_ft, mean_tension_lbf, towline_model, span_ft, "
        "sag_ft, end_angle_tug_deg, end_angle_tow_deg, static_stiffness_lbf_per_ft, breaking_strength_lbf, "
        "a10_lbf_per_ft, a01_lbf_s_per_ft, a20_lbf_per_ft2, a11_lbf_s_per_ft2, a02_lbf_s2_per_ft2, a30_lbf_per_ft3, "
        "a21_lbf_s_per_ft3, a12_lbf_s2_per_ft3, a03_lbf_s3_per_ft3, fit_rms_lbf, fit_max_error_lbf, fit_samples, "
        "lowest_elevation_ft) VALUES (?1, ?2, ?3, ?4, ?5, 'test', 0, ?6, 0, 0, 0, ?7, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, "
        "0, ?8)");
    auto set_fit = db.prepare("UPDATE cases SET fit_id = ?1 WHERE case_id = ?2");
    int k = 0;
    for (const SyntheticCase& c : cases) {
      ++k;
      auto opt = [](double v) { return std::isnan(v) ? std::optional<double>() : std::optional<double>(v); };
      if (c.case_id > 0) {
        ins_case.bind(1, c.case_id);
      } else {
        ins_case.bind_null(1);
      }
      ins_case.bind(2, "key-" + std::to_string(k))
          .bind(3, "sha-" + std::to_string(k))
          .bind(4, c.tug)
          .bind(5, c.tow)
          .bind(6, c.speed_kt)
          .bind(7, c.spectrum)
          .bind(8, opt(c.wind_kt))
          .bind(9, opt(c.hs_ft))
          .bind(10, opt(c.tp_s))
          .bind(11, c.heading_deg)
          .bind(12, c.line)
          .bind(13, c.length_ft)
          .bind(14, c.mean_tension_lbf)
          .bind(15, c.days)
          .bind(16, k)
          .bind(17, c.status)
          .bind(18, opt(c.calculated_mean_tension_lbf));
      ins_case.run();
      if (c.status != "done") continue;
      const std::int64_t id = db.last_insert_rowid();
      if (!std::isnan(c.sag_ft)) {
        ins_fit.bind(1, "fit-" + std::to_string(k))
            .bind(2, c.tug)
            .bind(3, c.line)
            .bind(4, c.length_ft)
            .bind(5, c.mean_tension_lbf)
            .bind(6, c.sag_ft)
            .bind(7, c.breaking_strength_lbf)
            .bind(8, opt(c.lowest_elevation_ft));
        ins_fit.run();
        set_fit.bind(1, db.last_insert_rowid()).bind(2, id);
        set_fit.run();
      }
      const double beta = 1.0 / c.alpha_per_kip;
      const double x999 = c.u_kips + beta * reduced_variate_999();
      const double x99 = c.u_kips - beta * std::log(-std::log(0.99));
      const double mean = c.u_kips + kEulerGamma * beta;
      const double var = std::pow(kPi * beta, 2) / 6.0;
      const double lo = std::isnan(c.ci_low_kips) ? 0.95 * x999 : c.ci_low_kips;
      const double hi = std::isnan(c.ci_high_kips) ? 1.05 * x999 : c.ci_high_kips;
      const bool above = c.mean_tension_lbf + 1000.0 * x999 > c.breaking_strength_lbf;
      ins_result.bind(1, id)
          .bind(2, c.u_kips)
          .bind(3, c.alpha_per_kip)
          .bind(4, mean)
          .bind(5, var)
          .bind(6, x999)
          .bind(7, x99)
          .bind(8, c.ci_level)
          .bind(9, lo)
          .bind(10, hi)
          .bind(11, x999)
          .bind(12, c.breaking_strength_lbf)
          .bind(13, above ? 1 : 0)
          .bind(14, c.slack_fraction)
          .bind(15, 0.0)
          .bind(16, 1.0)
          .bind(17, "test");
      ins_result.run();
    }
  });
}

// Heading profiles (schema 10, query.h EQ-QUERY-11): one heading_profiles row
// per line (speed, wind, length, mean tension) holding `sigma_kips` on the
// 0, 2.5, ..., deg grid, and every case pointed at its line's; the case with
// id `skip` (0: none) is left without one.
inline void write_heading_profiles(const std::filesystem::path& path, const std::vector<double>& sigma_kips,
                                   std::int64_t skip = 0) {
  auto db = store::Database::open(path, store::Database::Mode::kReadWrite);
  db.transaction([&] {
    auto lines = db.prepare(
        "SELECT DISTINCT speed_kt, wind_kt, length_ft, mean_tension_lbf FROM cases ORDER BY 1, 2, 3, 4");
    auto insert = db.prepare(
        "INSERT INTO heading_profiles (profile_key, mean_tension_lbf, heading_first_deg, heading_step_deg, headings, "
        "sigma_kips_f32) VALUES (?, ?, 0, 2.5, ?, ?)");
    auto point = db.prepare(
        "UPDATE cases SET profile_id = ? WHERE speed_kt = ? AND wind_kt = ? AND length_ft = ? AND "
        "mean_tension_lbf = ? AND case_id != ?");
    int k = 0;
    while (lines.step()) {
      const double s = lines.column_double(0), w = lines.column_double(1), l = lines.column_double(2);
      const double m = lines.column_double(3);
      insert.reset();
      insert.bind(1, "profile-" + std::to_string(++k))
          .bind(2, m)
          .bind(3, static_cast<std::int64_t>(sigma_kips.size()))
          .bind_blob(4, store::pack_float32(sigma_kips));
      insert.run();
      point.reset();
      point.bind(1, db.last_insert_rowid()).bind(2, s).bind(3, w).bind(4, l).bind(5, m).bind(6, skip);
      point.run();
    }
  });
}

// Speed profiles (schema 11, query.h EQ-QUERY-12): one speed_profiles row per
// line (wind, heading, length) holding `sigma_kips` (binary16) on the grid
// first_kt, first_kt + step_kt, ..., and every case pointed at its line's.
inline void write_speed_profiles(const std::filesystem::path& path, const std::vector<double>& sigma_kips,
                                 double first_kt, double step_kt) {
  auto db = store::Database::open(path, store::Database::Mode::kReadWrite);
  std::string packed;
  if (!store::pack_float16(sigma_kips, &packed)) throw std::runtime_error("speed profile does not fit binary16");
  db.transaction([&] {
    auto lines = db.prepare("SELECT DISTINCT wind_kt, heading_deg, length_ft FROM cases ORDER BY 1, 2, 3");
    auto insert = db.prepare(
        "INSERT INTO speed_profiles (profile_key, speed_first_kt, speed_step_kt, speeds, sigma_kips_f16) "
        "VALUES (?, ?, ?, ?, ?)");
    auto point = db.prepare(
        "UPDATE cases SET speed_profile_id = ? WHERE wind_kt = ? AND heading_deg = ? AND length_ft = ?");
    while (lines.step()) {
      insert.reset();
      insert.bind_blob(1, std::string(32, 'k'))
          .bind(2, first_kt)
          .bind(3, step_kt)
          .bind(4, static_cast<std::int64_t>(sigma_kips.size()))
          .bind_blob(5, packed);
      insert.run();
      point.reset();
      point.bind(1, db.last_insert_rowid())
          .bind(2, lines.column_double(0))
          .bind(3, lines.column_double(1))
          .bind(4, lines.column_double(2));
      point.run();
    }
  });
}

// A full grid over speed, wind, heading and length for one tug/tow/line,
// with 2-4 mean tensions per node (their own values, as in the thesis: the
// node's "calculated" mean tension times the factors below, with a count that
// varies from node to node). u and beta come from the given functions.
struct GridSpec {
  std::vector<double> speeds_kt = {3.0, 5.0, 7.0, 9.0};
  std::vector<double> winds_kt = {20.0, 30.0, 35.0};
  std::vector<double> headings_deg = {0.0, 60.0, 120.0, 180.0};
  std::vector<double> lengths_ft = {800.0, 1500.0, 2000.0};
  std::string tug = "T-ATF 166", tow = "LHA 1", line = "wire";
  double breaking_strength_lbf = 360000.0;
  // Node mean tension before the factors [lbf], e.g. rising with speed.
  std::function<double(double speed_kt, double wind_kt)> nominal_mean_lbf = [](double s, double w) {
    return 30000.0 + 6000.0 * s + 500.0 * w;
  };
  // Store the nominal mean tension as each case's calculated one (EQ-QUERY-9).
  bool store_calculated = false;
  std::function<double(double s, double w, double h, double l, double m)> u_kips;
  std::function<double(double s, double w, double h, double l, double m)> beta_kips;
};

// The factors applied to a node's nominal mean tension: 2, 3 or 4 of them.
inline std::vector<double> mean_factors(int node_number) {
  switch (node_number % 3) {
    case 0: return {0.6, 1.0, 1.15};
    case 1: return {0.6, 1.15};
    default: return {0.6, 0.85, 1.0, 1.15};
  }
}

inline std::vector<SyntheticCase> grid_cases(const GridSpec& g) {
  std::vector<SyntheticCase> out;
  int node = 0;
  for (double s : g.speeds_kt) {
    for (double w : g.winds_kt) {
      for (double h : g.headings_deg) {
        for (double l : g.lengths_ft) {
          for (double f : mean_factors(node)) {
            SyntheticCase c;
            c.tug = g.tug;
            c.tow = g.tow;
            c.line = g.line;
            c.speed_kt = s;
            c.wind_kt = w;
            c.heading_deg = h;
            c.length_ft = l;
            c.mean_tension_lbf = f * g.nominal_mean_lbf(s, w);
            if (g.store_calculated) c.calculated_mean_tension_lbf = g.nominal_mean_lbf(s, w);
            c.u_kips = g.u_kips(s, w, h, l, c.mean_tension_lbf);
            c.alpha_per_kip = 1.0 / g.beta_kips(s, w, h, l, c.mean_tension_lbf);
            c.breaking_strength_lbf = g.breaking_strength_lbf;
            out.push_back(c);
          }
          ++node;
        }
      }
    }
  }
  return out;
}

}  // namespace towdb::test

#endif  // TOWDB_TESTS_QUERY_SYNTHETIC_DB_HPP
