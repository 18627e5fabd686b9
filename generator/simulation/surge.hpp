// Nonlinear surge of tug and tow on the towline: the time-domain core of the
// long-time towing simulation (thesis 3.7, program sapc97; docs/physics.md 6.1).
//
// Equations (re-derived; ship-fixed axes x forward, both vessels heading the
// same way, the tug ahead; alpha_k the line's angle below horizontal at vessel
// k's tow point; tau the dynamic tension, positive = more tension):
//   EQ-SURGE-1  M_1 x_1'' + B_1 x_1' = -tau cos(alpha_1) + f_1(t)      (tug, pulled aft)
//   EQ-SURGE-2  M_7 x_7'' + B_7 x_7' = +tau cos(alpha_2) + f_7(t)      (tow, pulled forward)
//   EQ-SURGE-3  xi = x_1 cos(alpha_1) - x_7 cos(alpha_2) + xi_ns(t),
//               xi' = x_1' cos(alpha_1) - x_7' cos(alpha_2) + xi_ns'(t)
//   EQ-SURGE-4  tau = P(xi, xi') (polynomial towline, with T + tau >= 0: slack line)
//   EQ-SURGE-5  the day's maximum: on each step [t, t + h], the vertex of the
//               parabola through tau(t), tau_m, tau(t + h) when it lies
//               inside the step, else the largest of the three; tau_m is P at
//               the RK4 dense-output state of the middle (Hermite cubic,
//               Hairer, Norsett & Wanner 1993, II.6),
//                 y_m = (y(t) + y(t + h)) / 2 + h (y'(t) - y'(t + h)) / 8,
//               with the forcing of the middle; steps whose ends lie far
//               below the running maximum are skipped (kPeakGateFraction).
//               Sampling tau only at the steps would read a peak of
//               frequency w low by up to 1 - cos(w h / 2) (3.1 % at
//               w = 0.5 rad/s, h = 1 s); the rule's measured effect is in
//               docs/performance.md ("The daily maximum between steps").
//   EQ-SURGE-6  (diagnostic, SurgeParameters::linear_non_surge_tension)
//               tau = max(-T, P(xi_s, xi_s') + k_ns xi_ns + c_ns xi_ns'),
//               xi_s the surge part of EQ-SURGE-3: the non-surge tension
//               linear, added to the polynomial's surge tension.
// M_k = mass + surge added mass, B_k = linear surge damping (hull + propeller +
// wave-induced), f_k = first- plus second-order wave surge force, xi_ns the
// non-surge extension (heave, pitch, ... projected on the line tangents).
// The extension is the separation of the tow points along the end tangents:
// the tug moving forward or the tow moving aft stretches the line.
//
// Day structure: each day is an independent periodic record of length
// T_day = N dt. Integration starts at rest at t = -warmup (the record is
// periodic, so the forcing before t = 0 is the day's own end) and statistics
// are taken over [0, T_day) only: the start-up transient is excluded from every
// day, which makes days independent and lets them run in parallel, and lets
// integrate_days advance several days in lock step on one core (throughput
// only: each day's arithmetic is that of integrate_day).
//
// Lock step (integrate_days): K days' records are interleaved sample by sample
// (LockstepForcing) and the K days are the K lanes of one vector of doubles
// (GCC vector extensions; lanes::Lanes<K, W> of simulation/lanes.hpp, K/W native vectors of W
// doubles). On an interval where no day needs substeps, one RK4 step advances
// all K days with vector operations; otherwise each day takes its own
// substeps with the scalar code. Every lane performs the IEEE operations of
// the scalar code in the same order (no fused multiply-add: every target is
// built with -ffp-contract=off, cmake/TowdbHelpers.cmake), so a day's results
// are bit-identical whichever path, group or vector width it ran in. Tension
// laws are therefore written once, as templates on the number type (double
// or lanes::Lanes<K, W>), with the lanes:: helpers for max, min, clamp and
// select.
//
// Vector width: the program is built for baseline x86-64 (SSE2, W = 2). On
// a processor with AVX2, integrate_days_fastest runs four days as one AVX
// register (W = 4) in integrate_days_avx2, a function GCC compiles for AVX2
// on its own (target attribute), chosen at run time (fastest_lane_isa); its
// speed against the SSE2 path is in docs/performance.md.
//
// Integrator: classical RK4. The step is the forcing interval dt, split into
// m substeps where the local line stiffness makes the relative surge mode fast
// (snap loads): m = ceil(h_needed / ...), with omega_loc h <= max_omega_h and
// beta_loc h <= max_omega_h, omega_loc^2 = k_loc (cos^2 a1/M1 + cos^2 a2/M7),
// beta_loc = c_loc (...) + B_k/M_k. Forcing between samples: 4-point cubic
// (Catmull-Rom) interpolation of the periodic record.
//
// Units: SI (kg, N, m, s).
#ifndef TOWDB_SIMULATION_SURGE_HPP
#define TOWDB_SIMULATION_SURGE_HPP

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "common/error.hpp"
#include "simulation/lanes.hpp"

namespace towdb::simulation {

struct SurgeParameters {
  double tug_mass_kg = 0.0;          // mass + surge added mass
  double tow_mass_kg = 0.0;
  double tug_damping_n_s_m = 0.0;    // linear surge damping
  double tow_damping_n_s_m = 0.0;
  double cos_alpha_tug = 1.0;        // cos of the line angle at the tug's tow point
  double cos_alpha_tow = 1.0;
  // EQ-SURGE-6 (diagnostic, off): the non-surge extension enters as a linear
  // tension added to the polynomial of the surge extension instead of inside
  // the polynomial's argument (thesis 3.4's reading "solve the non surge
  // tensions ..., then ... the surge components"):
  //   tau = max(-T, P(xi_s, xi_s') + k_ns xi_ns + c_ns xi_ns'),
  //   xi_s = x_1 cos(alpha_1) - x_7 cos(alpha_2).
  bool linear_non_surge_tension = false;
  double non_surge_stiffness_n_m = 0.0;   // k_ns (a10, or the equivalent line of case_runner EQ-SURGE-7)
  double non_surge_damping_n_s_m = 0.0;   // c_ns (a01, or likewise)

  void validate() const;
};

// One day's periodic forcing, sampled every dt_s (all vectors the same length).
struct DayForcing {
  double dt_s = 1.0;
  std::vector<double> tug_force_n;    // f1 + f2 on the tug, surge
  std::vector<double> tow_force_n;    // f1 + f2 on the tow, surge
  std::vector<double> xi_ns_m;        // non-surge extension
  std::vector<double> xi_ns_dot_m_s;  // its time derivative

  std::size_t size() const { return tug_force_n.size(); }
  void validate() const;
};

// K days' forcing interleaved sample by sample: record[i K + l] is day l's
// sample i (one vector load gives sample i of all K days).
template <std::size_t K>
struct LockstepForcing {
  double dt_s = 1.0;
  std::vector<double> tug_force_n, tow_force_n, xi_ns_m, xi_ns_dot_m_s;  // n K values each

  std::size_t size() const { return tug_force_n.size() / K; }  // n
  // Sizes the records for n samples per day (contents unspecified).
  void resize(std::size_t n) {
    for (auto* r : {&tug_force_n, &tow_force_n, &xi_ns_m, &xi_ns_dot_m_s}) r->resize(n * K);
  }
  // Lane `to` becomes a copy of lane `from`.
  void copy_lane(std::size_t from, std::size_t to) {
    TOWDB_ASSERT(from < K && to < K);
    for (auto* r : {&tug_force_n, &tow_force_n, &xi_ns_m, &xi_ns_dot_m_s}) {
      for (std::size_t i = 0; i < size(); ++i) (*r)[i * K + to] = (*r)[i * K + from];
    }
  }
  // Copies a whole day into lane l (records already sized to day.size()).
  void set_day(std::size_t l, const DayForcing& day) {
    TOWDB_ASSERT(l < K && day.size() == size());
    for (std::size_t i = 0; i < day.size(); ++i) {
      tug_force_n[i * K + l] = day.tug_force_n[i];
      tow_force_n[i * K + l] = day.tow_force_n[i];
      xi_ns_m[i * K + l] = day.xi_ns_m[i];
      xi_ns_dot_m_s[i * K + l] = day.xi_ns_dot_m_s[i];
    }
  }
};

struct IntegratorOptions {
  double warmup_s = 1800.0;     // start-up time simulated before the day; > 5 relative-mode decay times
  double max_omega_h = 0.4;     // omega_loc * h bound (RK4 phase error per step < 1e-4 rad at 0.4)
  int max_substeps = 256;       // cap on substeps per forcing interval (snap loads)

  void validate() const;
};

struct DayStatistics {
  double max_tension_n = 0.0;   // largest dynamic tension tau over the day (EQ-SURGE-5)
  double min_tension_n = 0.0;   // smallest (>= -mean tension: slack)
  double slack_time_s = 0.0;    // time with the line slack (T + tau <= 0)
  int snatch_events = 0;        // slack -> taut transitions
  long substeps = 0;            // RK4 steps taken (for cost reporting)
  double tension_sum_n = 0.0;   // sum of tau over the day's forcing samples (for the mean)
  double tension_sum_sq_n2 = 0.0;  // sum of tau^2 over them (for the variance)
  long samples = 0;             // forcing samples recorded
  // The extension the tension law sees (EQ-SURGE-3, or its surge part under
  // EQ-SURGE-6) at the forcing samples: where the day took the line,
  // against the range a fitted law is valid over (towline FitSummary).
  double extension_min_m = std::numeric_limits<double>::infinity();
  double extension_max_m = -std::numeric_limits<double>::infinity();
  double extension_sum_m = 0.0;
  double extension_sum_sq_m2 = 0.0;
};

// The tension law: a type with, for T = double and T = lanes::Lanes<K, W>,
//   template <typename T> T tension(T xi_m, T xi_dot_m_s) const;    // tau [N], already >= -T
//   template <typename T> T stiffness(T xi_m, T xi_dot_m_s) const;  // d tau / d xi [N/m]
//   template <typename T> T damping(T xi_m, T xi_dot_m_s) const;    // d tau / d xi' [N s/m]
//   double mean_tension_n() const;                                  // T (slack when tau <= -T)
// written with +, -, *, / and the lanes:: helpers only (so that every lane
// computes what the double version computes). A law may also declare
//   static constexpr bool kForcedInline = true;
// when its three templates are forced inline (TOWDB_SURGE_INLINE): only such
// a law runs on integrate_days_avx2. That function passes AVX vectors by
// value, and an out-of-line copy of a law's template, compiled for the
// baseline, would expect them on the stack instead (in a -O0 build a law
// without TOWDB_SURGE_INLINE computed garbage there). A law that does not
// declare it runs on the baseline vectors: slower, never wrong.
// Integrates one day; optional `trace` receives tau at the forcing samples:
// trace[k] = tau at t = k dt, k = 0 .. N - 1.
template <typename TensionLaw>
DayStatistics integrate_day(const SurgeParameters& p, const DayForcing& f, const TensionLaw& law,
                            const IntegratorOptions& options, std::vector<double>* trace = nullptr);

// K days with the same record length and step, integrated in lock step (see
// the file comment), as K/W vectors of W doubles: W = 2 is SSE2's vector,
// which every x86-64 processor has; W = 4 is an AVX register, fast only in
// code compiled for AVX (integrate_days_avx2; elsewhere GCC would split it).
// Day l's statistics (and trace) are bit-identical to integrate_day on day l
// alone, for either W. (Forced inline, so that integrate_days_avx2 compiles
// the vector loop for AVX2; the scalar substep path it calls stays baseline.)
template <typename TensionLaw, std::size_t K, std::size_t W = 2>
std::array<DayStatistics, K> integrate_days(const SurgeParameters& p, const LockstepForcing<K>& f,
                                            const TensionLaw& law, const IntegratorOptions& options,
                                            const std::array<std::vector<double>*, K>& trace = {});

// Whether TensionLaw declares kForcedInline = true (see the law contract).
template <typename TensionLaw, typename = void>
inline constexpr bool kLawForcedInline = false;
template <typename TensionLaw>
inline constexpr bool kLawForcedInline<TensionLaw, std::void_t<decltype(TensionLaw::kForcedInline)>> =
    TensionLaw::kForcedInline;

// The vectors integrate_days_fastest uses on this processor: kAvx2 (four
// days in one 4-double AVX register) where the processor and the operating
// system support AVX2, else kBaseline (two 2-double vectors).
enum class LaneIsa { kBaseline, kAvx2 };
LaneIsa fastest_lane_isa();
const char* lane_isa_name(LaneIsa isa);  // "baseline", "avx2"

// (Not on Windows: GCC does not align the stack to 32 bytes there, GCC bug
// 54412, and this function spills AVX registers with aligned moves.)
#if defined(__GNUC__) && defined(__x86_64__) && !defined(_WIN32)
#define TOWDB_SURGE_HAVE_AVX2_PATH 1
// integrate_days<TensionLaw, 4, 4>, the whole RK4 loop compiled for AVX2 by
// GCC's target attribute on this function alone: everything else in the
// program stays baseline code, and functions this one calls without
// inlining keep their baseline code too. Call only when fastest_lane_isa()
// is kAvx2. Same bits as integrate_days<TensionLaw, 4> (no fused
// multiply-add: AVX2 does not imply FMA, and -ffp-contract=off).
template <typename TensionLaw>
[[gnu::target("avx2")]] std::array<DayStatistics, 4> integrate_days_avx2(
    const SurgeParameters& p, const LockstepForcing<4>& f, const TensionLaw& law, const IntegratorOptions& options,
    const std::array<std::vector<double>*, 4>& trace = {}) {
  static_assert(kLawForcedInline<TensionLaw>, "integrate_days_avx2: the law must force its templates inline");
  return integrate_days<TensionLaw, 4, 4>(p, f, law, options, trace);
}
#endif

// The vectors integrate_days_fastest<TensionLaw> takes when asked for `isa`:
// AVX2 only where the processor has it and for a law with kForcedInline,
// else the baseline vectors.
template <typename TensionLaw>
LaneIsa lane_isa_for(LaneIsa isa) {
  if (isa == LaneIsa::kAvx2 && kLawForcedInline<TensionLaw> && fastest_lane_isa() == LaneIsa::kAvx2) {
    return LaneIsa::kAvx2;
  }
  return LaneIsa::kBaseline;
}

// Four days in lock step with the vectors lane_isa_for<TensionLaw>(isa) (by
// default the fastest this processor has); the results do not depend on it.
template <typename TensionLaw>
std::array<DayStatistics, 4> integrate_days_fastest(const SurgeParameters& p, const LockstepForcing<4>& f,
                                                    const TensionLaw& law, const IntegratorOptions& options,
                                                    const std::array<std::vector<double>*, 4>& trace = {},
                                                    LaneIsa isa = fastest_lane_isa()) {
#if defined(TOWDB_SURGE_HAVE_AVX2_PATH)
  if constexpr (kLawForcedInline<TensionLaw>) {
    if (lane_isa_for<TensionLaw>(isa) == LaneIsa::kAvx2) return integrate_days_avx2(p, f, law, options, trace);
  }
#endif
  (void)isa;
  return integrate_days<TensionLaw, 4>(p, f, law, options, trace);
}

// ---------------------------------------------------------------------------
// Implementation (a template: the tension law is inlined into the RK4 loop).

namespace detail {

template <typename T>
struct StateOf {
  T x1, v1, x7, v7;
};
using State = StateOf<double>;

template <typename T>
struct ForcingOf {
  T f1, f7, xi_ns, xi_ns_dot;
};
using Forcing = ForcingOf<double>;

// The four samples around the interval [i, i + 1] of a periodic record of n
// samples: i - 1, i, i + 1, i + 2, wrapped (computed once per interval, without
// integer division).
struct Stencil {
  std::size_t im1, i, i1, i2;
};

inline Stencil stencil(std::size_t i, std::size_t n) {
  const std::size_t i1 = i + 1 == n ? 0 : i + 1;
  return {i == 0 ? n - 1 : i - 1, i, i1, i1 + 1 == n ? 0 : i1 + 1};
}

// One day's four records, read with a stride (1 for a DayForcing, K for lane
// l of a LockstepForcing<K>).
template <std::size_t Stride>
struct Records {
  const double *f1, *f7, *xi, *xi_dot;
};

inline Records<1> records_of(const DayForcing& f) {
  return {f.tug_force_n.data(), f.tow_force_n.data(), f.xi_ns_m.data(), f.xi_ns_dot_m_s.data()};
}

template <std::size_t K>
Records<K> records_of(const LockstepForcing<K>& f, std::size_t lane) {
  return {f.tug_force_n.data() + lane, f.tow_force_n.data() + lane, f.xi_ns_m.data() + lane,
          f.xi_ns_dot_m_s.data() + lane};
}

// Catmull-Rom interpolation of a periodic record at sample i + s, s in [0, 1].
template <std::size_t S>
inline double interpolate(const double* y, const Stencil& c, double s) {
  const double y0 = y[c.im1 * S], y1 = y[c.i * S], y2 = y[c.i1 * S], y3 = y[c.i2 * S];
  const double s2 = s * s, s3 = s2 * s;
  return 0.5 * ((2.0 * y1) + (-y0 + y2) * s + (2.0 * y0 - 5.0 * y1 + 4.0 * y2 - y3) * s2 +
                (-y0 + 3.0 * y1 - 3.0 * y2 + y3) * s3);
}

// Catmull-Rom at s = 1/2: (-y0 + 9 y1 + 9 y2 - y3) / 16.
template <typename T>
TOWDB_SURGE_INLINE T midpoint(T y0, T y1, T y2, T y3) {
  return (9.0 * (y1 + y2) - y0 - y3) * 0.0625;
}

template <std::size_t S>
inline double midpoint(const double* y, const Stencil& c) {
  return midpoint(y[c.im1 * S], y[c.i * S], y[c.i1 * S], y[c.i2 * S]);
}

template <std::size_t S>
inline Forcing forcing_at(const Records<S>& f, const Stencil& c, double s) {
  return {interpolate<S>(f.f1, c, s), interpolate<S>(f.f7, c, s), interpolate<S>(f.xi, c, s),
          interpolate<S>(f.xi_dot, c, s)};
}

template <std::size_t S>
inline Forcing midpoint_forcing(const Records<S>& f, const Stencil& c) {
  return {midpoint<S>(f.f1, c), midpoint<S>(f.f7, c), midpoint<S>(f.xi, c), midpoint<S>(f.xi_dot, c)};
}

template <std::size_t S>
inline Forcing sample_at(const Records<S>& f, std::size_t i) {
  return {f.f1[i * S], f.f7[i * S], f.xi[i * S], f.xi_dot[i * S]};
}

template <typename T>
TOWDB_SURGE_INLINE StateOf<T> axpy(const StateOf<T>& y, double h, const StateOf<T>& k) {
  return {y.x1 + h * k.x1, y.v1 + h * k.v1, y.x7 + h * k.x7, y.v7 + h * k.v7};
}

// EQ-SURGE-5's gate. A step whose ends lie more than this fraction of the
// total peak tension below the running maximum is not refined: to matter,
// the tension would have to rise between its ends by a fifth of the largest
// total tension within one step. A component that can do that has w h near
// pi, where neither the record nor the parabola resolves it anyway (a
// resolved one, w h <= 1, rises at most 1 - cos(1/2) = 12 % of its
// amplitude between samples). The gate depends on the day's own values
// only, so every day gets the same answer in any lock-step group.
inline constexpr double kPeakGateFraction = 0.2;

// The per-day arithmetic of the RK4 loop, shared by the single-day and the
// lock-step paths so that both perform the same operations in the same order
// (a day's result does not depend on the days it was integrated with).
template <typename TensionLaw>
struct SurgeKernel {
  // Held by value (a few doubles and a pointer): the statistics written in
  // the loop through references cannot alias them.
  const SurgeParameters p;
  const TensionLaw law;
  double mean_tension_n;          // T: slack when tau <= -T
  double inv_mass_line_per_kg;    // cos^2 a1 / M1 + cos^2 a2 / M7
  double hull_rate_per_s;         // max(B1/M1, B7/M7)

  SurgeKernel(const SurgeParameters& p_, const TensionLaw& law_)
      : p(p_),
        law(law_),
        mean_tension_n(law_.mean_tension_n()),
        inv_mass_line_per_kg(p_.cos_alpha_tug * p_.cos_alpha_tug / p_.tug_mass_kg +
                      p_.cos_alpha_tow * p_.cos_alpha_tow / p_.tow_mass_kg),
        hull_rate_per_s(std::max(p_.tug_damping_n_s_m / p_.tug_mass_kg, p_.tow_damping_n_s_m / p_.tow_mass_kg)) {}

  // The line's extension and its rate (EQ-SURGE-3).
  template <typename T>
  TOWDB_SURGE_INLINE void extension(const StateOf<T>& y, const ForcingOf<T>& g, T& xi, T& xi_dot) const {
    xi = y.x1 * p.cos_alpha_tug - y.x7 * p.cos_alpha_tow + g.xi_ns;
    xi_dot = y.v1 * p.cos_alpha_tug - y.v7 * p.cos_alpha_tow + g.xi_ns_dot;
  }

  // The extension the polynomial sees: the whole of EQ-SURGE-3, or its surge
  // part only under EQ-SURGE-6.
  template <typename T>
  TOWDB_SURGE_INLINE void law_extension(const StateOf<T>& y, const ForcingOf<T>& g, T& xi, T& xi_dot) const {
    if (!p.linear_non_surge_tension) {
      extension(y, g, xi, xi_dot);
    } else {
      xi = y.x1 * p.cos_alpha_tug - y.x7 * p.cos_alpha_tow;
      xi_dot = y.v1 * p.cos_alpha_tug - y.v7 * p.cos_alpha_tow;
    }
  }

  // The dynamic tension at state y and forcing g (EQ-SURGE-4, or EQ-SURGE-6).
  template <typename T>
  TOWDB_SURGE_INLINE T tension(const StateOf<T>& y, const ForcingOf<T>& g) const {
    T xi, xi_dot;
    law_extension(y, g, xi, xi_dot);
    const T tau = law.tension(xi, xi_dot);
    if (!p.linear_non_surge_tension) return tau;
    const T ns = p.non_surge_stiffness_n_m * g.xi_ns + p.non_surge_damping_n_s_m * g.xi_ns_dot;
    return lanes::max(tau + ns, lanes::splat<T>(-mean_tension_n));
  }

  // Derivative of the state; also returns the tension it used.
  template <typename T>
  TOWDB_SURGE_INLINE StateOf<T> derivative(const StateOf<T>& y0, const ForcingOf<T>& g, T* tau_out) const {
    const T tau = tension(y0, g);
    *tau_out = tau;
    return StateOf<T>{y0.v1, (-tau * p.cos_alpha_tug + g.f1 - p.tug_damping_n_s_m * y0.v1) / p.tug_mass_kg, y0.v7,
                      (tau * p.cos_alpha_tow + g.f7 - p.tow_damping_n_s_m * y0.v7) / p.tow_mass_kg};
  }

  // The rate that bounds the step on the interval starting at state y with
  // forcing g0: max(omega_loc, beta_loc) from the local stiffness and damping.
  template <typename T>
  TOWDB_SURGE_INLINE T rate(const StateOf<T>& y, const ForcingOf<T>& g0) const {
    T xi, xi_dot;
    law_extension(y, g0, xi, xi_dot);
    const T zero = lanes::splat<T>(0.0);
    const T k_line = lanes::max(zero, law.stiffness(xi, xi_dot)) * inv_mass_line_per_kg;
    const T c_loc = lanes::max(zero, law.damping(xi, xi_dot));
    T omega;
    if constexpr (std::is_same_v<T, double>) {
      omega = std::sqrt(k_line);
    } else {
      // Built from the lanes' square roots as a vector literal (see splat).
      for (std::size_t i = 0; i < T::kParts; ++i) {
        const auto k = k_line.h[i];
        if constexpr (sizeof(k) == 2 * sizeof(double)) {
          omega.h[i] = decltype(k){std::sqrt(k[0]), std::sqrt(k[1])};
        } else {
          omega.h[i] = decltype(k){std::sqrt(k[0]), std::sqrt(k[1]), std::sqrt(k[2]), std::sqrt(k[3])};
        }
      }
    }
    return lanes::max(omega, c_loc * inv_mass_line_per_kg + hull_rate_per_s);
  }

  // Whether one step covers an interval of length dt at that rate (also for
  // NaN: the caller's checks report it).
  TOWDB_SURGE_INLINE static bool one_substep(double rate, double dt, const IntegratorOptions& options) {
    return !(rate * dt > options.max_omega_h);
  }

  // Substeps for an interval of length dt at that rate.
  TOWDB_SURGE_INLINE static int substeps(double rate, double dt, const IntegratorOptions& options) {
    if (one_substep(rate, dt, options)) return 1;
    return std::min(options.max_substeps, static_cast<int>(std::ceil(rate * dt / options.max_omega_h)));
  }

  // Statistics at every substep start (where k1 applies: carried over from
  // the previous step's end), so snap-load troughs between forcing samples
  // count; each point stands for h. tau at the
  // interval's first substep is tau at forcing sample `sample_index`. (The
  // maximum is taken over each step by step_peak instead.)
  // `xi` (the law's extension at the sample) is read on the first substep only.
  TOWDB_SURGE_INLINE void record(DayStatistics& stats, bool& was_slack, double tau, double h, bool first_substep,
                                 std::size_t sample_index, std::vector<double>* trace, double xi) const {
    const bool slack = tau <= -mean_tension_n;
    stats.min_tension_n = lanes::min(stats.min_tension_n, tau);
    if (slack) stats.slack_time_s += h;
    if (was_slack && !slack) ++stats.snatch_events;
    was_slack = slack;
    if (first_substep) {
      stats.tension_sum_n += tau;
      stats.tension_sum_sq_n2 += tau * tau;
      ++stats.samples;
      if (trace) (*trace)[sample_index] = tau;
      stats.extension_min_m = lanes::min(stats.extension_min_m, xi);
      stats.extension_max_m = lanes::max(stats.extension_max_m, xi);
      stats.extension_sum_m += xi;
      stats.extension_sum_sq_m2 += xi * xi;
    }
  }

  // The extension the law sees at state y and forcing g (for the statistics).
  template <typename T>
  TOWDB_SURGE_INLINE T law_extension_only(const StateOf<T>& y, const ForcingOf<T>& g) const {
    T xi, xi_dot;
    law_extension(y, g, xi, xi_dot);
    return xi;
  }

  // The largest tension on a step of length h from y0 (derivative f0, tension
  // tau0) to y1 (f1, tau1), forcing gm at its middle (EQ-SURGE-5): the
  // vertex of the parabola through tau0, tau_m, tau1 when it lies inside
  // the step, where tau_m is the tension of the RK4 dense-output state at
  // the middle, y_m = (y0 + y1)/2 + h (f0 - f1)/8; otherwise the largest of
  // the three.
  template <typename T>
  TOWDB_SURGE_INLINE T step_peak(const StateOf<T>& y0, const StateOf<T>& f0, T tau0, const StateOf<T>& y1,
                                 const StateOf<T>& f1, T tau1, const ForcingOf<T>& gm, double h) const {
    const double e = 0.125 * h;
    const StateOf<T> ym{0.5 * (y0.x1 + y1.x1) + e * (f0.x1 - f1.x1), 0.5 * (y0.v1 + y1.v1) + e * (f0.v1 - f1.v1),
                        0.5 * (y0.x7 + y1.x7) + e * (f0.x7 - f1.x7), 0.5 * (y0.v7 + y1.v7) + e * (f0.v7 - f1.v7)};
    const T tau_m = tension(ym, gm);
    // p(s) = a s^2 + b s + tau0 through (0, tau0), (1/2, tau_m), (1, tau1);
    // an interior maximum when a < 0 and 0 < -b / 2a < 1.
    const T a = 2.0 * (tau0 + tau1) - 4.0 * tau_m;
    const T b = 4.0 * tau_m - tau1 - 3.0 * tau0;
    const T zero = lanes::splat<T>(0.0);
    const T ends = lanes::max(lanes::max(tau0, tau1), tau_m);
    const T vertex = tau0 - b * b / (4.0 * a);
    return lanes::select((a < zero) & (zero < b) & (b < -2.0 * a), lanes::max(ends, vertex), ends);
  }

  // Whether to refine a step whose ends carry tau0 and tau1 against the
  // running maximum max_tau (EQ-SURGE-5's gate): not when both ends lie more
  // than kPeakGateFraction of the total peak tension T + max_tau below it.
  // (Written as "not below" so that it holds when the threshold is NaN: a
  // law without a slack limit has T = infinity and starts at max_tau = -T.)
  template <typename T>
  TOWDB_SURGE_INLINE auto peak_gate(T tau0, T tau1, T max_tau) const {
    return lanes::negate(lanes::max(tau0, tau1) < max_tau - kPeakGateFraction * (max_tau + mean_tension_n));
  }

  // The running maximum after a step (EQ-SURGE-5): raised to step_peak where
  // peak_gate holds; step_peak is evaluated only when some lane needs it.
  template <typename T>
  TOWDB_SURGE_INLINE void raise_max(T& max_tau, const StateOf<T>& y0, const StateOf<T>& f0, T tau0,
                                    const StateOf<T>& y1, const StateOf<T>& f1, T tau1, const ForcingOf<T>& gm,
                                    double h) const {
    const auto gate = peak_gate(tau0, tau1, max_tau);
    if (lanes::any(gate)) {
      max_tau = lanes::select(gate, lanes::max(max_tau, step_peak(y0, f0, tau0, y1, f1, tau1, gm, h)), max_tau);
    }
  }

  template <typename T>
  TOWDB_SURGE_INLINE static void advance(StateOf<T>& y, double h, const StateOf<T>& k1, const StateOf<T>& k2,
                                         const StateOf<T>& k3, const StateOf<T>& k4) {
    y.x1 += h / 6.0 * (k1.x1 + 2.0 * k2.x1 + 2.0 * k3.x1 + k4.x1);
    y.v1 += h / 6.0 * (k1.v1 + 2.0 * k2.v1 + 2.0 * k3.v1 + k4.v1);
    y.x7 += h / 6.0 * (k1.x7 + 2.0 * k2.x7 + 2.0 * k3.x7 + k4.x7);
    y.v7 += h / 6.0 * (k1.v7 + 2.0 * k2.v7 + 2.0 * k3.v7 + k4.v7);
  }

  // One forcing interval [i, i + 1] of one day in m substeps (the general
  // path). k1 and tau hold the derivative and tension at y on entry (the
  // forcing at sample i) and at the new y on return: each step's end
  // derivative is the next step's k1 (first same as last), and step_peak
  // needs both.
  template <std::size_t S>
  void interval(State& y, State& k1, double& tau, double dt, const Records<S>& f, const Stencil& c, int m,
                bool recording, std::size_t sample_index, DayStatistics& stats, bool& was_slack,
                std::vector<double>* trace) const {
    const double h = dt / m;
    for (int j = 0; j < m; ++j) {
      const Forcing gm = m == 1 ? midpoint_forcing(f, c) : forcing_at(f, c, (j + 0.5) / m);
      const Forcing gb = j + 1 == m ? sample_at(f, c.i1) : forcing_at(f, c, static_cast<double>(j + 1) / m);
      double unused = 0.0;
      if (recording) {
        const double xi = j == 0 ? law_extension_only(y, sample_at(f, c.i)) : 0.0;
        record(stats, was_slack, tau, h, j == 0, sample_index, trace, xi);
      }
      const State k2 = derivative(axpy(y, 0.5 * h, k1), gm, &unused);
      const State k3 = derivative(axpy(y, 0.5 * h, k2), gm, &unused);
      const State k4 = derivative(axpy(y, h, k3), gb, &unused);
      const State y0 = y;
      advance(y, h, k1, k2, k3, k4);
      double tau1 = 0.0;
      const State f1 = derivative(y, gb, &tau1);
      if (recording) raise_max(stats.max_tension_n, y0, k1, tau, y, f1, tau1, gm, h);
      k1 = f1;
      tau = tau1;
    }
    stats.substeps += m;
  }
};

// The lock-step statistics of K days, one lane per day (what
// SurgeKernel::record accumulates, lane by lane).
template <std::size_t K, std::size_t W>
struct LaneStatistics {
  using V = lanes::Lanes<K, W>;
  using Mask = lanes::LaneMask<K, W>;
  V max_tension, min_tension, slack_time, sum, sum_sq;
  V extension_min, extension_max, extension_sum, extension_sum_sq;
  Mask snatch_events, was_slack;  // counts; masks (-1 = slack)
  std::array<long, K> substeps{}, samples{};

  void to(std::size_t l, DayStatistics& s, bool& slack) const {
    s.max_tension_n = max_tension[l];
    s.min_tension_n = min_tension[l];
    s.slack_time_s = slack_time[l];
    s.snatch_events = static_cast<int>(snatch_events[l]);
    s.substeps = substeps[l];
    s.tension_sum_n = sum[l];
    s.tension_sum_sq_n2 = sum_sq[l];
    s.samples = samples[l];
    s.extension_min_m = extension_min[l];
    s.extension_max_m = extension_max[l];
    s.extension_sum_m = extension_sum[l];
    s.extension_sum_sq_m2 = extension_sum_sq[l];
    slack = was_slack[l] != 0;
  }
  void from(std::size_t l, const DayStatistics& s, bool slack) {
    max_tension.set(l, s.max_tension_n);
    min_tension.set(l, s.min_tension_n);
    slack_time.set(l, s.slack_time_s);
    snatch_events.set(l, s.snatch_events);
    substeps[l] = s.substeps;
    sum.set(l, s.tension_sum_n);
    sum_sq.set(l, s.tension_sum_sq_n2);
    samples[l] = s.samples;
    extension_min.set(l, s.extension_min_m);
    extension_max.set(l, s.extension_max_m);
    extension_sum.set(l, s.extension_sum_m);
    extension_sum_sq.set(l, s.extension_sum_sq_m2);
    was_slack.set(l, slack ? -1 : 0);
  }
  // SurgeKernel::record for the first (only) substep of an interval.
  TOWDB_SURGE_INLINE void record(V tau, V xi, double minus_mean, double h, std::size_t sample_index,
                                 const std::array<std::vector<double>*, K>& trace) {
    const Mask slack = tau <= lanes::splat<V>(minus_mean);
    min_tension = lanes::min(min_tension, tau);
    slack_time = lanes::select(slack, slack_time + h, slack_time);
    snatch_events -= was_slack & ~slack;
    was_slack = slack;
    sum += tau;
    sum_sq += tau * tau;
    extension_min = lanes::min(extension_min, xi);
    extension_max = lanes::max(extension_max, xi);
    extension_sum += xi;
    extension_sum_sq += xi * xi;
    for (std::size_t l = 0; l < K; ++l) {
      ++samples[l];
      if (trace[l]) (*trace[l])[sample_index] = tau[l];
    }
  }
};

template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE State lane(const StateOf<lanes::Lanes<K, W>>& v, std::size_t l) {
  return {v.x1[l], v.v1[l], v.x7[l], v.v7[l]};
}

template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE void set_lane(StateOf<lanes::Lanes<K, W>>& v, std::size_t l, const State& s) {
  v.x1.set(l, s.x1);
  v.v1.set(l, s.v1);
  v.x7.set(l, s.x7);
  v.v7.set(l, s.v7);
}

template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE lanes::Lanes<K, W> load(const std::vector<double>& r, std::size_t i) {
  typedef typename lanes::Native<W>::Unaligned Unaligned;
  lanes::Lanes<K, W> v;
  for (std::size_t j = 0; j < K / W; ++j) v.h[j] = *reinterpret_cast<const Unaligned*>(r.data() + i * K + j * W);
  return v;
}

template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE ForcingOf<lanes::Lanes<K, W>> sample_lanes(const LockstepForcing<K>& f, std::size_t i) {
  return {load<K, W>(f.tug_force_n, i), load<K, W>(f.tow_force_n, i), load<K, W>(f.xi_ns_m, i),
          load<K, W>(f.xi_ns_dot_m_s, i)};
}

template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE lanes::Lanes<K, W> midpoint_lanes(const std::vector<double>& r, const Stencil& c) {
  return midpoint(load<K, W>(r, c.im1), load<K, W>(r, c.i), load<K, W>(r, c.i1), load<K, W>(r, c.i2));
}

template <std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE ForcingOf<lanes::Lanes<K, W>> midpoint_lanes(const LockstepForcing<K>& f, const Stencil& c) {
  return {midpoint_lanes<K, W>(f.tug_force_n, c), midpoint_lanes<K, W>(f.tow_force_n, c),
          midpoint_lanes<K, W>(f.xi_ns_m, c), midpoint_lanes<K, W>(f.xi_ns_dot_m_s, c)};
}

// The steps of one periodic day of n samples: integration starts at rest
// `warmup` samples before sample 0 (the warm-up is the day's own end, at
// sample `start`) and runs `total` intervals; statistics from sample 0 on.
struct DaySteps {
  std::size_t warmup, start, total;
};

inline DaySteps day_steps(double warmup_s, double dt, std::size_t n) {
  const std::size_t warmup = static_cast<std::size_t>(std::ceil(warmup_s / dt));
  return {warmup, (n - warmup % n) % n, warmup + n};
}

// The single-day loop (integrate_day).
template <typename TensionLaw>
DayStatistics integrate_one(const SurgeKernel<TensionLaw>& kernel, const DayForcing& f,
                            const IntegratorOptions& options, std::vector<double>* trace) {
  const std::size_t n = f.size();
  const double dt = f.dt_s;
  const Records<1> r = records_of(f);
  const DaySteps steps = day_steps(options.warmup_s, dt, n);
  DayStatistics stats;
  stats.max_tension_n = -kernel.mean_tension_n;
  stats.min_tension_n = std::numeric_limits<double>::infinity();
  if (trace) trace->assign(n, 0.0);
  State y{0.0, 0.0, 0.0, 0.0};
  double tau = 0.0;
  State k1 = kernel.derivative(y, sample_at(r, steps.start), &tau);
  bool was_slack = false;
  std::size_t i = steps.start;
  for (std::size_t step = 0; step < steps.total; ++step) {
    const Stencil c = stencil(i, n);
    const bool recording = step >= steps.warmup;
    const int m = kernel.substeps(kernel.rate(y, sample_at(r, i)), dt, options);
    kernel.interval(y, k1, tau, dt, r, c, m, recording, recording ? step - steps.warmup : 0, stats, was_slack, trace);
    i = c.i1;
  }
  return stats;
}

}  // namespace detail

template <typename TensionLaw, std::size_t K, std::size_t W>
TOWDB_SURGE_INLINE std::array<DayStatistics, K> integrate_days(const SurgeParameters& p, const LockstepForcing<K>& f,
                                                               const TensionLaw& law, const IntegratorOptions& options,
                                                               const std::array<std::vector<double>*, K>& trace) {
  using detail::Forcing;
  using detail::ForcingOf;
  using detail::State;
  using detail::StateOf;
  using V = lanes::Lanes<K, W>;
  const std::size_t n = f.size();
  const double dt = f.dt_s;
  TOWDB_ASSERT(f.tow_force_n.size() == n * K && f.xi_ns_m.size() == n * K && f.xi_ns_dot_m_s.size() == n * K);
  const detail::SurgeKernel<TensionLaw> kernel(p, law);

  const detail::DaySteps steps = detail::day_steps(options.warmup_s, dt, n);

  detail::LaneStatistics<K, W> stats{};
  stats.max_tension = lanes::splat<V>(-kernel.mean_tension_n);
  stats.min_tension = lanes::splat<V>(std::numeric_limits<double>::infinity());
  stats.extension_min = lanes::splat<V>(std::numeric_limits<double>::infinity());
  stats.extension_max = lanes::splat<V>(-std::numeric_limits<double>::infinity());
  for (std::size_t l = 0; l < K; ++l) {
    if (trace[l]) trace[l]->assign(n, 0.0);
  }
  const V zero = lanes::splat<V>(0.0);
  StateOf<V> y{zero, zero, zero, zero};
  V tau;
  StateOf<V> k1 = kernel.derivative(y, detail::sample_lanes<K, W>(f, steps.start), &tau);

  std::size_t i = steps.start;
  for (std::size_t step = 0; step < steps.total; ++step) {
    const detail::Stencil c = detail::stencil(i, n);
    const bool recording = step >= steps.warmup;
    const std::size_t sample_index = recording ? step - steps.warmup : 0;
    const ForcingOf<V> g0 = detail::sample_lanes<K, W>(f, i);
    const V rate = kernel.rate(y, g0);
    bool one_step = true;
    for (std::size_t l = 0; l < K; ++l) one_step = one_step && kernel.one_substep(rate[l], dt, options);
    if (one_step) {
      // Every day takes one step: kernel.interval with m = 1, all lanes at once.
      const ForcingOf<V> gm = detail::midpoint_lanes<K, W>(f, c);
      const ForcingOf<V> gb = detail::sample_lanes<K, W>(f, c.i1);
      V unused, tau1;
      if (recording) stats.record(tau, kernel.law_extension_only(y, g0), -kernel.mean_tension_n, dt, sample_index, trace);
      const StateOf<V> k2 = kernel.derivative(detail::axpy(y, 0.5 * dt, k1), gm, &unused);
      const StateOf<V> k3 = kernel.derivative(detail::axpy(y, 0.5 * dt, k2), gm, &unused);
      const StateOf<V> k4 = kernel.derivative(detail::axpy(y, dt, k3), gb, &unused);
      const StateOf<V> y0 = y;
      detail::SurgeKernel<TensionLaw>::advance(y, dt, k1, k2, k3, k4);
      const StateOf<V> f1 = kernel.derivative(y, gb, &tau1);
      if (recording) kernel.raise_max(stats.max_tension, y0, k1, tau, y, f1, tau1, gm, dt);
      k1 = f1;
      tau = tau1;
      for (std::size_t l = 0; l < K; ++l) ++stats.substeps[l];
    } else {
      // Some day needs substeps: each day takes its own, with the scalar code.
      for (std::size_t l = 0; l < K; ++l) {
        const detail::Records<K> r = detail::records_of(f, l);
        State yl = detail::lane(y, l);
        State kl = detail::lane(k1, l);
        double taul = tau[l];
        DayStatistics sl;
        bool was_slack = false;
        stats.to(l, sl, was_slack);
        const int m = kernel.substeps(rate[l], dt, options);
        kernel.interval(yl, kl, taul, dt, r, c, m, recording, sample_index, sl, was_slack, trace[l]);
        stats.from(l, sl, was_slack);
        detail::set_lane(y, l, yl);
        detail::set_lane(k1, l, kl);
        tau.set(l, taul);
      }
    }
    i = c.i1;
  }
  std::array<DayStatistics, K> out;
  for (std::size_t l = 0; l < K; ++l) {
    bool unused = false;
    stats.to(l, out[l], unused);
  }
  return out;
}

template <typename TensionLaw>
DayStatistics integrate_day(const SurgeParameters& p, const DayForcing& f, const TensionLaw& law,
                            const IntegratorOptions& options, std::vector<double>* trace) {
  return detail::integrate_one(detail::SurgeKernel<TensionLaw>(p, law), f, options, trace);
}

}  // namespace towdb::simulation

#endif  // TOWDB_SIMULATION_SURGE_HPP
