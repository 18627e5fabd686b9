// Nonlinear surge of tug and tow on the towline: the time-domain core of the
// long-time towing simulation (thesis 3.7, program sapc97; physics-notes.md 8).
//
// Equations (re-derived; ship-fixed axes x forward, both vessels heading the
// same way, the tug ahead; alpha_k the line's angle below horizontal at vessel
// k's tow point; tau the dynamic tension, positive = more tension):
//   EQ-SURGE-1  M_1 x_1'' + B_1 x_1' = -tau cos(alpha_1) + f_1(t)      (tug, pulled aft)
//   EQ-SURGE-2  M_7 x_7'' + B_7 x_7' = +tau cos(alpha_2) + f_7(t)      (tow, pulled forward)
//   EQ-SURGE-3  xi = x_1 cos(alpha_1) - x_7 cos(alpha_2) + xi_ns(t),
//               xi' = x_1' cos(alpha_1) - x_7' cos(alpha_2) + xi_ns'(t)
//   EQ-SURGE-4  tau = P(xi, xi') (polynomial towline, with T + tau >= 0: slack line)
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
#include <limits>
#include <vector>

#include "common/error.hpp"

// The RK4 loop's helpers must be inlined into it (GCC 12 otherwise keeps
// SurgeKernel::derivative out of line: 25 % slower per step).
#if defined(__GNUC__)
#define TOWDB_SURGE_INLINE [[gnu::always_inline]] inline
#else
#define TOWDB_SURGE_INLINE inline
#endif

namespace towdb::simulation {

struct SurgeParameters {
  double tug_mass_kg = 0.0;          // mass + surge added mass
  double tow_mass_kg = 0.0;
  double tug_damping_n_s_m = 0.0;    // linear surge damping
  double tow_damping_n_s_m = 0.0;
  double cos_alpha_tug = 1.0;        // cos of the line angle at the tug's tow point
  double cos_alpha_tow = 1.0;

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

struct IntegratorOptions {
  double warmup_s = 1800.0;     // start-up time simulated before the day; > 5 relative-mode decay times
  double max_omega_h = 0.4;     // omega_loc * h bound (RK4 phase error per step < 1e-4 rad at 0.4)
  int max_substeps = 256;       // cap on substeps per forcing interval (snap loads)

  void validate() const;
};

struct DayStatistics {
  double max_tension_n = 0.0;   // largest dynamic tension tau over the day
  double min_tension_n = 0.0;   // smallest (>= -mean tension: slack)
  double slack_time_s = 0.0;    // time with the line slack (T + tau <= 0)
  int snatch_events = 0;        // slack -> taut transitions
  long substeps = 0;            // RK4 steps taken (for cost reporting)
  double tension_sum_n = 0.0;   // sum of tau over the day's forcing samples (for the mean)
  double tension_sum_sq_n2 = 0.0;  // sum of tau^2 over them (for the variance)
  long samples = 0;             // forcing samples recorded
};

// The tension law: a type with
//   double tension(double xi_m, double xi_dot_m_s) const;       // tau [N], already >= -T
//   double stiffness(double xi_m, double xi_dot_m_s) const;     // d tau / d xi [N/m]
//   double damping(double xi_m, double xi_dot_m_s) const;       // d tau / d xi' [N s/m]
//   double mean_tension_n() const;                              // T (slack when tau <= -T)
// Integrates one day; optional `trace` receives tau at the forcing samples:
// trace[k] = tau at t = k dt, k = 0 .. N - 1.
template <typename TensionLaw>
DayStatistics integrate_day(const SurgeParameters& p, const DayForcing& f, const TensionLaw& law,
                            const IntegratorOptions& options, std::vector<double>* trace = nullptr);

// K days with the same record length and step, integrated in lock step: each
// forcing interval is one RK4 step for every day when none needs substeps,
// with the K days' stages interleaved (their dependency chains overlap in the
// processor; about 2x the single-day throughput at K = 4), and day by day
// otherwise. Day l's statistics are bit-identical to integrate_day on f[l]
// alone: every day performs the same operations in the same order.
template <typename TensionLaw, std::size_t K>
std::array<DayStatistics, K> integrate_days(const SurgeParameters& p, const std::array<const DayForcing*, K>& f,
                                            const TensionLaw& law, const IntegratorOptions& options,
                                            const std::array<std::vector<double>*, K>& trace = {});

// ---------------------------------------------------------------------------
// Implementation (a template: the tension law is inlined into the RK4 loop).

namespace detail {

struct State {
  double x1, v1, x7, v7;
};

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

// Catmull-Rom interpolation of a periodic record at sample i + s, s in [0, 1].
inline double interpolate(const std::vector<double>& y, const Stencil& c, double s) {
  const double y0 = y[c.im1], y1 = y[c.i], y2 = y[c.i1], y3 = y[c.i2];
  const double s2 = s * s, s3 = s2 * s;
  return 0.5 * ((2.0 * y1) + (-y0 + y2) * s + (2.0 * y0 - 5.0 * y1 + 4.0 * y2 - y3) * s2 +
                (-y0 + 3.0 * y1 - 3.0 * y2 + y3) * s3);
}

struct Forcing {
  double f1, f7, xi_ns, xi_ns_dot;
};

// Catmull-Rom at s = 1/2: (-y0 + 9 y1 + 9 y2 - y3) / 16.
inline double midpoint(const std::vector<double>& y, const Stencil& c) {
  return (9.0 * (y[c.i] + y[c.i1]) - y[c.im1] - y[c.i2]) * 0.0625;
}

inline Forcing forcing_at(const DayForcing& f, const Stencil& c, double s) {
  return {interpolate(f.tug_force_n, c, s), interpolate(f.tow_force_n, c, s), interpolate(f.xi_ns_m, c, s),
          interpolate(f.xi_ns_dot_m_s, c, s)};
}

inline Forcing midpoint_forcing(const DayForcing& f, const Stencil& c) {
  return {midpoint(f.tug_force_n, c), midpoint(f.tow_force_n, c), midpoint(f.xi_ns_m, c),
          midpoint(f.xi_ns_dot_m_s, c)};
}

inline Forcing sample_at(const DayForcing& f, std::size_t i) {
  return {f.tug_force_n[i], f.tow_force_n[i], f.xi_ns_m[i], f.xi_ns_dot_m_s[i]};
}

inline State axpy(const State& y, double h, const State& k) {
  return {y.x1 + h * k.x1, y.v1 + h * k.v1, y.x7 + h * k.x7, y.v7 + h * k.v7};
}

}  // namespace detail

namespace detail {

// The per-day arithmetic of the RK4 loop, shared by the single-day and the
// lock-step paths so that both perform the same operations in the same order
// (a day's result does not depend on the days it was integrated with).
template <typename TensionLaw>
struct SurgeKernel {
  // Held by value (a few doubles and a pointer): the statistics written in
  // the loop through references cannot alias them.
  const SurgeParameters p;
  const TensionLaw law;
  double mean;            // T: slack when tau <= -T
  double inv_mass_line;   // cos^2 a1 / M1 + cos^2 a2 / M7
  double hull_rate;       // max(B1/M1, B7/M7)

  SurgeKernel(const SurgeParameters& p_, const TensionLaw& law_)
      : p(p_),
        law(law_),
        mean(law_.mean_tension_n()),
        inv_mass_line(p_.cos_alpha_tug * p_.cos_alpha_tug / p_.tug_mass_kg +
                      p_.cos_alpha_tow * p_.cos_alpha_tow / p_.tow_mass_kg),
        hull_rate(std::max(p_.tug_damping_n_s_m / p_.tug_mass_kg, p_.tow_damping_n_s_m / p_.tow_mass_kg)) {}

  // Derivative of the state; also returns the tension it used.
  TOWDB_SURGE_INLINE State derivative(const State& y0, const Forcing& g, double* tau_out) const {
    const double xi = y0.x1 * p.cos_alpha_tug - y0.x7 * p.cos_alpha_tow + g.xi_ns;
    const double xi_dot = y0.v1 * p.cos_alpha_tug - y0.v7 * p.cos_alpha_tow + g.xi_ns_dot;
    const double tau = law.tension(xi, xi_dot);
    *tau_out = tau;
    return State{y0.v1, (-tau * p.cos_alpha_tug + g.f1 - p.tug_damping_n_s_m * y0.v1) / p.tug_mass_kg, y0.v7,
                 (tau * p.cos_alpha_tow + g.f7 - p.tow_damping_n_s_m * y0.v7) / p.tow_mass_kg};
  }

  // Substeps for the interval starting at state y with forcing g0: the local
  // stiffness and damping of the line bound omega_loc h and beta_loc h.
  TOWDB_SURGE_INLINE int substeps(const State& y, const Forcing& g0, double dt,
                                  const IntegratorOptions& options) const {
    const double xi = y.x1 * p.cos_alpha_tug - y.x7 * p.cos_alpha_tow + g0.xi_ns;
    const double xi_dot = y.v1 * p.cos_alpha_tug - y.v7 * p.cos_alpha_tow + g0.xi_ns_dot;
    const double k_loc = std::max(0.0, law.stiffness(xi, xi_dot));
    const double c_loc = std::max(0.0, law.damping(xi, xi_dot));
    const double rate = std::max(std::sqrt(k_loc * inv_mass_line), c_loc * inv_mass_line + hull_rate);
    if (!(rate * dt > options.max_omega_h)) return 1;  // also NaN: the caller's checks report it
    return std::min(options.max_substeps, static_cast<int>(std::ceil(rate * dt / options.max_omega_h)));
  }

  // Statistics at every substep start (the k1 evaluation), so snap-load peaks
  // between forcing samples count; each point stands for h. tau at the
  // interval's first substep is tau at forcing sample `sample_index`.
  TOWDB_SURGE_INLINE void record(DayStatistics& stats, bool& was_slack, double tau, double h, bool first_substep,
                                 std::size_t sample_index, std::vector<double>* trace) const {
    const bool slack = tau <= -mean;
    stats.max_tension_n = std::max(stats.max_tension_n, tau);
    stats.min_tension_n = std::min(stats.min_tension_n, tau);
    if (slack) stats.slack_time_s += h;
    if (was_slack && !slack) ++stats.snatch_events;
    was_slack = slack;
    if (first_substep) {
      stats.tension_sum_n += tau;
      stats.tension_sum_sq_n2 += tau * tau;
      ++stats.samples;
      if (trace) (*trace)[sample_index] = tau;
    }
  }

  TOWDB_SURGE_INLINE static void advance(State& y, double h, const State& k1, const State& k2, const State& k3,
                                         const State& k4) {
    y.x1 += h / 6.0 * (k1.x1 + 2.0 * k2.x1 + 2.0 * k3.x1 + k4.x1);
    y.v1 += h / 6.0 * (k1.v1 + 2.0 * k2.v1 + 2.0 * k3.v1 + k4.v1);
    y.x7 += h / 6.0 * (k1.x7 + 2.0 * k2.x7 + 2.0 * k3.x7 + k4.x7);
    y.v7 += h / 6.0 * (k1.v7 + 2.0 * k2.v7 + 2.0 * k3.v7 + k4.v7);
  }

  // One forcing interval [i, i + 1] of one day in m substeps (the general path).
  void interval(State& y, const DayForcing& f, const Stencil& c, const Forcing& g0, int m, bool recording,
                std::size_t sample_index, DayStatistics& stats, bool& was_slack,
                std::vector<double>* trace) const {
    const double h = f.dt_s / m;
    Forcing ga = g0;
    for (int j = 0; j < m; ++j) {
      const Forcing gm = m == 1 ? midpoint_forcing(f, c) : forcing_at(f, c, (j + 0.5) / m);
      const Forcing gb = j + 1 == m ? sample_at(f, c.i1) : forcing_at(f, c, static_cast<double>(j + 1) / m);
      double tau = 0.0, unused = 0.0;
      const State k1 = derivative(y, ga, &tau);
      if (recording) record(stats, was_slack, tau, h, j == 0, sample_index, trace);
      const State k2 = derivative(axpy(y, 0.5 * h, k1), gm, &unused);
      const State k3 = derivative(axpy(y, 0.5 * h, k2), gm, &unused);
      const State k4 = derivative(axpy(y, h, k3), gb, &unused);
      advance(y, h, k1, k2, k3, k4);
      ga = gb;
    }
    stats.substeps += m;
  }
};

}  // namespace detail

template <typename TensionLaw, std::size_t K>
std::array<DayStatistics, K> integrate_days(const SurgeParameters& p, const std::array<const DayForcing*, K>& f,
                                            const TensionLaw& law, const IntegratorOptions& options,
                                            const std::array<std::vector<double>*, K>& trace) {
  using detail::Forcing;
  using detail::State;
  static_assert(K >= 1);
  const std::size_t n = f[0]->size();
  const double dt = f[0]->dt_s;
  for (std::size_t l = 1; l < K; ++l) {
    TOWDB_ASSERT(f[l]->size() == n && f[l]->dt_s == dt);
  }
  const detail::SurgeKernel<TensionLaw> kernel(p, law);

  const std::size_t warmup_samples = static_cast<std::size_t>(std::ceil(options.warmup_s / dt));
  const std::size_t start = (n - warmup_samples % n) % n;  // periodic: warm-up is the day's own end
  const std::size_t total = warmup_samples + n;

  std::array<DayStatistics, K> stats;
  std::array<State, K> y;
  std::array<bool, K> was_slack;
  for (std::size_t l = 0; l < K; ++l) {
    stats[l].max_tension_n = -kernel.mean;
    stats[l].min_tension_n = std::numeric_limits<double>::infinity();
    if (trace[l]) trace[l]->assign(n, 0.0);
    y[l] = State{0.0, 0.0, 0.0, 0.0};
    was_slack[l] = false;
  }

  std::size_t i = start;
  for (std::size_t step = 0; step < total; ++step) {
    const detail::Stencil c = detail::stencil(i, n);
    const bool recording = step >= warmup_samples;
    const std::size_t sample_index = recording ? step - warmup_samples : 0;
    std::array<Forcing, K> g0;
    std::array<int, K> m;
    int most = 1;
    for (std::size_t l = 0; l < K; ++l) {
      g0[l] = detail::sample_at(*f[l], i);
      m[l] = kernel.substeps(y[l], g0[l], dt, options);
      most = std::max(most, m[l]);
    }
    if (K > 1 && most == 1) {
      // Every day takes one step: the days' RK4 stages are interleaved, so
      // their independent dependency chains overlap in the processor. Same
      // operations per day as kernel.interval with m = 1.
      std::array<Forcing, K> gm, gb;
      std::array<State, K> k1, k2, k3, k4;
      std::array<double, K> tau;
      double unused = 0.0;
      for (std::size_t l = 0; l < K; ++l) {
        gm[l] = detail::midpoint_forcing(*f[l], c);
        gb[l] = detail::sample_at(*f[l], c.i1);
      }
      for (std::size_t l = 0; l < K; ++l) k1[l] = kernel.derivative(y[l], g0[l], &tau[l]);
      if (recording) {
        for (std::size_t l = 0; l < K; ++l) {
          kernel.record(stats[l], was_slack[l], tau[l], dt, true, sample_index, trace[l]);
        }
      }
      for (std::size_t l = 0; l < K; ++l) {
        k2[l] = kernel.derivative(detail::axpy(y[l], 0.5 * dt, k1[l]), gm[l], &unused);
      }
      for (std::size_t l = 0; l < K; ++l) {
        k3[l] = kernel.derivative(detail::axpy(y[l], 0.5 * dt, k2[l]), gm[l], &unused);
      }
      for (std::size_t l = 0; l < K; ++l) k4[l] = kernel.derivative(detail::axpy(y[l], dt, k3[l]), gb[l], &unused);
      for (std::size_t l = 0; l < K; ++l) {
        detail::SurgeKernel<TensionLaw>::advance(y[l], dt, k1[l], k2[l], k3[l], k4[l]);
        ++stats[l].substeps;
      }
    } else {
      for (std::size_t l = 0; l < K; ++l) {
        kernel.interval(y[l], *f[l], c, g0[l], m[l], recording, sample_index, stats[l], was_slack[l], trace[l]);
      }
    }
    i = c.i1;
  }
  return stats;
}

template <typename TensionLaw>
DayStatistics integrate_day(const SurgeParameters& p, const DayForcing& f, const TensionLaw& law,
                            const IntegratorOptions& options, std::vector<double>* trace) {
  return integrate_days<TensionLaw, 1>(p, {&f}, law, options, {trace})[0];
}

}  // namespace towdb::simulation

#endif  // TOWDB_SIMULATION_SURGE_HPP
