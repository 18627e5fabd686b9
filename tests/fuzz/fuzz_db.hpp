// The database the query fuzzers run against, written through the query
// tests' synthetic writer (tests/query/synthetic_db.hpp): three groups that
// cover the engine's loading paths.
//   A  T-ATF 166 / LHA 1 / wire, wind seas, calculated mean tension stored
//      (EQ-QUERY-9 relative axis), towline fits with a sag;
//   B  ARS 50 / FFG 7 / fiber, wind seas, absolute mean-tension axis;
//   C  ARS 50 / LHA 1 / wire, JONSWAP seas on Hs and Tp axes.
// `small` keeps one or two values per axis (a ~100 kB file for byte flips).
#ifndef TOWDB_TESTS_FUZZ_FUZZ_DB_HPP
#define TOWDB_TESTS_FUZZ_FUZZ_DB_HPP

#include <filesystem>
#include <vector>

#include "synthetic_db.hpp"

namespace towdb::fuzz {

inline std::vector<test::SyntheticCase> fuzz_db_cases(bool small) {
  using test::GridSpec;
  using test::SyntheticCase;
  auto u = [](double s, double w, double h, double l, double m) {
    return 20.0 + 3.0 * s + 0.5 * w + 0.05 * h - 0.005 * l + 0.0002 * m;
  };
  auto beta = [](double, double w, double, double, double) { return 5.0 + 0.1 * w; };
  GridSpec a;
  a.speeds_kt = small ? std::vector<double>{5.0, 7.0} : std::vector<double>{5.0, 7.0, 9.0};
  a.winds_kt = small ? std::vector<double>{20.0, 30.0} : std::vector<double>{20.0, 30.0, 35.0};
  a.headings_deg = small ? std::vector<double>{0.0, 180.0} : std::vector<double>{0.0, 90.0, 180.0};
  a.lengths_ft = {1000.0, 2000.0};
  a.store_calculated = true;
  a.u_kips = u;
  a.beta_kips = beta;
  std::vector<SyntheticCase> out = test::grid_cases(a);
  for (SyntheticCase& c : out) c.sag_ft = 10.0 + 0.01 * c.length_ft;

  GridSpec b = a;
  b.tug = "ARS 50";
  b.tow = "FFG 7";
  b.line = "fiber";
  b.store_calculated = false;
  b.speeds_kt = {5.0, 9.0};
  b.winds_kt = {20.0, 35.0};
  b.headings_deg = {0.0, 180.0};
  b.lengths_ft = small ? std::vector<double>{800.0} : std::vector<double>{800.0, 1500.0};
  b.breaking_strength_lbf = 400000.0;
  for (const SyntheticCase& c : test::grid_cases(b)) out.push_back(c);

  for (double hs : small ? std::vector<double>{8.0, 16.0} : std::vector<double>{8.0, 12.0, 16.0}) {
    for (double tp : {8.0, 10.0}) {
      for (double h : {0.0, 180.0}) {
        for (double m : {50000.0, 70000.0}) {
          SyntheticCase c;
          c.tug = "ARS 50";
          c.tow = "LHA 1";
          c.spectrum = "jonswap";
          c.wind_kt = test::kNoValue;
          c.hs_ft = hs;
          c.tp_s = tp;
          c.heading_deg = h;
          c.length_ft = 1500.0;
          c.mean_tension_lbf = m;
          c.u_kips = 10.0 + 4.0 * hs + 0.5 * tp + 0.02 * h + 0.0001 * m;
          c.alpha_per_kip = 1.0 / (4.0 + 0.2 * hs);
          out.push_back(c);
        }
      }
    }
  }
  return out;
}

inline void write_fuzz_db(const std::filesystem::path& path, bool small) {
  test::write_synthetic_db(path, fuzz_db_cases(small));
}

}  // namespace towdb::fuzz

#endif  // TOWDB_TESTS_FUZZ_FUZZ_DB_HPP
