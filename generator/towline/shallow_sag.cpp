#include "towline/shallow_sag.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::towline {

void DynamicsOptions::validate() const {
  require_in_range("dynamics.samples_per_period", samples_per_period, 8, 4096);
  require_in_range("dynamics.ramp_cycles", ramp_cycles, 0, 100);
  require_in_range("dynamics.min_cycles", min_cycles, 1, 1000);
  require_in_range("dynamics.max_cycles", max_cycles, min_cycles, 100000);
  require_in_range("dynamics.periodicity_tolerance", periodicity_tolerance, 1e-9, 0.5);
  require_in_range("dynamics.steps_per_period", steps_per_period, 4, 1 << 20);
  require_in_range("dynamics.steps_per_line_period", steps_per_line_period, 2, 1 << 20);
  require_in_range("dynamics.newton_tolerance", newton_tolerance, 1e-15, 1e-3);
  require_in_range("dynamics.newton_max_iterations", newton_max_iterations, 2, 1000);
  require_in_range("dynamics.courant_target", courant_target, 0.05, 1.8);
  require_in_range("dynamics.courant_limit", courant_limit, courant_target, 1.99);
}

namespace {

// Added mass per stretched length [kg/m]: C_A rho pi D^2 / 4.
double added_mass_kg_m(const model::TowlineComponent& c) {
  return c.added_mass_coefficient * kRhoSeawater_kg_m3 * kPi * c.hydrodynamic_diameter_m *
         c.hydrodynamic_diameter_m / 4.0;
}

// Wave travel time int sqrt(m/T) dp over segment i (midpoint rule, 16 parts).
double segment_travel_time_s(const Catenary& cat, int i) {
  const auto& c = cat.towline().segments[static_cast<std::size_t>(i)].component;
  const double s0 = cat.segment_start_m(i);
  const double s1 = cat.segment_start_m(i + 1);
  constexpr int kParts = 16;
  double t = 0.0;
  for (int k = 0; k < kParts; ++k) {
    const CatenaryPoint pt = cat.point_at(s0 + (s1 - s0) * (k + 0.5) / kParts);
    const double stretch = 1.0 + pt.tension_n / c.ea_n;
    const double m = c.mass_per_length_kg_m / stretch + added_mass_kg_m(c);
    t += std::sqrt(m / pt.tension_n) * stretch * (s1 - s0) / kParts;
  }
  return t;
}

// Solves the symmetric tridiagonal system (diag, off) x = rhs (Thomas).
std::vector<double> solve_tridiagonal(std::vector<double> diag, const std::vector<double>& off,
                                      std::vector<double> rhs) {
  const std::size_t n = diag.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double f = off[i - 1] / diag[i - 1];
    diag[i] -= f * off[i - 1];
    rhs[i] -= f * rhs[i - 1];
  }
  std::vector<double> x(n);
  x[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) x[i] = (rhs[i] - off[i] * x[i + 1]) / diag[i];
  return x;
}

}  // namespace

ShallowSagModel::ShallowSagModel(const Catenary& catenary, int n_elements) {
  const int n_seg = catenary.segment_count();
  require_in_range("shallow-sag element count", n_elements, 2 * n_seg, 1000000);
  horizontal_tension_n_ = catenary.horizontal_tension_n();
  compliance_m_n_ = catenary.axial_compliance_m_n();

  std::vector<double> travel(static_cast<std::size_t>(n_seg));
  double travel_total = 0.0;
  for (int i = 0; i < n_seg; ++i) {
    travel[static_cast<std::size_t>(i)] = segment_travel_time_s(catenary, i);
    travel_total += travel[static_cast<std::size_t>(i)];
  }

  // Element boundaries (unstretched s) and their catenary points.
  std::vector<CatenaryPoint> nodes;
  std::vector<int> elem_segment;
  nodes.push_back(catenary.point_at(0.0));
  for (int i = 0; i < n_seg; ++i) {
    const double share = n_elements * travel[static_cast<std::size_t>(i)] / travel_total;
    const int n_i = std::max(2, static_cast<int>(std::lround(share)));
    const double s0 = catenary.segment_start_m(i);
    const double s1 = catenary.segment_start_m(i + 1);
    for (int k = 1; k <= n_i; ++k) {
      CatenaryPoint pt = catenary.point_at(s0 + (s1 - s0) * k / n_i);
      // point_at(s) at a junction belongs to the segment ending there; the
      // slope is continuous, so the element's turning angle is unaffected.
      nodes.push_back(pt);
      elem_segment.push_back(i);
    }
  }
  const std::size_t n = elem_segment.size();
  elem_h_m_.resize(n);
  elem_tension_n_.resize(n);
  node_mass_kg_.assign(n + 1, 0.0);
  node_b_.assign(n + 1, 0.0);
  node_drag_kg_m_.assign(n + 1, 0.0);
  double min_tension = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < n; ++e) {
    const auto& c = catenary.towline().segments[static_cast<std::size_t>(elem_segment[e])].component;
    const CatenaryPoint& a = nodes[e];
    const CatenaryPoint& b = nodes[e + 1];
    const double ds = b.s_m - a.s_m;
    const double h = b.p_m - a.p_m;
    const double t_mid = catenary.point_at(0.5 * (a.s_m + b.s_m)).tension_n;
    elem_h_m_[e] = h;
    elem_tension_n_[e] = t_mid;
    min_tension = std::min(min_tension, t_mid);
    const double mass = c.mass_per_length_kg_m * ds + added_mass_kg_m(c) * h;
    const double drag = 0.5 * kRhoSeawater_kg_m3 * c.drag_coefficient_normal * c.hydrodynamic_diameter_m * h;
    const double dphi = b.slope_rad - a.slope_rad;  // = int kappa dp over the element
    node_mass_kg_[e] += 0.5 * mass;
    node_mass_kg_[e + 1] += 0.5 * mass;
    node_drag_kg_m_[e] += 0.5 * drag;
    node_drag_kg_m_[e + 1] += 0.5 * drag;
    node_b_[e] += 0.5 * dphi;
    node_b_[e + 1] += 0.5 * dphi;
  }
  tau_floor_n_ = -min_tension;
}

double ShallowSagModel::quasi_static_stiffness_n_m() const { return linear_dynamic_stiffness_n_m(0.0); }

double ShallowSagModel::linear_dynamic_stiffness_n_m(double omega_rad_s) const {
  require_in_range("dynamic stiffness frequency [rad/s]", omega_rad_s, 0.0, 1e4);
  const std::size_t n = elem_h_m_.size();
  const std::size_t m = n - 1;  // interior nodes 1..n-1
  std::vector<double> diag(m), off(m > 0 ? m - 1 : 0), rhs(m);
  for (std::size_t j = 1; j < n; ++j) {
    const double al = elem_tension_n_[j - 1] / elem_h_m_[j - 1];
    const double ar = elem_tension_n_[j] / elem_h_m_[j];
    diag[j - 1] = al + ar - omega_rad_s * omega_rad_s * node_mass_kg_[j];
    if (j + 1 < n) off[j - 1] = -ar;
    rhs[j - 1] = node_b_[j];
  }
  const std::vector<double> q = solve_tridiagonal(diag, off, rhs);
  double btq = 0.0;
  for (std::size_t j = 1; j < n; ++j) btq += node_b_[j] * q[j - 1];
  return 1.0 / (compliance_m_n_ + btq);
}

std::vector<LinearMode> ShallowSagModel::linear_modes(int count) const {
  const int n = n_elements();
  const int m = n - 1;
  require_in_range("linear mode count", count, 1, m);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
  for (int j = 1; j < n; ++j) {
    const auto ju = static_cast<std::size_t>(j);
    const double al = elem_tension_n_[ju - 1] / elem_h_m_[ju - 1];
    const double ar = elem_tension_n_[ju] / elem_h_m_[ju];
    a(j - 1, j - 1) += al + ar;
    if (j + 1 < n) {
      a(j - 1, j) -= ar;
      a(j, j - 1) -= ar;
    }
  }
  Eigen::VectorXd b(m), inv_sqrt_m(m);
  for (int j = 1; j < n; ++j) {
    b(j - 1) = node_b_[static_cast<std::size_t>(j)];
    inv_sqrt_m(j - 1) = 1.0 / std::sqrt(node_mass_kg_[static_cast<std::size_t>(j)]);
  }
  a += b * b.transpose() / compliance_m_n_;
  const Eigen::MatrixXd scaled = inv_sqrt_m.asDiagonal() * a * inv_sqrt_m.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(scaled);
  if (solver.info() != Eigen::Success) {
    throw NumericalError("shallow-sag linear modes: Eigen SelfAdjointEigenSolver failed (iteration 0, residual n/a)");
  }
  std::vector<LinearMode> modes;
  for (int k = 0; k < count; ++k) {
    const Eigen::VectorXd q = inv_sqrt_m.asDiagonal() * solver.eigenvectors().col(k);
    double num = 0.0;
    for (int j = 0; j < m; ++j) num += q(j) * q(m - 1 - j);
    LinearMode mode;
    mode.omega_rad_s = std::sqrt(std::max(0.0, solver.eigenvalues()(k)));
    mode.symmetry = num / q.squaredNorm();
    modes.push_back(mode);
  }
  return modes;
}


double ShallowSagModel::lowest_frequency_rad_s() const {
  // Inverse iteration on M^{-1} S, S = K_T + b b^T / c (tridiagonal plus rank
  // one, solved by Sherman-Morrison); a fixed iteration count keeps it
  // deterministic, and only a time-step scale is needed from it.
  const std::size_t n = elem_h_m_.size();
  const std::size_t m = n - 1;
  std::vector<double> diag(m), off(m > 0 ? m - 1 : 0), b(m), x(m, 1.0);
  for (std::size_t j = 1; j < n; ++j) {
    diag[j - 1] = elem_tension_n_[j - 1] / elem_h_m_[j - 1] + elem_tension_n_[j] / elem_h_m_[j];
    if (j + 1 < n) off[j - 1] = -elem_tension_n_[j] / elem_h_m_[j];
    b[j - 1] = node_b_[j];
  }
  const std::vector<double> ab = solve_tridiagonal(diag, off, b);
  double bab = 0.0;
  for (std::size_t j = 0; j < m; ++j) bab += b[j] * ab[j];
  double lambda = 0.0;
  for (int it = 0; it < 40; ++it) {
    std::vector<double> rhs(m);
    for (std::size_t j = 0; j < m; ++j) rhs[j] = node_mass_kg_[j + 1] * x[j];
    std::vector<double> y = solve_tridiagonal(diag, off, rhs);
    double by = 0.0;
    for (std::size_t j = 0; j < m; ++j) by += b[j] * y[j];
    const double factor = by / (compliance_m_n_ + bab);
    double norm = 0.0;
    double xmy = 0.0;
    for (std::size_t j = 0; j < m; ++j) {
      y[j] -= factor * ab[j];
      xmy += x[j] * node_mass_kg_[j + 1] * y[j];
      norm += y[j] * node_mass_kg_[j + 1] * y[j];
    }
    double xmx = 0.0;
    for (std::size_t j = 0; j < m; ++j) xmx += x[j] * node_mass_kg_[j + 1] * x[j];
    lambda = xmx / xmy;  // Rayleigh-type estimate of the smallest eigenvalue
    const double scale = 1.0 / std::sqrt(norm);
    for (std::size_t j = 0; j < m; ++j) x[j] = y[j] * scale;
  }
  return std::sqrt(lambda);
}

namespace {

// Integrator state: node arrays of size N + 1 (ends fixed at zero).
struct SagState {
  std::vector<double> q, v, a, f;
  double tau_n = 0.0;
  bool slack = false;
  double omega2_bound = 0.0;
};

// Thomas factorisation of a tridiagonal matrix (sub/super diagonal `off`),
// reused for several right-hand sides.
struct Tridiagonal {
  std::vector<double> pivot, ratio, off;
  void factor(const std::vector<double>& diag, const std::vector<double>& offdiag, std::size_t m) {
    pivot.resize(m);
    ratio.resize(m);
    off = offdiag;
    pivot[0] = diag[0];
    for (std::size_t i = 1; i < m; ++i) {
      ratio[i] = off[i - 1] / pivot[i - 1];
      pivot[i] = diag[i] - ratio[i] * off[i - 1];
    }
  }
  void solve(std::vector<double>& x, std::size_t m) const {
    for (std::size_t i = 1; i < m; ++i) x[i] -= ratio[i] * x[i - 1];
    x[m - 1] /= pivot[m - 1];
    for (std::size_t i = m - 1; i-- > 0;) x[i] = (x[i] - off[i] * x[i + 1]) / pivot[i];
  }
};

// The discretised line as the time steppers read it (ShallowSagModel's arrays).
struct SagLine {
  const std::vector<double>& elem_h_m;
  const std::vector<double>& elem_tension_n;
  const std::vector<double>& node_mass_kg;
  const std::vector<double>& node_b;
  const std::vector<double>& node_drag_kg_m;
  double compliance_m_n;
  double tau_floor_n;
};

// The prescribed chord extension p0(t) = a env(t) sin(w t), env rising as
// (1 - cos)/2 over the ramp; returns p0 and stores dp0/dt in *rate.
struct HarmonicExtension {
  double amplitude_m;
  double omega_rad_s;
  double ramp_s;
  double operator()(double t, double* rate) const {
    double env = 1.0;
    double env_rate = 0.0;
    if (t < ramp_s) {
      env = 0.5 * (1.0 - std::cos(kPi * t / ramp_s));
      env_rate = 0.5 * kPi / ramp_s * std::sin(kPi * t / ramp_s);
    }
    const double sn = std::sin(omega_rad_s * t);
    const double cs = std::cos(omega_rad_s * t);
    *rate = amplitude_m * (env_rate * sn + env * omega_rad_s * cs);
    return amplitude_m * env * sn;
  }
};

// Advances a SagState through time by either integrator (see the header's
// discretisation notes); owns the Newton workspace so steps do not allocate.
class SagStepper {
 public:
  SagStepper(const SagLine& line, const HarmonicExtension& extension, const DynamicsOptions& options,
             double dt_implicit_s, double newton_tol_m)
      : line_(line),
        extension_(extension),
        options_(options),
        implicit_(options.integrator == Integrator::kImplicitTrapezoidal),
        dt_implicit_s_(dt_implicit_s),
        newton_tol_m_(newton_tol_m),
        n_(line.elem_h_m.size()),
        m_(n_ - 1),
        diag_(m_),
        off_(m_ > 0 ? m_ - 1 : 0),
        rhs_(m_),
        gvec_(m_),
        yvec_(m_) {}

  bool implicit() const { return implicit_; }

  // The state at rest at t = 0 (forces and tension evaluated).
  SagState initial_state() const {
    SagState st;
    st.q.assign(n_ + 1, 0.0);
    st.v.assign(n_ + 1, 0.0);
    st.a.assign(n_ + 1, 0.0);
    st.f.assign(n_ + 1, 0.0);
    double rate0 = 0.0;
    evaluate(st, extension_(0.0, &rate0));
    return st;
  }

  // Conservative force f (string + tension-curvature, no drag), tension and
  // stability bound at state `st` and extension p0 (EQ-TOWLINE-6..8).
  void evaluate(SagState& st, double p0) const;

  // Advances `st` over one sample interval [t0, t0 + dt_sample] in k equal
  // substeps; an interval whose substeps fail (Courant limit or Newton) is
  // redone with more. Counts steps, iterations and dt extremes into `run`.
  void advance_interval(SagState& st, double t0, double dt_sample, HarmonicRun& run);

 private:
  // Explicit kick-drift-kick step; false if dt omega_max passed the limit.
  bool explicit_step(SagState& st, double dt, double t_new, double* courant) const;
  // Implicit trapezoidal (Newmark average acceleration) step solved by
  // Newton's method; false if Newton did not converge.
  bool implicit_step(SagState& st, double dt, double t_new, int* iterations);
  // Newmark velocity and acceleration of `st` from its displacement.
  void newmark_rates(SagState& st, double dt) const;

  const SagLine& line_;
  const HarmonicExtension& extension_;
  const DynamicsOptions& options_;
  const bool implicit_;
  const double dt_implicit_s_;
  const double newton_tol_m_;
  const std::size_t n_;  // elements
  const std::size_t m_;  // interior nodes 1..n-1
  Tridiagonal tri_;
  std::vector<double> diag_, off_, rhs_, gvec_, yvec_;
  SagState old_, saved_;
};

void SagStepper::evaluate(SagState& st, double p0) const {
  const std::size_t n = n_;
  double bq = 0.0;
  double q2 = 0.0;
  for (std::size_t e = 0; e < n; ++e) {
    const double dq = st.q[e + 1] - st.q[e];
    q2 += dq * dq / line_.elem_h_m[e];
    bq += line_.node_b[e] * st.q[e];
  }
  const double tau_c = (p0 - bq + 0.5 * q2) / line_.compliance_m_n;
  st.slack = tau_c < line_.tau_floor_n;
  st.tau_n = st.slack ? line_.tau_floor_n : tau_c;
  double gershgorin = 0.0;
  double rank_one = 0.0;
  double f_left = 0.0;
  double a_left = 0.0;
  double slope_left = 0.0;
  for (std::size_t e = 0; e < n; ++e) {
    const double a = (line_.elem_tension_n[e] + st.tau_n) / line_.elem_h_m[e];
    const double slope = (st.q[e + 1] - st.q[e]) / line_.elem_h_m[e];
    const double f_right = a * (st.q[e + 1] - st.q[e]);
    if (e > 0) {
      const double inv_m = 1.0 / line_.node_mass_kg[e];
      st.f[e] = f_right - f_left + st.tau_n * line_.node_b[e];
      gershgorin = std::max(gershgorin, 2.0 * (a_left + a) * inv_m);
      const double g = -line_.node_b[e] + slope_left - slope;  // d(c tau)/d q_e
      rank_one += g * g * inv_m;
    }
    f_left = f_right;
    a_left = a;
    slope_left = slope;
  }
  st.omega2_bound = gershgorin + (st.slack ? 0.0 : rank_one / line_.compliance_m_n);
}

bool SagStepper::explicit_step(SagState& st, double dt, double t_new, double* courant) const {
  const std::size_t n = n_;
  double rate = 0.0;
  for (std::size_t j = 1; j < n; ++j) {
    const double inv_m = 1.0 / line_.node_mass_kg[j];
    const double damp = 0.5 * dt * line_.node_drag_kg_m[j] * std::abs(st.v[j]) * inv_m;
    st.v[j] = (st.v[j] + 0.5 * dt * st.f[j] * inv_m) / (1.0 + damp);
    st.q[j] += dt * st.v[j];
  }
  evaluate(st, extension_(t_new, &rate));
  for (std::size_t j = 1; j < n; ++j) {
    const double inv_m = 1.0 / line_.node_mass_kg[j];
    const double damp = 0.5 * dt * line_.node_drag_kg_m[j] * std::abs(st.v[j]) * inv_m;
    st.v[j] = (st.v[j] + 0.5 * dt * st.f[j] * inv_m) / (1.0 + damp);
  }
  *courant = dt * std::sqrt(st.omega2_bound);
  return *courant <= options_.courant_limit;
}

void SagStepper::newmark_rates(SagState& st, double dt) const {
  for (std::size_t j = 1; j < n_; ++j) {
    st.v[j] = 2.0 * (st.q[j] - old_.q[j]) / dt - old_.v[j];
    st.a[j] = 2.0 * (st.v[j] - old_.v[j]) / dt - old_.a[j];
  }
}

// The Jacobian 4M/dt^2 + 4D|v|/dt + (T_e + tau)/h_e terms is tridiagonal,
// plus g g^T / c while taut (Sherman-Morrison).
bool SagStepper::implicit_step(SagState& st, double dt, double t_new, int* iterations) {
  const std::size_t n = n_;
  const std::size_t m = m_;
  old_ = st;
  double rate = 0.0;
  const double p0 = extension_(t_new, &rate);
  for (std::size_t j = 1; j < n; ++j) st.q[j] = old_.q[j] + dt * old_.v[j] + 0.5 * dt * dt * old_.a[j];
  const double q_scale = 1.0;
  for (int it = 0; it < options_.newton_max_iterations; ++it) {
    evaluate(st, p0);
    newmark_rates(st, dt);
    double q_max = 0.0;
    for (std::size_t j = 1; j < n; ++j) q_max = std::max(q_max, std::abs(st.q[j]));
    // Residual G = M a - f + D |v| v and the Jacobian.
    for (std::size_t j = 1; j < n; ++j) {
      const double mj = line_.node_mass_kg[j];
      const double dj = line_.node_drag_kg_m[j];
      rhs_[j - 1] = -(mj * st.a[j] - st.f[j] + dj * std::abs(st.v[j]) * st.v[j]);
      const double al = (line_.elem_tension_n[j - 1] + st.tau_n) / line_.elem_h_m[j - 1];
      const double ar = (line_.elem_tension_n[j] + st.tau_n) / line_.elem_h_m[j];
      diag_[j - 1] = 4.0 * mj / (dt * dt) + 4.0 * dj * std::abs(st.v[j]) / dt + al + ar;
      if (j + 1 < n) off_[j - 1] = -ar;
      gvec_[j - 1] = -line_.node_b[j] + (st.q[j] - st.q[j - 1]) / line_.elem_h_m[j - 1] -
                     (st.q[j + 1] - st.q[j]) / line_.elem_h_m[j];
    }
    tri_.factor(diag_, off_, m);
    tri_.solve(rhs_, m);
    if (!st.slack) {
      yvec_ = gvec_;
      tri_.solve(yvec_, m);
      double gx = 0.0;
      double gy = 0.0;
      for (std::size_t j = 0; j < m; ++j) {
        gx += gvec_[j] * rhs_[j];
        gy += gvec_[j] * yvec_[j];
      }
      const double factor = gx / (line_.compliance_m_n + gy);
      for (std::size_t j = 0; j < m; ++j) rhs_[j] -= factor * yvec_[j];
    }
    double step = 0.0;
    for (std::size_t j = 1; j < n; ++j) {
      st.q[j] += rhs_[j - 1];
      step = std::max(step, std::abs(rhs_[j - 1]));
    }
    if (!(step <= 1e300)) break;
    if (step <= newton_tol_m_ * (q_scale + q_max)) {
      evaluate(st, p0);
      newmark_rates(st, dt);
      *iterations = it + 1;
      return true;
    }
  }
  *iterations = options_.newton_max_iterations;
  return false;
}

void SagStepper::advance_interval(SagState& st, double t0, double dt_sample, HarmonicRun& run) {
  saved_ = st;
  int k_sub = implicit_ ? std::max(1, static_cast<int>(std::ceil(dt_sample / dt_implicit_s_ - 1e-9)))
                        : std::max(1, static_cast<int>(std::ceil(dt_sample * std::sqrt(st.omega2_bound) /
                                                                 options_.courant_target)));
  for (int attempt = 0;; ++attempt) {
    if (attempt > 24 || k_sub > (1 << 24)) {
      throw NumericalError(std::string("shallow-sag ") + (implicit_ ? "implicit" : "explicit") +
                           " time stepping: no acceptable substep at t = " + format_value(t0) +
                           " s (iteration " + std::to_string(attempt) + ", residual tau " +
                           format_value(st.tau_n) + " N)");
    }
    const double dt = dt_sample / k_sub;
    bool ok = true;
    double worst = 0.0;  // explicit: dt omega_max of the rejected substep
    for (int i = 0; i < k_sub && ok; ++i) {
      const double t_new = t0 + dt_sample * (i + 1) / k_sub;
      ++run.steps;
      if (implicit_) {
        int iterations = 0;
        ok = implicit_step(st, dt, t_new, &iterations);
        run.newton_iterations += iterations;
      } else {
        double courant = 0.0;
        ok = explicit_step(st, dt, t_new, &courant);
        if (!ok) worst = std::isfinite(courant) ? courant : 0.0;
      }
    }
    if (ok) {
      run.min_dt_s = std::min(run.min_dt_s, dt);
      run.max_dt_s = std::max(run.max_dt_s, dt);
      return;
    }
    st = saved_;
    k_sub = std::max(2 * k_sub, static_cast<int>(std::ceil(k_sub * worst / options_.courant_target)));
  }
}

// Throws NumericalError unless the state after sample `sample_index` (ending
// at t_end) is finite.
void require_finite_state(const SagState& st, std::size_t n, double t_end, long long sample_index) {
  double q_sum = 0.0;
  for (std::size_t j = 1; j < n; ++j) q_sum += std::abs(st.q[j]) + std::abs(st.v[j]);
  if (!std::isfinite(q_sum) || !std::isfinite(st.tau_n)) {
    throw NumericalError("shallow-sag integration produced a non-finite state at t = " +
                         format_value(t_end) + " s (sample " + std::to_string(sample_index + 1) +
                         ", residual tau = " + format_value(st.tau_n) + " N)");
  }
}

// Cycle-to-cycle change of tau, max_k |tau_k - tau_k(previous)|, as a fraction
// of the cycle's tau range (at least floor_n); stored with the verdict in `run`.
void measure_periodicity(const std::vector<TensionSample>& cycle, const std::vector<TensionSample>& previous,
                         double floor_n, double tolerance, HarmonicRun& run) {
  double lo = cycle[0].tau_n, hi = cycle[0].tau_n, change = 0.0;
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    lo = std::min(lo, cycle[k].tau_n);
    hi = std::max(hi, cycle[k].tau_n);
    change = std::max(change, std::abs(cycle[k].tau_n - previous[k].tau_n));
  }
  run.periodicity_change = change / std::max(hi - lo, floor_n);
  run.periodic = run.periodicity_change <= tolerance;
}

}  // namespace

HarmonicRun ShallowSagModel::run_harmonic(double amplitude_m, double omega_rad_s,
                                          const DynamicsOptions& options) const {
  options.validate();
  require_in_range("harmonic extension amplitude [m]", amplitude_m, 0.0, 1e3);
  require_in_range("harmonic extension frequency [rad/s]", omega_rad_s, 1e-4, 1e3);
  const std::size_t n = elem_h_m_.size();
  const double period_s = 2.0 * kPi / omega_rad_s;
  const int spp = options.samples_per_period;
  const double dt_sample = period_s / spp;
  // Implicit: dt resolves the excitation period and the line's lowest period.
  const double dt_implicit =
      std::min(period_s / options.steps_per_period,
               2.0 * kPi / lowest_frequency_rad_s() / options.steps_per_line_period);
  const double newton_tol_m = options.newton_tolerance * (1.0 + amplitude_m);

  const SagLine line{elem_h_m_,          elem_tension_n_, node_mass_kg_,  node_b_,
                     node_drag_kg_m_,    compliance_m_n_, tau_floor_n_};
  const HarmonicExtension extension{amplitude_m, omega_rad_s, options.ramp_cycles * period_s};
  SagStepper stepper(line, extension, options, dt_implicit, newton_tol_m);
  SagState st = stepper.initial_state();

  HarmonicRun run;
  run.amplitude_m = amplitude_m;
  run.omega_rad_s = omega_rad_s;
  run.min_dt_s = dt_sample;
  run.max_dt_s = 0.0;
  run.max_tau_n = st.tau_n;
  run.min_tau_n = st.tau_n;

  std::vector<TensionSample> cycle(static_cast<std::size_t>(spp)), previous;
  const int ramp_samples = options.ramp_cycles * spp;
  const double periodicity_floor_n = 1e-12 * (std::abs(amplitude_m) / compliance_m_n_ + horizontal_tension_n_);
  // Ramp samples first (c_idx = -1), then full-amplitude cycles.
  for (int c_idx = -1; c_idx < options.max_cycles; ++c_idx) {
    const bool ramp = c_idx < 0;
    const int n_samples = ramp ? ramp_samples : spp;
    for (int k = 0; k < n_samples; ++k) {
      const long long sample_index =
          ramp ? k : static_cast<long long>(ramp_samples) + static_cast<long long>(c_idx) * spp + k;
      const double t0 = static_cast<double>(sample_index) * dt_sample;
      if (!ramp) {
        double p0_rate = 0.0;
        const double p0 = extension(t0, &p0_rate);
        cycle[static_cast<std::size_t>(k)] = {p0, p0_rate, st.tau_n, st.slack};
      }
      stepper.advance_interval(st, t0, dt_sample, run);
      require_finite_state(st, n, t0 + dt_sample, sample_index);
      run.max_tau_n = std::max(run.max_tau_n, st.tau_n);
      run.min_tau_n = std::min(run.min_tau_n, st.tau_n);
    }
    if (ramp) continue;
    run.cycles = c_idx + 1;
    if (!previous.empty()) {
      measure_periodicity(cycle, previous, periodicity_floor_n, options.periodicity_tolerance, run);
      if (run.periodic && run.cycles >= options.min_cycles) break;
    }
    previous = cycle;
  }
  int slack_count = 0;
  for (const auto& sample : cycle) slack_count += sample.slack ? 1 : 0;
  run.slack_fraction = static_cast<double>(slack_count) / spp;
  run.samples = cycle;
  return run;
}

}  // namespace towdb::towline
