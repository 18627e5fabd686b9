// The 12-degree-of-freedom coupled model of tug + towline + tow in the
// frequency domain (MIT 12D, program tow9712; thesis 3.4; docs/physics.md 5).
//
// DOFs: 0..5 the tug (surge, sway, heave, roll, pitch, yaw), 6..11 the tow,
// each in its own ship-fixed axes (x forward, y port, z up, origin midships on
// the waterline; pitch positive bow DOWN, as in seakeeping/seakeeping.hpp).
// Both vessels head the same way at the same speed U; the tow is a horizontal
// distance G behind the tug (origin to origin).
//
// Geometry of the line (in-line equilibrium, re-derived here):
//   alpha_1, alpha_2 = depression angles of the line at the tug's and the
//   tow's tow point (the line leaves both fittings downward). Unit tangents,
//   pointing from each fitting INTO the line:
//     t_1 = (-cos a1, 0, -sin a1)  (tug: aft and down)
//     t_2 = (+cos a2, 0, -sin a2)  (tow: forward and down)
//   A fitting at r = (x_p, 0, z_p) moves by u = (eta1 + z_p eta5, ..., eta3 - x_p eta5)
//   (sway, roll, yaw move it sideways only: normal to the line's vertical
//   plane, so they do not stretch it to first order).
//   EQ-COUPLED-1  xi = -t_1 . u_1 - t_2 . u_2 = S^T x,
//                 S = [cos a1, 0, sin a1, 0, z1 cos a1 - x1 sin a1, 0,
//                      -cos a2, 0, sin a2, 0, -z2 cos a2 - x2 sin a2, 0]
//                 (x_k, z_k the tow point of vessel k). The surge entries give
//                 the thesis's xi = x_1 cos a1 - x_7 cos a2 + xi_ns.
//   EQ-COUPLED-2  The tension increment tau acts on each fitting along t_k;
//                 its generalised force is -tau S (virtual work: tau dxi).
//                 Linearised line tau = k xi + c xi' (k = a10, c = a01 of the
//                 polynomial) adds K_line = k S S^T and B_line = c S S^T.
//   EQ-COUPLED-3  [-w_e^2 (M + A) + i w_e (B + B_s + c S S^T) + (C + k S S^T)] x = F,
//                 B_s = surge damping (hull + propeller + wave-induced) on
//                 DOFs 0 and 6, in addition to the strip-theory damping.
//   EQ-COUPLED-4  Wave phase lag: with the wave Re{a exp(i(w_e t - k x cos mu))}
//                 (seakeeping EQ-WAVE-1) the tow's origin at x = -G sees
//                 exp(+i k G cos mu) times the elevation at the tug's origin,
//                 so F = [F_tug ; F_tow exp(i k G cos mu)] referred to the
//                 tug's origin. Because the system is linear, every output is
//                 split as P(w) + Q(w) exp(i k G cos mu): P, Q are smooth in w
//                 and can be interpolated; the lag is applied per component.
//   EQ-COUPLED-5  Non-surge extension xi_ns = S_ns^T x, S_ns = S with the
//                 surge entries 0 and 6 zeroed (thesis 3.4, vector S_ns).
// Outputs per frequency (per unit wave amplitude at the tug's origin, complex
// amplitudes X(t) = Re{X exp(i w_e t)}): the first-order surge force on each
// vessel (referred to its own origin), xi_ns split as P + Q exp(i k G cos mu),
// the drift coefficients R_aw/zeta^2 of both vessels, and the vertical motion
// of each tow point.
// Units: SI. Source: Milgram (1995), J. Ship Res.; Desroches (1997) 3.4.
#ifndef TOWDB_COUPLED_COUPLED_HPP
#define TOWDB_COUPLED_COUPLED_HPP

#include <complex>
#include <vector>

#include <Eigen/Core>

#include "model/vessel.hpp"
#include "seakeeping/seakeeping.hpp"

namespace towdb::coupled {

using Vector12d = Eigen::Matrix<double, 12, 1>;
using Vector12cd = Eigen::Matrix<std::complex<double>, 12, 1>;
using Matrix12cd = Eigen::Matrix<std::complex<double>, 12, 12>;

struct LineGeometry {
  double tug_angle_rad = 0.0;   // alpha_1, depression at the tug's tow point
  double tow_angle_rad = 0.0;   // alpha_2, depression at the tow's bow fitting
  model::TowPoint tug_point;    // tow point in the tug's axes
  model::TowPoint tow_point;    // bow fitting in the tow's axes
  double separation_m = 0.0;    // G, tug origin to tow origin, horizontal (> 0)

  void validate() const;
};

struct LinearLine {
  double stiffness_n_m = 0.0;    // k = a10
  double damping_n_s_m = 0.0;    // c = a01
};

struct SurgeDampings {
  double tug_n_s_m = 0.0;  // hull + propeller + wave-induced
  double tow_n_s_m = 0.0;
};

// EQ-COUPLED-1.
Vector12d extension_vector(const LineGeometry& geometry);
// EQ-COUPLED-5.
Vector12d non_surge_extension_vector(const LineGeometry& geometry);

struct CoupledResponse {
  double omega_rad_s = 0.0;     // absolute wave frequency
  double omega_e_rad_s = 0.0;   // encounter frequency (signed)
  double wavenumber_rad_m = 0.0;
  // Motions for the wave at the tug origin: x = motion_p + motion_q e^{i k G cos mu}.
  Vector12cd motion_p = Vector12cd::Zero();
  Vector12cd motion_q = Vector12cd::Zero();
  std::complex<double> xi_ns_p{0.0, 0.0};  // EQ-COUPLED-5 parts
  std::complex<double> xi_ns_q{0.0, 0.0};
  std::complex<double> surge_force_tug_n_per_m{0.0, 0.0};  // tug's own origin
  std::complex<double> surge_force_tow_n_per_m{0.0, 0.0};  // tow's own origin
  double drift_tug_n_per_m2 = 0.0;  // R_aw / zeta^2
  double drift_tow_n_per_m2 = 0.0;
};

// Couples two strip-theory responses computed at the same absolute
// frequencies, speed and heading (EQ-COUPLED-3). Throws InputError when the
// responses do not match.
std::vector<CoupledResponse> couple(const std::vector<seakeeping::VesselResponse>& tug,
                                    const std::vector<seakeeping::VesselResponse>& tow,
                                    const LineGeometry& geometry, const LinearLine& line,
                                    const SurgeDampings& surge);

// The 12x12 impedance of EQ-COUPLED-3 at one frequency (for tests and tools).
Matrix12cd impedance(const seakeeping::VesselResponse& tug, const seakeeping::VesselResponse& tow,
                     const LineGeometry& geometry, const LinearLine& line, const SurgeDampings& surge);

}  // namespace towdb::coupled

#endif  // TOWDB_COUPLED_COUPLED_HPP
