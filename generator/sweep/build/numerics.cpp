#include "sweep/build/numerics.hpp"

#include <cmath>
#include <complex>
#include <cstring>
#include <vector>

#include "io/ship_file.hpp"
#include "sea/record.hpp"
#include "sea/spectrum.hpp"
#include "simulation/case_runner.hpp"

namespace towdb::sweep {
namespace {

void append_bits(std::string& bytes, double x) {
  char b[sizeof x];
  std::memcpy(b, &x, sizeof x);
  bytes.append(b, sizeof b);
}

std::string compute_fingerprint() {
  std::string bytes;
  // The simulation's day (simulation::CaseOptions's record: 86,400 samples at
  // 1 s), unit transfer function, a 20 kt Pierson-Moskowitz sea met at 9 kt.
  const sea::RecordPlan plan(sea::single_system(sea::Spectrum::pierson_moskowitz(10.29), 2.0), 4.63,
                             simulation::CaseOptions{}.record);
  const std::vector<std::complex<double>> unit(plan.components().size(), 1.0);
  const sea::DaySynthesizer synthesizer(plan, {unit}, {});
  auto workspace = synthesizer.make_workspace();
  synthesizer.synthesize(1997, 0, workspace);
  for (double x : workspace.linear(0)) append_bits(bytes, x);
  bytes.push_back(synthesizer.plan_from_stored_wisdom() ? 'w' : 'e');
  // The math library at fixed arguments.
  for (int k = 0; k < 64; ++k) {
    const double x = 0.1 + 0.37 * k;
    for (double y : {std::sin(x), std::cos(x), std::exp(0.1 * x), std::log(x), std::pow(x, 1.7), std::atan2(x, 1.3),
                     std::hypot(x, 0.7), std::cbrt(x), std::tanh(0.2 * x)}) {
      append_bits(bytes, y);
    }
  }
  return io::sha256_hex(bytes).substr(0, 16);
}

}  // namespace

std::string numerics_fingerprint() {
  static const std::string fingerprint = compute_fingerprint();
  return fingerprint;
}

std::string numerics_mismatch(int rank, const std::string& rank_fingerprint, const std::string& rank0_fingerprint) {
  if (rank_fingerprint == rank0_fingerprint) return {};
  return "MPI rank " + std::to_string(rank) + ": numerics fingerprint " + rank_fingerprint + " differs from rank 0's " +
         rank0_fingerprint +
         " (another FFT plan or math library: sweep/build/numerics.hpp); its results would differ in the last bits, "
         "so it computes nothing: run every rank on one machine kind";
}

}  // namespace towdb::sweep
