#include "sea/record.hpp"

#include <fftw3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <utility>
#include <string>

#include "common/error.hpp"
#include "common/random.hpp"
#include "sea/fft_wisdom.hpp"

namespace towdb::sea {
namespace {

// Components whose cell holds less than this fraction of the sea's m0 are not
// kept (far spectral tails): their total is below 1e-15 * m0 * (bins), far
// below any test tolerance, and they would cost time every day.
constexpr double kNegligibleEnergyFraction = 1.0e-15;
// Largest record length accepted (FFTW takes int sizes; 2^27 samples of a day
// is a 0.6 ms step, far finer than any towing model needs).
constexpr std::int64_t kMaxSamples = std::int64_t{1} << 27;
// Phases have 2^24 levels: phi = 2 pi k / 2^24, k = top 24 bits of a draw, and
// exp(i phi) = coarse[k >> 12] * fine[k & 4095] from two 4096-entry tables.
constexpr int kPhaseBits = 24;
constexpr int kPhaseTableBits = 12;
constexpr std::size_t kPhaseTableSize = std::size_t{1} << kPhaseTableBits;

// FFTW's planner is not thread-safe; every plan creation and destruction in
// towdb's sea module goes through this lock. Execution with the new-array
// functions (fftw_execute_dft_c2r) is thread-safe and needs no lock.
std::mutex& fftw_planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Loads kStoredRecordWisdom into FFTW once per process, before the first plan
// (caller holds the planner lock). FFTW refuses wisdom from another FFTW
// version; codelets this processor lacks make the wisdom-only plan fail.
void import_stored_wisdom() {
  static const bool imported = fftw_import_wisdom_from_string(kStoredRecordWisdom) != 0;
  (void)imported;
}

struct PhaseTables {
  std::array<std::complex<double>, kPhaseTableSize> coarse;
  std::array<std::complex<double>, kPhaseTableSize> fine;
  PhaseTables() {
    const double step = 2.0 * kPi / static_cast<double>(std::uint64_t{1} << kPhaseBits);
    for (std::size_t i = 0; i < kPhaseTableSize; ++i) {
      const double coarse_rad = step * static_cast<double>(i << kPhaseTableBits);
      const double fine_rad = step * static_cast<double>(i);
      coarse[i] = {std::cos(coarse_rad), std::sin(coarse_rad)};
      fine[i] = {std::cos(fine_rad), std::sin(fine_rad)};
    }
  }
};

const PhaseTables& phase_tables() {
  static const PhaseTables tables;
  return tables;
}

std::uint64_t phase_index(RandomStream& stream) { return stream.next_u64() >> (64 - kPhaseBits); }

// Plain complex product: std::complex's operator* carries C99 Annex G NaN
// recovery branches that keep the hot loops from vectorising; our operands
// are finite by construction (validated transfer functions, unit phasors).
inline std::complex<double> mul(std::complex<double> a, std::complex<double> b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// ---- Frequency branches of EQ-SEA-6 -----------------------------------------
// kappa = V cos(mu) / g [s/rad]; w_e = w - kappa w^2; u = |w_e| >= 0.
enum class BranchShape {
  kRising,     // kappa <= 0: u = w + |kappa| w^2, w in [0, inf)
  kBelowFold,  // kappa > 0:  u = w - kappa w^2, w in [0, 1/(2 kappa)], u rising to 1/(4 kappa)
  kAboveFold,  // kappa > 0:  u = w - kappa w^2, w in [1/(2 kappa), 1/kappa], u falling to 0
  kNegative,   // kappa > 0:  u = kappa w^2 - w, w in [1/kappa, inf), w_e < 0
};

struct Branch {
  int system = 0;
  BranchShape shape = BranchShape::kRising;
  double kappa_s = 0.0;
  double u_max_rad_s = std::numeric_limits<double>::infinity();
};

// Inverse of the branch map: the absolute frequency whose |w_e| is u. The
// roots are written in the cancellation-free forms 2u / (1 + sqrt(.)).
double omega_of_u(const Branch& b, double u) {
  const double k = b.kappa_s;
  switch (b.shape) {
    case BranchShape::kRising:
      return 2.0 * u / (1.0 + std::sqrt(1.0 - 4.0 * k * u));  // k <= 0
    case BranchShape::kBelowFold:
      return 2.0 * u / (1.0 + std::sqrt(std::max(0.0, 1.0 - 4.0 * k * u)));
    case BranchShape::kAboveFold:
      return (1.0 + std::sqrt(std::max(0.0, 1.0 - 4.0 * k * u))) / (2.0 * k);
    case BranchShape::kNegative:
      return (1.0 + std::sqrt(1.0 + 4.0 * k * u)) / (2.0 * k);
  }
  return 0.0;
}

// Largest |w_e| of a system's frequencies in [0, w_hi].
double max_encounter_below(double kappa_s, double omega_hi) {
  const double we_hi = std::abs(omega_hi - kappa_s * omega_hi * omega_hi);
  if (kappa_s <= 0.0) return we_hi;
  const double fold = 0.5 / kappa_s;
  return omega_hi > fold ? std::max(0.25 / kappa_s, we_hi) : we_hi;
}

}  // namespace

void RecordOptions::validate() const {
  require_in_range("record.duration_s", duration_s, 1.0, 1.0e7);
  require_in_range("record.encounter_cutoff_rad_s", encounter_cutoff_rad_s, 0.0, 200.0);
  require_in_range("record.tail_energy_fraction", tail_energy_fraction, 1.0e-12, 0.5);
  require_in_range("record.max_time_step_s", max_time_step_s, 0.0, duration_s);
  require_input(samples >= 0 && samples <= kMaxSamples, "record.samples", static_cast<double>(samples),
                "must be 0 (automatic) or a record length up to 2^27");
  require_input(bins_per_component >= 1 && bins_per_component <= 4096, "record.bins_per_component",
                bins_per_component, "must be an integer from 1 to 4096");
}

std::int64_t fft_friendly_size(std::int64_t min_n) {
  require_input(min_n >= 1 && min_n <= kMaxSamples, "fft size", static_cast<double>(min_n),
                "must be from 1 to 2^27");
  // Multiples of 8 (FFTW's c2r of odd or singly even sizes measured 2-3x slower
  // at N ~ 5e4) whose other prime factors are 3, 5 or 7.
  for (std::int64_t n = std::max<std::int64_t>(8, (min_n + 7) / 8 * 8);; n += 8) {
    std::int64_t r = n;
    for (std::int64_t p : {2, 3, 5, 7}) {
      while (r % p == 0) r /= p;
    }
    if (r == 1) return n;
  }
}

void draw_phases(std::uint64_t seed, std::uint64_t day, std::span<double> phases_rad) {
  RandomStream stream(seed, day);
  const double step = 2.0 * kPi / static_cast<double>(std::uint64_t{1} << kPhaseBits);
  for (double& phase : phases_rad) phase = step * static_cast<double>(phase_index(stream));
}

RecordPlan::RecordPlan(const SeaState& sea, double speed_m_s, const RecordOptions& options)
    : sea_(sea), speed_m_s_(speed_m_s), options_(options) {
  sea_.validate();
  options_.validate();
  require_in_range("record.speed_m_s", speed_m_s, 0.0, 30.0);
  const double g = kGravity_m_s2;
  const double dw = bin_omega_rad_s();
  const double total_m0 = sea_.variance_m2();

  // Branches with energy (EQ-SEA-6), in a fixed order: system, then shape.
  std::vector<Branch> branches;
  for (int s = 0; s < static_cast<int>(sea_.systems.size()); ++s) {
    const WaveSystem& ws = sea_.systems[static_cast<std::size_t>(s)];
    const double kappa = speed_m_s * std::cos(ws.heading_rad) / g;
    if (kappa <= 0.0) {
      branches.push_back({s, BranchShape::kRising, kappa});
      continue;
    }
    const double fold = 0.5 / kappa;
    const double u_max = 0.25 / kappa;
    const double floor_m2 = kNegligibleEnergyFraction * total_m0;
    branches.push_back({s, BranchShape::kBelowFold, kappa, u_max});
    if (ws.spectrum.energy_between_m2(fold, 2.0 * fold) > floor_m2) {
      branches.push_back({s, BranchShape::kAboveFold, kappa, u_max});
    }
    if (ws.spectrum.energy_between_m2(2.0 * fold, std::numeric_limits<double>::infinity()) > floor_m2) {
      branches.push_back({s, BranchShape::kNegative, kappa});
    }
  }
  spacing_bins_ = std::max(options_.bins_per_component, static_cast<int>(branches.size()));

  // Cutoff and record length (EQ-SEA-7, thesis eq. 3-22: dt = pi / w_c).
  cutoff_rad_s_ = options_.encounter_cutoff_rad_s;
  if (cutoff_rad_s_ == 0.0) {
    for (const WaveSystem& ws : sea_.systems) {
      const double kappa = speed_m_s * std::cos(ws.heading_rad) / g;
      const double w_hi = ws.spectrum.tail_omega_rad_s(options_.tail_energy_fraction);
      cutoff_rad_s_ = std::max(cutoff_rad_s_, max_encounter_below(kappa, w_hi));
    }
  }
  highest_bin_ = static_cast<std::int64_t>(std::floor(cutoff_rad_s_ / dw));
  require_input(highest_bin_ >= 1, "record.encounter_cutoff_rad_s", cutoff_rad_s_,
                "must be at least one frequency bin, 2 pi / duration_s = " + format_value(dw));
  const std::int64_t nyquist_min = 2 * highest_bin_ + 2;
  require_input(nyquist_min <= kMaxSamples, "record.encounter_cutoff_rad_s", cutoff_rad_s_,
                "gives more than 2^27 samples per record: lower the cutoff or the duration");
  std::int64_t step_min = 1;
  if (options_.max_time_step_s > 0.0) {
    step_min = static_cast<std::int64_t>(std::ceil(options_.duration_s / options_.max_time_step_s));
    require_input(step_min <= kMaxSamples, "record.max_time_step_s", options_.max_time_step_s,
                  "gives more than 2^27 samples per record");
  }
  if (options_.samples > 0) {
    require_input(options_.samples >= std::max(nyquist_min, step_min), "record.samples",
                  static_cast<double>(options_.samples),
                  "must be at least " + std::to_string(std::max(nyquist_min, step_min)) +
                      " (2 * highest bin + 2, and duration / max_time_step_s)");
    samples_ = options_.samples;
  } else {
    samples_ = fft_friendly_size(std::max(nyquist_min, step_min));
  }

  // Components (EQ-SEA-7): branch b owns the bins m = c W + r_b, r_b = b + 1,
  // and each bin's cell [m - W/2, m + W/2) * dw of |w_e| (the first cell starts
  // at 0). Its energy is the spectrum integrated over the absolute frequencies
  // that map into the cell.
  const double half_cell = 0.5 * static_cast<double>(spacing_bins_);
  for (std::size_t b = 0; b < branches.size(); ++b) {
    const Branch& br = branches[b];
    const WaveSystem& ws = sea_.systems[static_cast<std::size_t>(br.system)];
    const std::int64_t residue = static_cast<std::int64_t>(b) + 1;
    for (std::int64_t c = 0;; ++c) {
      const std::int64_t m = c * spacing_bins_ + residue;
      if (m > highest_bin_) break;
      const double md = static_cast<double>(m);
      const double u_lo = c == 0 ? 0.0 : (md - half_cell) * dw;
      if (u_lo >= br.u_max_rad_s) break;
      const double u_hi = std::min((md + half_cell) * dw, br.u_max_rad_s);
      double w_a = omega_of_u(br, u_lo);
      double w_b = omega_of_u(br, u_hi);
      if (w_a > w_b) std::swap(w_a, w_b);
      const double energy_m2 = ws.spectrum.energy_between_m2(w_a, w_b);
      if (!(energy_m2 > kNegligibleEnergyFraction * total_m0)) continue;
      const double u_c = std::clamp(md * dw, u_lo, u_hi);
      const double w = omega_of_u(br, u_c);
      WaveComponent comp;
      comp.omega_rad_s = w;
      comp.encounter_omega_rad_s = br.shape == BranchShape::kNegative ? -u_c : u_c;
      comp.wavenumber_rad_m = w * w / g;
      comp.heading_rad = ws.heading_rad;
      comp.amplitude_m = std::sqrt(2.0 * energy_m2);
      comp.bin = m;
      comp.negative_encounter = br.shape == BranchShape::kNegative;
      comp.system = br.system;
      components_.push_back(comp);
      retained_m2_ += energy_m2;
    }
  }
  require_input(!components_.empty(), "record.encounter_cutoff_rad_s", cutoff_rad_s_,
                "keeps no wave energy: raise the cutoff");
}

// ---- DaySynthesizer ---------------------------------------------------------

struct DaySynthesizer::Impl {
  RecordPlan plan;
  int n = 0;        // record length N
  int n_spec = 0;   // N/2 + 1 complex bins of the c2r input
  std::vector<int> bins;
  std::vector<unsigned char> negative;
  // 0.5 a_j H_k(w_j), conjugated when w_e < 0 (EQ-SEA-8).
  std::vector<std::vector<std::complex<double>>> linear_gain;
  // 0.5 a_j sqrt(max(D_k(w_j), 0)) exp(i theta_kj), conjugated when w_e < 0
  // (EQ-SEA-9), and the same from max(-D_k, 0) for the components where D_k is
  // negative (empty when none is: then the series is D >= 0's bit for bit).
  std::vector<std::vector<std::complex<double>>> drift_gain;
  std::vector<std::vector<std::complex<double>>> drift_gain_negative;
  std::vector<double> drift_mean;
  // Bins [first, first + count) of the c2r input that no component writes:
  // they are zeroed before every transform (c2r overwrites its input). When
  // the gaps are many small runs, one memset of the whole input is cheaper.
  std::vector<std::pair<int, int>> gaps;
  bool zero_by_gaps = false;
  fftw_plan c2r = nullptr;
  bool plan_from_wisdom = false;  // c2r came from kStoredRecordWisdom

  void clear_input(fftw_complex* spectrum) const {
    if (zero_by_gaps) {
      for (const auto& [first, count] : gaps) {
        std::memset(static_cast<void*>(spectrum + first), 0, sizeof(fftw_complex) * static_cast<std::size_t>(count));
      }
    } else {
      std::memset(static_cast<void*>(spectrum), 0, sizeof(fftw_complex) * static_cast<std::size_t>(n_spec));
    }
  }

  explicit Impl(RecordPlan p) : plan(std::move(p)) {}
  ~Impl() {
    if (c2r != nullptr) {
      std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      fftw_destroy_plan(c2r);
    }
  }
};

struct DaySynthesizer::Workspace::Buffers {
  int n = 0;
  int n_spec = 0;
  std::size_t n_linear = 0;
  fftw_complex* spectrum = nullptr;
  double* scratch = nullptr;
  double* scratch_negative = nullptr;  // only when a drift series has D < 0 somewhere
  std::vector<double*> outputs;  // linear series, then drift series
  std::vector<std::complex<double>> phasors;

  ~Buffers() {
    fftw_free(spectrum);
    fftw_free(scratch);
    fftw_free(scratch_negative);
    for (double* p : outputs) fftw_free(p);
  }
};

DaySynthesizer::Workspace::Workspace(std::unique_ptr<Buffers> buffers) : buffers_(std::move(buffers)) {}
DaySynthesizer::Workspace::~Workspace() = default;
DaySynthesizer::Workspace::Workspace(Workspace&&) noexcept = default;
DaySynthesizer::Workspace& DaySynthesizer::Workspace::operator=(Workspace&&) noexcept = default;

std::span<const double> DaySynthesizer::Workspace::linear(std::size_t k) const {
  TOWDB_ASSERT(k < buffers_->n_linear);
  return {buffers_->outputs[k], static_cast<std::size_t>(buffers_->n)};
}

std::span<const double> DaySynthesizer::Workspace::drift(std::size_t k) const {
  TOWDB_ASSERT(buffers_->n_linear + k < buffers_->outputs.size());
  return {buffers_->outputs[buffers_->n_linear + k], static_cast<std::size_t>(buffers_->n)};
}

DaySynthesizer::DaySynthesizer(RecordPlan plan,
                               const std::vector<std::vector<std::complex<double>>>& linear_transfer,
                               const std::vector<std::vector<double>>& drift_coefficient,
                               const std::vector<std::vector<double>>& drift_phase_rad)
    : impl_(std::make_unique<Impl>(std::move(plan))) {
  Impl& im = *impl_;
  const std::vector<WaveComponent>& comps = im.plan.components();
  const std::size_t nc = comps.size();
  im.n = static_cast<int>(im.plan.samples());
  im.n_spec = im.n / 2 + 1;
  im.bins.resize(nc);
  im.negative.resize(nc);
  for (std::size_t j = 0; j < nc; ++j) {
    im.bins[j] = static_cast<int>(comps[j].bin);
    im.negative[j] = comps[j].negative_encounter ? 1 : 0;
  }
  {
    std::vector<unsigned char> used(static_cast<std::size_t>(im.n_spec), 0);
    for (int b : im.bins) used[static_cast<std::size_t>(b)] = 1;
    for (int m = 0; m < im.n_spec;) {
      if (used[static_cast<std::size_t>(m)] != 0) {
        ++m;
        continue;
      }
      const int first = m;
      while (m < im.n_spec && used[static_cast<std::size_t>(m)] == 0) ++m;
      im.gaps.emplace_back(first, m - first);
    }
    // Runs of ~64 bins or more (1 KiB) make per-gap memsets worthwhile.
    im.zero_by_gaps = static_cast<int>(im.gaps.size()) * 64 < im.n_spec;
  }
  for (std::size_t k = 0; k < linear_transfer.size(); ++k) {
    const auto& h = linear_transfer[k];
    require_input(h.size() == nc, "linear_transfer[" + std::to_string(k) + "] (size)",
                  static_cast<double>(h.size()),
                  "must have one entry per plan component (" + std::to_string(nc) + ")");
    std::vector<std::complex<double>> gain(nc);
    for (std::size_t j = 0; j < nc; ++j) {
      if (!std::isfinite(h[j].real()) || !std::isfinite(h[j].imag())) {
        require_input(false, "linear_transfer[" + std::to_string(k) + "][" + std::to_string(j) + "]",
                      std::abs(h[j]), "must be finite");
      }
      const std::complex<double> hk = comps[j].negative_encounter ? std::conj(h[j]) : h[j];
      gain[j] = 0.5 * comps[j].amplitude_m * hk;
    }
    im.linear_gain.push_back(std::move(gain));
  }
  require_input(drift_phase_rad.empty() || drift_phase_rad.size() == drift_coefficient.size(),
                "drift_phase_rad (size)", static_cast<double>(drift_phase_rad.size()),
                "must be empty or have one series per drift_coefficient series (" +
                    std::to_string(drift_coefficient.size()) + ")");
  for (std::size_t k = 0; k < drift_coefficient.size(); ++k) {
    const auto& d = drift_coefficient[k];
    require_input(d.size() == nc, "drift_coefficient[" + std::to_string(k) + "] (size)",
                  static_cast<double>(d.size()),
                  "must have one entry per plan component (" + std::to_string(nc) + ")");
    const std::vector<double>* theta = drift_phase_rad.empty() ? nullptr : &drift_phase_rad[k];
    if (theta != nullptr) {
      require_input(theta->size() == nc, "drift_phase_rad[" + std::to_string(k) + "] (size)",
                    static_cast<double>(theta->size()),
                    "must have one entry per plan component (" + std::to_string(nc) + ")");
    }
    std::vector<std::complex<double>> gain(nc), gain_negative;
    double mean = 0.0;
    for (std::size_t j = 0; j < nc; ++j) {
      if (!std::isfinite(d[j])) {
        require_input(false, "drift_coefficient[" + std::to_string(k) + "][" + std::to_string(j) + "]", d[j],
                      "must be finite");
      }
      const double a = comps[j].amplitude_m;
      const double th = theta != nullptr ? (*theta)[j] : 0.0;
      if (!std::isfinite(th)) {
        require_input(false, "drift_phase_rad[" + std::to_string(k) + "][" + std::to_string(j) + "]", th,
                      "must be finite");
      }
      // The phase enters like phi_j: conjugated with it for w_e < 0 (EQ-SEA-8).
      const std::complex<double> lag(std::cos(th), comps[j].negative_encounter ? -std::sin(th) : std::sin(th));
      if (d[j] >= 0.0) {
        gain[j] = 0.5 * a * std::sqrt(d[j]) * lag;
      } else {
        if (gain_negative.empty()) gain_negative.resize(nc);
        gain_negative[j] = 0.5 * a * std::sqrt(-d[j]) * lag;
      }
      mean += a * a * d[j];
    }
    im.drift_gain.push_back(std::move(gain));
    im.drift_gain_negative.push_back(std::move(gain_negative));
    im.drift_mean.push_back(mean);
  }
  // One c2r plan for every series, made once and never from timing
  // measurements made here, so that the plan (and so every bit of the output)
  // is the same in every process: the stored wisdom's plan where it applies
  // (fft_wisdom.hpp), else FFTW_ESTIMATE's.
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  import_stored_wisdom();
  auto* in = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(im.n_spec)));
  auto* out = static_cast<double*>(fftw_malloc(sizeof(double) * static_cast<std::size_t>(im.n)));
  if (in != nullptr && out != nullptr) {
    im.c2r = fftw_plan_dft_c2r_1d(im.n, in, out, FFTW_PATIENT | FFTW_WISDOM_ONLY);
    im.plan_from_wisdom = im.c2r != nullptr;
    if (im.c2r == nullptr) im.c2r = fftw_plan_dft_c2r_1d(im.n, in, out, FFTW_ESTIMATE);
  }
  fftw_free(in);
  fftw_free(out);
  if (im.c2r == nullptr) {
    throw NumericalError("FFTW c2r planner: no plan for record length " + std::to_string(im.n));
  }
}

DaySynthesizer::~DaySynthesizer() = default;
DaySynthesizer::DaySynthesizer(DaySynthesizer&&) noexcept = default;
DaySynthesizer& DaySynthesizer::operator=(DaySynthesizer&&) noexcept = default;

const RecordPlan& DaySynthesizer::plan() const { return impl_->plan; }
std::size_t DaySynthesizer::linear_count() const { return impl_->linear_gain.size(); }
std::size_t DaySynthesizer::drift_count() const { return impl_->drift_gain.size(); }
double DaySynthesizer::drift_mean(std::size_t k) const { return impl_->drift_mean.at(k); }
bool DaySynthesizer::plan_from_stored_wisdom() const { return impl_->plan_from_wisdom; }

std::string plan_record_wisdom(std::int64_t samples) {
  require_in_range("plan_record_wisdom: samples", static_cast<double>(samples), 8.0,
                   static_cast<double>(kMaxSamples));
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_forget_wisdom();  // plan from scratch, not from the stored wisdom
  const auto n = static_cast<std::size_t>(samples);
  auto* in = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1)));
  auto* out = static_cast<double*>(fftw_malloc(sizeof(double) * n));
  fftw_plan plan = in != nullptr && out != nullptr
                       ? fftw_plan_dft_c2r_1d(static_cast<int>(samples), in, out, FFTW_PATIENT)
                       : nullptr;
  std::string wisdom;
  if (plan != nullptr) {
    char* text = fftw_export_wisdom_to_string();
    if (text != nullptr) wisdom = text;
    std::free(text);  // FFTW: "the caller is responsible for deallocating it with free"
    fftw_destroy_plan(plan);
  }
  fftw_free(in);
  fftw_free(out);
  if (wisdom.empty()) throw NumericalError("FFTW: no plan for a c2r of " + std::to_string(samples) + " samples");
  return wisdom;
}

DaySynthesizer::Workspace DaySynthesizer::make_workspace() const {
  const Impl& im = *impl_;
  auto buf = std::make_unique<Workspace::Buffers>();
  buf->n = im.n;
  buf->n_spec = im.n_spec;
  buf->n_linear = im.linear_gain.size();
  const std::size_t n = static_cast<std::size_t>(im.n);
  buf->spectrum = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(im.n_spec)));
  buf->scratch = static_cast<double*>(fftw_malloc(sizeof(double) * n));
  const bool any_negative = std::any_of(im.drift_gain_negative.begin(), im.drift_gain_negative.end(),
                                        [](const auto& g) { return !g.empty(); });
  if (any_negative) buf->scratch_negative = static_cast<double*>(fftw_malloc(sizeof(double) * n));
  const std::size_t series = im.linear_gain.size() + im.drift_gain.size();
  for (std::size_t k = 0; k < series; ++k) {
    buf->outputs.push_back(static_cast<double*>(fftw_malloc(sizeof(double) * n)));
  }
  if (buf->spectrum == nullptr || buf->scratch == nullptr || (any_negative && buf->scratch_negative == nullptr) ||
      std::find(buf->outputs.begin(), buf->outputs.end(), nullptr) != buf->outputs.end()) {
    throw NumericalError("DaySynthesizer workspace: fftw_malloc failed for " + std::to_string(n) +
                         " samples");
  }
  buf->phasors.resize(im.bins.size());
  return Workspace(std::move(buf));
}

void DaySynthesizer::synthesize(std::uint64_t seed, std::uint64_t day, Workspace& ws) const {
  const Impl& im = *impl_;
  Workspace::Buffers& buf = *ws.buffers_;
  TOWDB_ASSERT(buf.n == im.n && buf.phasors.size() == im.bins.size());
  const std::size_t nc = im.bins.size();
  const std::size_t n = static_cast<std::size_t>(im.n);

  // exp(i phi_j), conjugated for w_e < 0 (EQ-SEA-8): the phasor at bin m.
  const PhaseTables& tables = phase_tables();
  RandomStream stream(seed, day);
  const std::uint64_t low_mask = kPhaseTableSize - 1;
  for (std::size_t j = 0; j < nc; ++j) {
    const std::uint64_t k = phase_index(stream);
    const std::complex<double> u = mul(tables.coarse[k >> kPhaseTableBits], tables.fine[k & low_mask]);
    buf.phasors[j] = im.negative[j] != 0 ? std::conj(u) : u;
  }
  auto* spec = reinterpret_cast<std::complex<double>*>(buf.spectrum);

  for (std::size_t k = 0; k < im.linear_gain.size(); ++k) {
    im.clear_input(buf.spectrum);
    const std::complex<double>* gain = im.linear_gain[k].data();
    for (std::size_t j = 0; j < nc; ++j) spec[im.bins[j]] = mul(gain[j], buf.phasors[j]);
    fftw_execute_dft_c2r(im.c2r, buf.spectrum, buf.outputs[k]);
  }

  // EQ-SEA-9 via the real and imaginary parts of the envelope:
  //   p = Re E = sum c cos(w_e t + phi),  q = Im E = sum c sin(w_e t + phi),
  // each a c2r of half-amplitudes (b/2) e^{i phi} and -i (b/2) e^{i phi}
  // (conjugated, and -i -> +i, for w_e < 0); f2 = mean - (p^2 + q^2).
  // |E|^2 of the envelope with half-amplitude gains `gain`, into `out`.
  const auto envelope_power = [&](const std::complex<double>* gain, double* out) {
    im.clear_input(buf.spectrum);
    for (std::size_t j = 0; j < nc; ++j) spec[im.bins[j]] = mul(gain[j], buf.phasors[j]);
    fftw_execute_dft_c2r(im.c2r, buf.spectrum, out);
    im.clear_input(buf.spectrum);
    for (std::size_t j = 0; j < nc; ++j) {
      const std::complex<double> v = mul(gain[j], buf.phasors[j]);
      // -i v = (v.imag, -v.real); +i v = (-v.imag, v.real).
      spec[im.bins[j]] = im.negative[j] != 0 ? std::complex<double>(-v.imag(), v.real())
                                             : std::complex<double>(v.imag(), -v.real());
    }
    fftw_execute_dft_c2r(im.c2r, buf.spectrum, buf.scratch);
    const double* q = buf.scratch;
    for (std::size_t i = 0; i < n; ++i) out[i] = out[i] * out[i] + q[i] * q[i];
  };
  for (std::size_t k = 0; k < im.drift_gain.size(); ++k) {
    double* f2 = buf.outputs[buf.n_linear + k];
    envelope_power(im.drift_gain[k].data(), f2);
    const double mean = im.drift_mean[k];
    if (im.drift_gain_negative[k].empty()) {
      for (std::size_t i = 0; i < n; ++i) f2[i] = mean - f2[i];
    } else {
      // Components with D < 0 (a thrust) give a second envelope whose power
      // adds with the opposite sign; cross terms between the two signs are
      // left out (sqrt(D_j D_l) is not real there).
      envelope_power(im.drift_gain_negative[k].data(), buf.scratch_negative);
      for (std::size_t i = 0; i < n; ++i) f2[i] = mean - f2[i] + buf.scratch_negative[i];
    }
  }
}

}  // namespace towdb::sea
