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
// day, which makes days independent and lets them run in parallel.
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
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

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

inline State axpy(const State& y, double h, const State& k) {
  return {y.x1 + h * k.x1, y.v1 + h * k.v1, y.x7 + h * k.x7, y.v7 + h * k.v7};
}

}  // namespace detail

template <typename TensionLaw>
DayStatistics integrate_day(const SurgeParameters& p, const DayForcing& f, const TensionLaw& law,
                            const IntegratorOptions& options, std::vector<double>* trace) {
  using detail::State;
  const std::size_t n = f.size();
  const double dt = f.dt_s;
  const double mean = law.mean_tension_n();
  const double inv_mass_line =
      p.cos_alpha_tug * p.cos_alpha_tug / p.tug_mass_kg + p.cos_alpha_tow * p.cos_alpha_tow / p.tow_mass_kg;
  const double hull_rate = std::max(p.tug_damping_n_s_m / p.tug_mass_kg, p.tow_damping_n_s_m / p.tow_mass_kg);

  const std::size_t warmup_samples = static_cast<std::size_t>(std::ceil(options.warmup_s / dt));
  const std::size_t start = (n - warmup_samples % n) % n;  // periodic: warm-up is the day's own end
  const std::size_t total = warmup_samples + n;

  DayStatistics stats;
  stats.max_tension_n = -mean;
  stats.min_tension_n = std::numeric_limits<double>::infinity();
  if (trace) trace->assign(n, 0.0);
  State y{0.0, 0.0, 0.0, 0.0};
  bool was_slack = false;

  // Derivative of the state; also returns the tension it used.
  const auto derivative = [&](const State& y0, const detail::Forcing& g, double* tau_out) {
    const double xi = y0.x1 * p.cos_alpha_tug - y0.x7 * p.cos_alpha_tow + g.xi_ns;
    const double xi_dot = y0.v1 * p.cos_alpha_tug - y0.v7 * p.cos_alpha_tow + g.xi_ns_dot;
    const double tau = law.tension(xi, xi_dot);
    *tau_out = tau;
    return State{y0.v1, (-tau * p.cos_alpha_tug + g.f1 - p.tug_damping_n_s_m * y0.v1) / p.tug_mass_kg, y0.v7,
                 (tau * p.cos_alpha_tow + g.f7 - p.tow_damping_n_s_m * y0.v7) / p.tow_mass_kg};
  };
  const auto sample = [&](std::size_t i) {
    return detail::Forcing{f.tug_force_n[i], f.tow_force_n[i], f.xi_ns_m[i], f.xi_ns_dot_m_s[i]};
  };

  std::size_t i = start;
  for (std::size_t step = 0; step < total; ++step) {
    const detail::Stencil c = detail::stencil(i, n);
    const std::size_t i1 = c.i1;
    const bool recording = step >= warmup_samples;
    // Local stiffness and damping of the line at the start of the interval.
    const detail::Forcing g0 = sample(i);
    const double xi = y.x1 * p.cos_alpha_tug - y.x7 * p.cos_alpha_tow + g0.xi_ns;
    const double xi_dot = y.v1 * p.cos_alpha_tug - y.v7 * p.cos_alpha_tow + g0.xi_ns_dot;
    const double k_loc = std::max(0.0, law.stiffness(xi, xi_dot));
    const double c_loc = std::max(0.0, law.damping(xi, xi_dot));
    const double rate = std::max(std::sqrt(k_loc * inv_mass_line), c_loc * inv_mass_line + hull_rate);
    int m = 1;
    if (rate * dt > options.max_omega_h) {
      m = std::min(options.max_substeps, static_cast<int>(std::ceil(rate * dt / options.max_omega_h)));
    }
    const double h = dt / m;
    detail::Forcing ga = g0;
    for (int j = 0; j < m; ++j) {
      const detail::Forcing gm = m == 1 ? detail::midpoint_forcing(f, c) : detail::forcing_at(f, c, (j + 0.5) / m);
      const detail::Forcing gb = j + 1 == m ? sample(i1) : detail::forcing_at(f, c, static_cast<double>(j + 1) / m);
      double tau = 0.0, unused = 0.0;
      const State k1 = derivative(y, ga, &tau);
      if (recording) {
        // Statistics at every substep start (the k1 evaluation), so snap-load
        // peaks between forcing samples count; each point stands for h.
        const bool slack = tau <= -mean;
        stats.max_tension_n = std::max(stats.max_tension_n, tau);
        stats.min_tension_n = std::min(stats.min_tension_n, tau);
        if (slack) stats.slack_time_s += h;
        if (was_slack && !slack) ++stats.snatch_events;
        was_slack = slack;
        if (j == 0) {  // tau at sample i
          stats.tension_sum_n += tau;
          stats.tension_sum_sq_n2 += tau * tau;
          ++stats.samples;
          if (trace) (*trace)[step - warmup_samples] = tau;
        }
      }
      const State k2 = derivative(detail::axpy(y, 0.5 * h, k1), gm, &unused);
      const State k3 = derivative(detail::axpy(y, 0.5 * h, k2), gm, &unused);
      const State k4 = derivative(detail::axpy(y, h, k3), gb, &unused);
      y.x1 += h / 6.0 * (k1.x1 + 2.0 * k2.x1 + 2.0 * k3.x1 + k4.x1);
      y.v1 += h / 6.0 * (k1.v1 + 2.0 * k2.v1 + 2.0 * k3.v1 + k4.v1);
      y.x7 += h / 6.0 * (k1.x7 + 2.0 * k2.x7 + 2.0 * k3.x7 + k4.x7);
      y.v7 += h / 6.0 * (k1.v7 + 2.0 * k2.v7 + 2.0 * k3.v7 + k4.v7);
      ga = gb;
    }
    stats.substeps += m;
    i = i1;
  }
  return stats;
}

}  // namespace towdb::simulation

#endif  // TOWDB_SIMULATION_SURGE_HPP
