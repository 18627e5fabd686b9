// Benchmarks of every stage of the physics chain (issue "Validation ... and
// the benchmark suite", item 4), on the bundled T-ATF 166 towing FFG 7 with
// 2,000 ft of wire at 50,000 lbf, 9 kt, 20 kt wind, following seas.
// Each benchmark also prints a value of its result as a counter, so a run
// shows that the work was done (after SQLite's speedtest1 --verify).
#include <array>
#include <vector>

#include <benchmark/benchmark.h>

#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "seakeeping/seakeeping.hpp"
#include "simulation/case_runner.hpp"
#include "statistics/fit.hpp"
#include "towline/catenary.hpp"
#include "towline/towline.hpp"

namespace {

using namespace towdb;

struct Fixture {
  io::ShipCatalog catalog = io::ShipCatalog::load(io::default_ships_dir());
  const model::Vessel& tug = catalog.vessel("T-ATF").vessel;
  const model::Vessel& tow = catalog.vessel("FFG7").vessel;
  model::Towline line = catalog.towline(tug, model::LineKind::kWire, units::ft_to_m(2000.0));
  towline::TowPoints points{tug.tow_point.z_m, tow.tow_point.z_m};
  double mean_n = units::lbf_to_n(50000.0);

  simulation::CaseInputs inputs() const {
    simulation::CaseInputs in;
    in.tug = &tug;
    in.tow = &tow;
    in.towline = line;
    in.speed_m_s = units::kt_to_m_s(9.0);
    in.sea = sea::single_system(sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(20.0)), 0.0);
    in.mean_tension_n = mean_n;
    in.days = 500;
    in.seed = 1;
    return in;
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_Catenary(benchmark::State& state) {
  const Fixture& f = fixture();
  double span = 0.0;
  for (auto _ : state) {
    const auto c = towline::Catenary::solve(f.line, f.points, f.mean_n);
    benchmark::DoNotOptimize(&c);
    span = c.span_m();
  }
  state.counters["span_ft"] = units::m_to_ft(span);
}
BENCHMARK(BM_Catenary)->Unit(benchmark::kMicrosecond);

void BM_TowlineFit(benchmark::State& state) {
  const Fixture& f = fixture();
  towline::TowlineFitOptions o;
  o.num_threads = 1;
  double a10 = 0.0;
  for (auto _ : state) {
    const auto fit = towline::build_towline_fit(f.line, f.points, f.mean_n, o);
    a10 = fit->coefficients().a10();
  }
  state.counters["a10_lbf_per_ft"] = units::n_per_m_to_lbf_per_ft(a10);
}
BENCHMARK(BM_TowlineFit)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_StripTheoryPerFrequency(benchmark::State& state) {
  const Fixture& f = fixture();
  double heave = 0.0;
  for (auto _ : state) {
    const auto r = seakeeping::compute_response(f.tow, units::kt_to_m_s(9.0), 3.14159, {0.8});
    heave = std::abs(r[0].rao[2]);
  }
  state.counters["heave_rao"] = heave;
}
BENCHMARK(BM_StripTheoryPerFrequency)->Unit(benchmark::kMillisecond);

std::shared_ptr<const simulation::CaseModel> prepared() {
  static const auto m = [] {
    simulation::CaseOptions o;
    return simulation::prepare_case(fixture().inputs(), o);
  }();
  return m;
}

void BM_DaySynthesis(benchmark::State& state) {
  const auto m = prepared();
  std::uint64_t day = 0;
  std::size_t n = 0;
  for (auto _ : state) {
    const auto forcing = simulation::day_forcing(*m, 1, day++);
    n = forcing.size();
  }
  state.counters["samples"] = static_cast<double>(n);
}
BENCHMARK(BM_DaySynthesis)->Unit(benchmark::kMillisecond);

void BM_DayIntegration(benchmark::State& state) {
  const auto m = prepared();
  const auto forcing = simulation::day_forcing(*m, 1, 0);
  double max_kips = 0.0;
  long substeps = 0;
  for (auto _ : state) {
    const auto s = simulation::simulate_day(*m, forcing, simulation::IntegratorOptions{});
    max_kips = units::n_to_kips(s.max_tension_n);
    substeps = s.substeps;
  }
  state.counters["max_kips"] = max_kips;
  state.counters["substeps"] = static_cast<double>(substeps);
}
BENCHMARK(BM_DayIntegration)->Unit(benchmark::kMillisecond);

// What run_case does: kLockstepDays days integrated together; the time is per
// group, items/s counts days. Argument: the vectors (0 = baseline SSE2,
// 1 = AVX2; skipped where the processor lacks AVX2).
void BM_DayIntegrationLockStep(benchmark::State& state) {
  const auto isa = state.range(0) == 0 ? simulation::LaneIsa::kBaseline : simulation::LaneIsa::kAvx2;
  if (isa != simulation::LaneIsa::kBaseline && simulation::fastest_lane_isa() != isa) {
    state.SkipWithError("this processor lacks AVX2");
    return;
  }
  const auto m = prepared();
  simulation::LockstepForcing<simulation::kLockstepDays> days;
  for (std::size_t l = 0; l < simulation::kLockstepDays; ++l) {
    const simulation::DayForcing day = simulation::day_forcing(*m, 1, l);
    days.dt_s = day.dt_s;
    days.resize(day.size());
    days.set_day(l, day);
  }
  double max_kips = 0.0;
  for (auto _ : state) {
    const auto s = simulation::simulate_days(*m, days, simulation::IntegratorOptions{}, isa);
    max_kips = units::n_to_kips(s[0].max_tension_n);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(simulation::kLockstepDays));
  state.counters["max_kips_day0"] = max_kips;
  state.SetLabel(simulation::lane_isa_name(isa));
}
BENCHMARK(BM_DayIntegrationLockStep)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_GumbelFit500(benchmark::State& state) {
  std::vector<double> x;
  for (int i = 0; i < 500; ++i) x.push_back(40.0 + 3.0 * std::sin(0.37 * i) + 0.01 * i);
  double q = 0.0;
  for (auto _ : state) {
    q = statistics::fit_gumbel_moments(x).quantile(0.999);
    benchmark::DoNotOptimize(q);
  }
  state.counters["x999"] = q;
}
BENCHMARK(BM_GumbelFit500)->Unit(benchmark::kMicrosecond);

void BM_Case500Days(benchmark::State& state) {
  const Fixture& f = fixture();
  simulation::CaseOptions o;
  o.num_threads = static_cast<int>(state.range(0));
  o.bootstrap_replicates = 200;
  simulation::prepare_case(f.inputs(), o);  // strip theory and towline fit memoised: not timed
  double dyn = 0.0;
  for (auto _ : state) {
    const auto r = simulation::run_case(f.inputs(), o);
    dyn = units::n_to_kips(r.statistics.dynamic_999_n);
  }
  state.counters["dynamic_999_kips"] = dyn;
}
BENCHMARK(BM_Case500Days)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
