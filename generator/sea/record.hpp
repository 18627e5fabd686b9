// One-day periodic sea records in the encounter frame (EQ-SEA-5..9 in sea/sea.hpp).
//
// Two stages, so that everything that does not depend on the random phases is
// done once per case:
//   RecordPlan      the wave components of a sea state for a vessel at speed V:
//                   their absolute and encounter frequencies, deterministic
//                   amplitudes and encounter bins; the record length and step.
//   DaySynthesizer  per-component transfer functions H_k and drift coefficients
//                   D_k of the caller's output series, FFTW plans, and the
//                   per-day synthesis (one phase draw -> all series at once).
// A DaySynthesizer is immutable after construction: synthesize() may be called
// concurrently from several threads, each with its own Workspace.
#ifndef TOWDB_SEA_RECORD_HPP
#define TOWDB_SEA_RECORD_HPP

#include <complex>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/constants.hpp"
#include "sea/spectrum.hpp"

namespace towdb::sea {

struct RecordOptions {
  // Record period T [s]; the encounter-frequency grid is 2 pi / T (EQ-SEA-7).
  double duration_s = kSecondsPerDay;
  // Highest |w_e| [rad/s] represented; components above are dropped. 0 = automatic
  // from tail_energy_fraction. Sets the time step dt <= pi / cutoff (thesis eq. 3-22).
  double encounter_cutoff_rad_s = 0.0;
  // Automatic cutoff: at most this fraction of each system's m0 is dropped.
  double tail_energy_fraction = 1.0e-3;
  // Upper bound on the time step [s] (0 = none): raises the record length N.
  double max_time_step_s = 0.0;
  // Exact record length N (0 = the smallest 2^a 3^b 5^c 7^d, a >= 3, allowed by the
  // cutoff and max_time_step_s). Must leave the cutoff below the Nyquist bin.
  std::int64_t samples = 0;
  // Components are spaced at least this many encounter bins apart (>= 1); raised
  // to the number of frequency branches so that no two components share a bin.
  int bins_per_component = 1;

  void validate() const;
};

// One wave component of the plan. A response with complex transfer function H
// (output per metre of wave amplitude, referred to the wave elevation at the
// vessel's origin) contributes Re(H a exp(i (w_e t + phi))) to a record.
struct WaveComponent {
  double omega_rad_s = 0.0;            // absolute frequency w: evaluate H_k and D_k here
  double encounter_omega_rad_s = 0.0;  // signed w_e = w - w^2 V cos(mu) / g (EQ-SEA-6)
  double wavenumber_rad_m = 0.0;       // k = w^2 / g (deep water)
  double heading_rad = 0.0;            // heading mu of the component's wave system
  double amplitude_m = 0.0;            // a = sqrt(2 * energy of its frequency cell) (EQ-SEA-7)
  std::int64_t bin = 0;                // record frequency bin m >= 1: |w_e| ~ m 2 pi / T
  bool negative_encounter = false;     // w_e < 0: stored as conj(H) a exp(-i phi) at bin m
  int system = 0;                      // index into SeaState::systems
};

class RecordPlan {
 public:
  // speed_m_s >= 0 is the vessels' forward speed; each system's heading is
  // taken from the sea state. Throws InputError for invalid inputs.
  RecordPlan(const SeaState& sea, double speed_m_s, const RecordOptions& options = {});

  const std::vector<WaveComponent>& components() const { return components_; }
  const SeaState& sea_state() const { return sea_; }
  const RecordOptions& options() const { return options_; }
  double speed_m_s() const { return speed_m_s_; }
  std::int64_t samples() const { return samples_; }       // N
  double duration_s() const { return options_.duration_s; }  // T
  double time_step_s() const { return options_.duration_s / static_cast<double>(samples_); }
  double bin_omega_rad_s() const { return 2.0 * kPi / options_.duration_s; }  // 2 pi / T
  double encounter_cutoff_rad_s() const { return cutoff_rad_s_; }
  std::int64_t highest_bin() const { return highest_bin_; }
  int bins_per_component() const { return spacing_bins_; }
  // Sum of the systems' m0 [m^2] and the part carried by the components,
  // sum a^2 / 2 [m^2] (= the variance of the unit-transfer record, EQ-SEA-8).
  double spectrum_variance_m2() const { return sea_.variance_m2(); }
  double retained_variance_m2() const { return retained_m2_; }

 private:
  SeaState sea_;
  double speed_m_s_;
  RecordOptions options_;
  double cutoff_rad_s_ = 0.0;
  std::int64_t highest_bin_ = 0;
  std::int64_t samples_ = 0;
  int spacing_bins_ = 1;
  double retained_m2_ = 0.0;
  std::vector<WaveComponent> components_;
};

// Smallest n >= min_n that is a multiple of 8 with no prime factor above 7
// (fast FFTW c2r sizes).
std::int64_t fft_friendly_size(std::int64_t min_n);

// The random phase of every component of one day: uniform on [0, 2 pi) with
// 2^24 levels, drawn in component order from RandomStream(seed, day).
void draw_phases(std::uint64_t seed, std::uint64_t day, std::span<double> phases_rad);

class DaySynthesizer {
 public:
  // linear_transfer[k][j] = H_k(w_j) of output series k for component j
  //   (output unit per metre of wave amplitude; e.g. N/m for a surge force).
  // drift_coefficient[k][j] = D_k(w_j), finite, of either sign (output unit per m^2 of amplitude
  //   squared, e.g. R_aw/zeta_a^2 in N/m^2) of second-order series k (EQ-SEA-9).
  // drift_phase_rad[k][j] (optional: empty = all 0) = theta_k(w_j), the phase
  //   of component j at the point where second-order series k acts, relative
  //   to the elevation at the reference origin: E_k is built from
  //   a_j sqrt(D_k) exp(i (w_e,j t + phi_j + theta_kj)) (EQ-SEA-9). A vessel
  //   whose origin is G metres astern of the reference sees the wave envelope
  //   with theta = k G cos mu, as its first-order forces do (EQ-SEA-8).
  // Every vector must have plan.components().size() entries.
  DaySynthesizer(RecordPlan plan, const std::vector<std::vector<std::complex<double>>>& linear_transfer,
                 const std::vector<std::vector<double>>& drift_coefficient,
                 const std::vector<std::vector<double>>& drift_phase_rad = {});
  ~DaySynthesizer();
  DaySynthesizer(DaySynthesizer&&) noexcept;
  DaySynthesizer& operator=(DaySynthesizer&&) noexcept;
  DaySynthesizer(const DaySynthesizer&) = delete;
  DaySynthesizer& operator=(const DaySynthesizer&) = delete;

  // Per-thread scratch and output storage (FFTW-aligned). Records are sampled
  // at t_n = n dt, n = 0..N-1.
  class Workspace {
   public:
    ~Workspace();
    Workspace(Workspace&&) noexcept;
    Workspace& operator=(Workspace&&) noexcept;
    Workspace(const Workspace&) = delete;
    Workspace& operator=(const Workspace&) = delete;

    // First-order record k: x_k(t_n) = sum_j Re(H_k a_j exp(i (w_e,j t_n + phi_j))).
    std::span<const double> linear(std::size_t k) const;
    // Second-order record k: f2_k(t_n) = -|E_k(t_n)|^2 + mean (zero mean), EQ-SEA-9.
    std::span<const double> drift(std::size_t k) const;

   private:
    friend class DaySynthesizer;
    struct Buffers;
    explicit Workspace(std::unique_ptr<Buffers> buffers);
    std::unique_ptr<Buffers> buffers_;
  };

  Workspace make_workspace() const;
  // Fills ws with every series of day `day` of the case with seed `seed`.
  // Same (seed, day) -> bit-identical records, on any thread.
  void synthesize(std::uint64_t seed, std::uint64_t day, Workspace& ws) const;

  const RecordPlan& plan() const;
  std::size_t linear_count() const;
  std::size_t drift_count() const;
  // Time mean of -|E_k|^2 that EQ-SEA-9 removes: sum_j a_j^2 D_k(w_j) (> 0 is a
  // resistance: the mean second-order force is minus this) [output unit].
  double drift_mean(std::size_t k) const;
  // Whether the FFT plan came from the stored wisdom (sea/fft_wisdom.hpp);
  // false: FFTW_ESTIMATE's plan, whose records differ in the last bits.
  bool plan_from_stored_wisdom() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The FFTW wisdom of the c2r plan of a record of `samples` points, planned
// from scratch with FFTW_PATIENT (minutes for a day's 86,400 points; it times
// candidate plans, so two runs may choose differently). What
// tools/make_fftw_wisdom prints, for sea/fft_wisdom.cpp. Forgets the wisdom
// already loaded in this process.
std::string plan_record_wisdom(std::int64_t samples);

}  // namespace towdb::sea

#endif  // TOWDB_SEA_RECORD_HPP
