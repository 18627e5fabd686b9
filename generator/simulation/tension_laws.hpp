// The surge integrator's tension laws tau(xi, xi') (simulation/surge.hpp
// states the interface): the polynomial towline of towline/ with its
// continuation outside the fitted range and the slack limit (EQ-CASE-1), and
// the linear law of the linear-limit check. Both are templates on the number
// type (double or lanes::Lanes<K, W>), so one law serves the scalar and the
// lock-step paths with the same bits lane by lane.
//
// Units: SI (N, m, m/s).
#ifndef TOWDB_SIMULATION_TENSION_LAWS_HPP
#define TOWDB_SIMULATION_TENSION_LAWS_HPP

#include <limits>

#include "simulation/lanes.hpp"
#include "towline/towline.hpp"

namespace towdb::simulation {

// The polynomial towline (towline EQ-TOWLINE-11/-13 with the slack limit) in
// the form simulation/surge.hpp integrates.
// EQ-CASE-1 (beyond the thesis): the polynomial is only known inside the
// range of the cable-dynamics runs it was fitted to, [xi_min, xi_max] x
// [-v_max, v_max]. Outside it a cubic can turn over (negative stiffness)
// and run away; there it is continued by its tangent plane at the nearest
// point of the range, with the slopes floored at 0 (tension never falls as the
// line is stretched further or faster):
//   tau = P(xc, vc) + max(0, dP/dxi) (xi - xc) + max(0, dP/dxi') (xi' - vc),
//   xc = clamp(xi, xi_min, xi_max), vc = clamp(xi', -v_max, v_max).
// Inside the range this is exactly the thesis's polynomial.
struct PolynomialLaw {
  static constexpr bool kForcedInline = true;  // surge.hpp: may run on integrate_days_avx2
  const towline::TowlineFit* fit;
  towline::AboveBreakingModel model;
  double x_lo_m, x_hi_m, v_max_m_s, x_b_m, k_spring_n_m, slack_n;

  PolynomialLaw(const towline::TowlineFit* f, towline::AboveBreakingModel m)
      : fit(f),
        model(m),
        x_lo_m(f->summary().fit_xi_min_m),
        x_hi_m(f->summary().fit_xi_max_m),
        v_max_m_s(f->summary().fit_xi_dot_max_m_s),
        x_b_m(f->summary().spring_onset_extension_m),
        k_spring_n_m(f->summary().straight_spring_n_m),
        slack_n(f->summary().slack_limit_n) {}

  // Evaluated four times per RK4 step: inlined into the loop (TOWDB_SURGE_INLINE,
  // simulation/surge.hpp); GCC 12 otherwise calls extended() out of line.
  // Templates on the number type (double or the integrator's lanes); the
  // branches of EQ-CASE-1 are lane selects, the same values as if / else.
  template <typename T>
  TOWDB_SURGE_INLINE T p(T x, T v) const {
    return fit->coefficients().evaluate(x, v);
  }
  template <typename T>
  TOWDB_SURGE_INLINE T dp_dx(T x, T v) const {
    const auto& a = fit->coefficients().a;
    return a[0] + 2.0 * a[2] * x + a[3] * v + 3.0 * a[5] * x * x + 2.0 * a[6] * x * v + a[7] * v * v;
  }
  template <typename T>
  TOWDB_SURGE_INLINE T dp_dv(T x, T v) const {
    const auto& a = fit->coefficients().a;
    return a[1] + a[3] * x + 2.0 * a[4] * v + a[6] * x * x + 2.0 * a[7] * x * v + 3.0 * a[8] * v * v;
  }
  // EQ-CASE-1 without the spring and slack limits.
  template <typename T>
  TOWDB_SURGE_INLINE T extended(T x, T v) const {
    const T xc = lanes::clamp(x, x_lo_m, x_hi_m), vc = lanes::clamp(v, -v_max_m_s, v_max_m_s);
    const T zero = lanes::splat<T>(0.0);
    T tau = p(xc, vc);
    const auto x_out = x != xc, v_out = v != vc;  // outside the fitted range (rare)
    if (lanes::any(x_out)) tau = lanes::select(x_out, tau + lanes::max(zero, dp_dx(xc, vc)) * (x - xc), tau);
    if (lanes::any(v_out)) tau = lanes::select(v_out, tau + lanes::max(zero, dp_dv(xc, vc)) * (v - vc), tau);
    return tau;
  }
  bool straight_spring() const { return model == towline::AboveBreakingModel::kStraightSpring; }
  template <typename T>
  TOWDB_SURGE_INLINE T unlimited(T x, T v) const {
    const T b = lanes::splat<T>(x_b_m);
    const auto above = x > b;
    if (!straight_spring() || !lanes::any(above)) return extended(x, v);
    return lanes::select(above, extended(b, v) + k_spring_n_m * (x - b), extended(x, v));
  }
  template <typename T>
  TOWDB_SURGE_INLINE T tension(T x, T v) const {
    return lanes::max(unlimited(x, v), lanes::splat<T>(slack_n));
  }
  template <typename T>
  TOWDB_SURGE_INLINE T stiffness(T x, T v) const {
    const T xc = lanes::clamp(x, x_lo_m, x_hi_m), vc = lanes::clamp(v, -v_max_m_s, v_max_m_s);
    const T d = dp_dx(xc, vc);
    const T k = lanes::select(x != xc, lanes::max(lanes::splat<T>(0.0), d), d);
    return straight_spring() ? lanes::select(x > lanes::splat<T>(x_b_m), lanes::splat<T>(k_spring_n_m), k) : k;
  }
  template <typename T>
  TOWDB_SURGE_INLINE T damping(T x, T v) const {
    if (straight_spring()) x = lanes::select(x > lanes::splat<T>(x_b_m), lanes::splat<T>(x_b_m), x);
    const T xc = lanes::clamp(x, x_lo_m, x_hi_m), vc = lanes::clamp(v, -v_max_m_s, v_max_m_s);
    const T d = dp_dv(xc, vc);
    return lanes::select(v != vc, lanes::max(lanes::splat<T>(0.0), d), d);
  }
  double mean_tension_n() const { return -slack_n; }
};

// tau = a10 xi + a01 xi', never slack (the linear-limit check).
struct LinearLaw {
  static constexpr bool kForcedInline = true;  // surge.hpp: may run on integrate_days_avx2
  double k_n_m, c_n_s_m;
  template <typename T>
  TOWDB_SURGE_INLINE T tension(T xi, T xd) const {
    return k_n_m * xi + c_n_s_m * xd;
  }
  template <typename T>
  TOWDB_SURGE_INLINE T stiffness(T, T) const {
    return lanes::splat<T>(k_n_m);
  }
  template <typename T>
  TOWDB_SURGE_INLINE T damping(T, T) const {
    return lanes::splat<T>(c_n_s_m);
  }
  double mean_tension_n() const { return std::numeric_limits<double>::infinity(); }
};

}  // namespace towdb::simulation

#endif  // TOWDB_SIMULATION_TENSION_LAWS_HPP
