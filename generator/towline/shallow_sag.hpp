// Shallow-sag cable dynamics about the static catenary (EQ-TOWLINE-6..10 in
// towline/towline.hpp): normal motion q(p, t) with fixed ends, a uniform
// dynamic tension tau(t) from the multi-segment compatibility relation,
// quadratic drag, added mass, and the slack constraint T + tau >= 0, driven by
// a prescribed extension of the chord p0(t) = a sin(w t).
//
// Discretisation (a lumped-mass finite-element/finite-volume scheme):
//  * nodes at element ends; elements never straddle a segment junction; the
//    number of elements of each segment is proportional to its wave travel
//    time int sqrt(m/T) dp, so every element has about the same transit time;
//  * element e has stretched length h_e, static tension T_e (at its middle),
//    turning angle dphi_e = int kappa dp (exact, from the catenary);
//  * node j: mass M_j = half the adjacent elements' structural mass (unstretched
//    length x mass per length, conserved) plus added mass C_A rho pi D^2/4 per
//    stretched length; drag factor D_j = half the adjacent (1/2) rho C_D D h_e;
//    curvature load vector b_j = (dphi_{j-1} + dphi_j) / 2 = int kappa N_j dp.
//  * tau c = p0 - sum_j b_j q_j + (1/2) sum_e (q_{e+1} - q_e)^2 / h_e  (EQ-TOWLINE-7)
//    with c = sum_i L_i / (EA)_i; tau = max(tau, -min_e T_e)         (EQ-TOWLINE-8)
//  * M_j q_j'' = f_j - f_{j-1} + tau b_j - D_j |q_j'| q_j',
//    f_e = (T_e + tau)(q_{e+1} - q_e)/h_e                             (EQ-TOWLINE-6)
//    Without drag and slack this is exactly Lagrange's equation of the energy
//    U = (1/2) sum_e T_e dq_e^2/h_e + (c/2) tau^2, so the scheme conserves
//    energy and cannot gain it through the tension coupling.
// Output is sampled at fixed phases (samples_per_period per cycle); each
// sample interval is split into k equal substeps. Two integrators:
//  * implicit trapezoidal rule (Newmark beta = 1/4, gamma = 1/2), the default:
//    the step residual M a + D|v|v - f = 0 is solved by Newton's method with
//    the exact Jacobian 4M/dt^2 + 4D|v|/dt + K_T + tau K + g g^T/c (the last
//    term only while taut), tridiagonal plus rank one: O(N) per iteration.
//    dt is set by accuracy (DynamicsOptions::steps_per_period and
//    steps_per_line_period), independent of the element size; an interval
//    whose Newton iteration fails is redone with twice the substeps.
//  * explicit kick-drift-kick (velocity Verlet), the reference: drag
//    semi-implicit in each half kick, v+ = (v + dt/2 F/M) / (1 + dt/2 D|v|/M);
//    k from a Gershgorin bound on the highest frequency of the linearised system,
//      omega_max^2 <= max_j 2 (a_{j-1} + a_j)/M_j + sum_j g_j^2 / (M_j c),
//      a_e = (T_e + tau)/h_e,  g_j = d(c tau)/d q_j,
//    and an interval is redone with more substeps whenever dt omega_max
//    exceeds the Courant limit (snap loads included).
// Both are deterministic: results depend only on the inputs.
#ifndef TOWDB_TOWLINE_SHALLOW_SAG_HPP
#define TOWDB_TOWLINE_SHALLOW_SAG_HPP

#include <vector>

#include "towline/catenary.hpp"

namespace towdb::towline {

enum class Integrator {
  // Newmark average acceleration (trapezoidal rule), Newton iterations per
  // step: unconditionally stable, dt set by accuracy (steps_per_period,
  // steps_per_line_period), not by the element size. The default.
  kImplicitTrapezoidal,
  // Kick-drift-kick with Courant-limited substeps: the independent reference.
  kExplicitVerlet,
};

struct DynamicsOptions {
  Integrator integrator = Integrator::kImplicitTrapezoidal;
  // Implicit: dt <= excitation period / this. The starting value of the
  // time-resolution search in build_towline_fit.
  int steps_per_period = 64;
  // Implicit: dt <= 2 pi / (lowest linear natural frequency of the line) /
  // this, so the line's own vibration (start-up, slack and snap) is resolved;
  // doubled together with steps_per_period by the search.
  int steps_per_line_period = 16;
  // Implicit: Newton stops when max |dq| <= this x (1 m + amplitude + max|q|).
  double newton_tolerance = 1e-10;
  // Implicit: Newton iterations before the sample interval is split in two.
  int newton_max_iterations = 30;
  // Output samples per excitation period (fixed phases: runs at different
  // resolutions can be compared sample by sample, and they feed the fit).
  int samples_per_period = 32;
  // The excitation amplitude is ramped in by (1 - cos)/2 over this many
  // periods, which keeps the start-up transient (free line vibration) small.
  int ramp_cycles = 1;
  // Full-amplitude cycles simulated at least (periodicity compares the
  // last two).
  int min_cycles = 2;
  // Full-amplitude cycles after which the run stops even if not periodic
  // (the last cycle is then used and HarmonicRun::periodic is false).
  int max_cycles = 60;
  // Periodic steady state: max_k |tau_k(cycle) - tau_k(previous cycle)| at
  // most this fraction of the cycle's tau range.
  double periodicity_tolerance = 2e-3;
  // Explicit: target dt * omega_max when substeps are chosen (stable below 2).
  double courant_target = 1.0;
  // Explicit: a substep with dt * omega_max above this is redone with more.
  double courant_limit = 1.9;
  void validate() const;
};

// One sample of a dynamics run (and one row of the polynomial fit's data).
struct TensionSample {
  double xi_m = 0.0;        // extension p0 along the chord
  double xi_dot_m_s = 0.0;  // its rate
  double tau_n = 0.0;       // dynamic tension (total minus static)
  bool slack = false;       // the slack limit held: tau = -min T (EQ-TOWLINE-8)
};

struct HarmonicRun {
  double amplitude_m = 0.0;
  double omega_rad_s = 0.0;
  std::vector<TensionSample> samples;  // the last simulated cycle, fixed phases
  int cycles = 0;                      // full-amplitude cycles simulated
  bool periodic = false;               // periodicity_tolerance reached
  double periodicity_change = 0.0;     // last cycle-to-cycle change / tau range
  double min_dt_s = 0.0;               // smallest and largest substep used
  double max_dt_s = 0.0;
  long long steps = 0;                 // substeps taken (retries included)
  long long newton_iterations = 0;     // implicit integrator only
  double slack_fraction = 0.0;         // recorded samples with the line slack
  double max_tau_n = 0.0;              // extremes of tau over the whole run
  double min_tau_n = 0.0;
};

struct LinearMode {
  double omega_rad_s = 0.0;
  // sum_j q_j q_{N-j} / sum_j q_j^2: +1 symmetric, -1 antisymmetric about the
  // middle node (meaningful for a symmetric line with level ends).
  double symmetry = 0.0;
};

class ShallowSagModel {
 public:
  // Discretises the line about `catenary` with about `n_elements` elements
  // (at least 2 per segment; the actual count is n_elements()).
  ShallowSagModel(const Catenary& catenary, int n_elements);

  int n_elements() const { return static_cast<int>(elem_h_m_.size()); }
  double compliance_m_n() const { return compliance_m_n_; }
  double tension_floor_n() const { return tau_floor_n_; }  // -min_e T_e
  double horizontal_tension_n() const { return horizontal_tension_n_; }

  // EQ-TOWLINE-10: d tau / d p0 for a quasi-static (slow, small) extension,
  // 1 / (c + b^T K_T^{-1} b), K_T the static-tension string stiffness.
  double quasi_static_stiffness_n_m() const;

  // Small-amplitude dynamic stiffness without drag, d tau / d p0 at frequency
  // omega: 1 / (c + b^T (K_T - omega^2 M)^{-1} b) (EQ-TOWLINE-10 at omega = 0).
  double linear_dynamic_stiffness_n_m(double omega_rad_s) const;

  // Lowest natural frequency of the same linear system (inverse iteration,
  // O(N)); sets the implicit integrator's time step.
  double lowest_frequency_rad_s() const;

  // EQ-TOWLINE-9: the `count` lowest natural frequencies of the linearised,
  // undamped discrete system M q'' + (K_T + b b^T / c) q = 0.
  std::vector<LinearMode> linear_modes(int count) const;

  // Integrates the response to p0(t) = amplitude sin(omega t) (after the ramp).
  // Throws NumericalError if the state becomes non-finite.
  HarmonicRun run_harmonic(double amplitude_m, double omega_rad_s,
                           const DynamicsOptions& options = {}) const;

 private:
  double horizontal_tension_n_ = 0.0;
  double compliance_m_n_ = 0.0;
  double tau_floor_n_ = 0.0;
  // Per element (size N).
  std::vector<double> elem_h_m_;
  std::vector<double> elem_tension_n_;
  // Per node (size N + 1; the end nodes are fixed and unused).
  std::vector<double> node_mass_kg_;
  std::vector<double> node_b_;
  std::vector<double> node_drag_kg_m_;
};

}  // namespace towdb::towline

#endif  // TOWDB_TOWLINE_SHALLOW_SAG_HPP
