// Query throughput (Google Benchmark): interpolated queries per second through
// the C API on one core. Target (issue "Query engine for tow planners"):
// >= 100,000 queries/s. The database is synthetic, thesis-sized: 4 speeds x
// 3 winds x 7 headings x 4 lengths x 2-4 mean tensions = 1008 cases (with and
// without heading and speed profiles), with
// Gumbel parameters from exp(linear) functions (tests/query/synthetic_db.hpp).
// The sum of the answers is printed as a counter ("checksum") so that two
// builds can be compared for identical results (after SQLite's speedtest1).
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <unistd.h>

#include "synthetic_db.hpp"
#include "towdb/query.h"

namespace {

struct Fixture {
  std::filesystem::path path;
  towdb_query_db* db = nullptr;
  std::vector<towdb_query_request> requests;

  // relative: every case stores its node's calculated mean tension and the
  // questions ask at the default, factor 1 of it (query.h EQ-QUERY-9).
  // profiles: every line also has a heading profile (EQ-QUERY-11) and a speed
  // profile (EQ-QUERY-12), as in the bundled database.
  Fixture(bool relative, bool profiles) {
    path = std::filesystem::temp_directory_path() /
           ("towdb-bench-" + std::to_string(::getpid()) + (relative ? "-relative" : "") +
            (profiles ? "-profiles" : "") + ".towdb");
    std::filesystem::remove(path);
    towdb::test::GridSpec g;
    g.headings_deg = {0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0};
    g.lengths_ft = {800.0, 1000.0, 1500.0, 2000.0};
    g.u_kips = [](double s, double w, double h, double l, double m) {
      return 40.0 * std::exp(0.05 * s + 0.03 * w - 0.0005 * l + 0.002 * h + 5e-6 * m);
    };
    g.beta_kips = [](double, double w, double, double, double m) { return 8.0 * std::exp(0.02 * w + 3e-6 * m); };
    g.store_calculated = relative;
    towdb::test::write_synthetic_db(path, towdb::test::grid_cases(g));
    if (profiles) {
      std::vector<double> sigma;
      for (int j = 0; j < 73; ++j) sigma.push_back(10.0 - 8.0 * std::cos((2.5 * j - 84.0) * 3.14159265358979 / 30.0));
      towdb::test::write_heading_profiles(path, sigma);
      std::vector<double> by_speed;  // 3 to 9 kt every 0.25 kt
      for (int j = 0; j < 25; ++j) by_speed.push_back(10.0 - 8.0 * std::cos((0.25 * j - 3.1) * 3.14159265358979 / 0.6));
      towdb::test::write_speed_profiles(path, by_speed, 3.0, 0.25);
    }
    if (towdb_query_open(path.c_str(), TOWDB_QUERY_SPACE_AUTO, &db) != TOWDB_QUERY_OK) std::abort();
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> us(3.0, 9.0), uw(20.0, 35.0), uh(0.0, 360.0), ul(800.0, 2000.0);
    for (int i = 0; i < 4096; ++i) {
      towdb_query_request r;
      towdb_query_request_init(&r);
      r.tug = "T-ATF 166";
      r.tow = "LHA 1";
      r.line = "wire";
      r.speed_kt = us(rng);
      r.wind_kt = uw(rng);
      r.heading_deg = uh(rng);
      r.length_ft = ul(rng);
      // Absolute: inside every node's stored mean tensions (60,900 to 66,700 lbf).
      r.mean_tension_lbf = relative ? std::numeric_limits<double>::quiet_NaN() : 63000.0;
      requests.push_back(r);
    }
  }
  ~Fixture() {
    towdb_query_close(db);
    std::filesystem::remove(path);
  }
};

// kind: 0 absolute mean-tension axis at a given tension, 1 the relative axis
// (EQ-QUERY-9) at the default calculated tension, 2 the same with heading and
// speed profiles (EQ-QUERY-11, 12).
Fixture& fixture(int kind) {
  static Fixture absolute_fixture(false, false);
  static Fixture relative_fixture(true, false);
  static Fixture profiles_fixture(true, true);
  return kind == 0 ? absolute_fixture : kind == 1 ? relative_fixture : profiles_fixture;
}

// state.range(0): the fixture's kind (above).
void BM_InterpolatedQuery(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)));
  towdb_query_result res;
  std::size_t i = 0;
  double checksum = 0.0;
  for (auto _ : state) {
    const int rc = towdb_query_run(f.db, &f.requests[i++ & 4095], &res);
    if (rc != TOWDB_QUERY_OK) state.SkipWithError(towdb_query_errmsg(f.db));
    checksum += res.dynamic_tension_kips;
    benchmark::DoNotOptimize(res);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["checksum"] = checksum / static_cast<double>(state.iterations());
}
BENCHMARK(BM_InterpolatedQuery)->Arg(0)->Arg(1)->Arg(2);

void BM_OpenDatabase(benchmark::State& state) {
  Fixture& f = fixture(0);
  for (auto _ : state) {
    towdb_query_db* db = nullptr;
    if (towdb_query_open(f.path.c_str(), TOWDB_QUERY_SPACE_AUTO, &db) != TOWDB_QUERY_OK) state.SkipWithError("open");
    towdb_query_close(db);
  }
}
BENCHMARK(BM_OpenDatabase)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
