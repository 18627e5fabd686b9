// Google Benchmark of one simulated day of sea records (sea/record.hpp): the
// cost the long-time towing simulation pays per day. A 500-day case must run
// in about 1 s on one core, so one day's records (3 first-order + 2
// second-order series) must stay well under 1-2 ms.
//
// Cases: PM sea for a 30 kt wind, tow speed 5 kt, head (180 deg) and following
// (0 deg, folded encounter frequencies) seas; encounter cutoff 2 rad/s (the
// record then has N = 55125 samples, dt = 1.57 s) or automatic (0.1% of m0).
// The reported counter "checksum" is the sum of squares of the first series of
// day 0 (seed 1997), so that builds can be compared (speedtest1 --verify).
#include <benchmark/benchmark.h>

#include <complex>
#include <vector>

#include "common/units.hpp"
#include "sea/sea.hpp"

namespace {

using towdb::sea::DaySynthesizer;
using towdb::sea::RecordOptions;
using towdb::sea::RecordPlan;
using towdb::sea::Spectrum;

DaySynthesizer make_case(double heading_deg, double cutoff_rad_s) {
  namespace units = towdb::units;
  const Spectrum pm = Spectrum::pierson_moskowitz(units::kt_to_m_s(30.0));
  RecordOptions options;
  options.encounter_cutoff_rad_s = cutoff_rad_s;
  RecordPlan plan(towdb::sea::single_system(pm, units::deg_to_rad(heading_deg)), units::kt_to_m_s(5.0), options);
  const std::size_t n = plan.components().size();
  // Representative transfer functions: surge force on tug and tow (the tow's
  // lags by k G cos(mu), G = 600 m) and a non-surge extension.
  std::vector<std::complex<double>> tug(n);
  std::vector<std::complex<double>> tow(n);
  std::vector<std::complex<double>> extension(n);
  std::vector<double> drift_tug(n);
  std::vector<double> drift_tow(n);
  for (std::size_t j = 0; j < n; ++j) {
    const auto& c = plan.components()[j];
    const double k = c.wavenumber_rad_m;
    tug[j] = {2.0e5 / (1.0 + k * 40.0), 0.0};
    tow[j] = std::polar(8.0e5 / (1.0 + k * 150.0), k * 600.0 * std::cos(c.heading_rad));
    extension[j] = {0.3, 0.1};
    drift_tug[j] = 3.0e3 * c.omega_rad_s;
    drift_tow[j] = 9.0e3 * c.omega_rad_s;
  }
  return DaySynthesizer(std::move(plan), {tug, tow, extension}, {drift_tug, drift_tow});
}

void BM_SeaDay(benchmark::State& state) {
  const double heading_deg = static_cast<double>(state.range(0));
  const double cutoff_rad_s = static_cast<double>(state.range(1)) / 10.0;
  const DaySynthesizer synth = make_case(heading_deg, cutoff_rad_s);
  auto ws = synth.make_workspace();
  synth.synthesize(1997, 0, ws);
  double checksum = 0.0;
  for (double x : ws.linear(0)) checksum += x * x;
  std::uint64_t day = 0;
  for (auto _ : state) {
    synth.synthesize(1997, day++, ws);
    benchmark::DoNotOptimize(ws.linear(0).data());
    benchmark::ClobberMemory();
  }
  state.counters["samples"] = static_cast<double>(synth.plan().samples());
  state.counters["components"] = static_cast<double>(synth.plan().components().size());
  state.counters["checksum"] = checksum;
}

void BM_SeaPlan(benchmark::State& state) {
  for (auto _ : state) {
    const DaySynthesizer synth = make_case(180.0, 2.0);
    benchmark::DoNotOptimize(&synth);
  }
}

}  // namespace

// Arguments: heading [deg], cutoff [0.1 rad/s] (0 = automatic).
BENCHMARK(BM_SeaDay)->Args({180, 20})->Args({0, 20})->Args({180, 0})->Args({0, 0})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SeaPlan)->Unit(benchmark::kMillisecond);
