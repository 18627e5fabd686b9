// Seakeeping of one vessel by strip theory: Lewis-form sections solved by the
// Ursell-Tasai multipole method, the Salvesen-Tuck-Faltinsen (STF 1970)
// ship-motion equations at forward speed in oblique waves, and the added
// resistance of Gerritsma & Beukelman (1972). Part of the MIT 5D chain of
// Desroches (1997) (docs/physics.md section 3).
//
// ---------------------------------------------------------------------------
// CONVENTIONS (re-derived here; every sign below was checked by a test)
// ---------------------------------------------------------------------------
// Ship axes: x forward, y to port, z up, origin at midships on the waterline
// (model/vessel.hpp). Modes (DOF index 0..5): surge x, sway y, heave z,
// roll (right hand about +x: starboard down), pitch (about +y: bow DOWN),
// yaw (about +z: bow to port). Vertical displacement of the hull at x is
// heave - x * pitch; lateral displacement is sway + x * yaw.
// Heading mu [rad], any value: 0 = following seas (waves travel toward +x),
// pi = head seas, pi/2 = waves travelling toward +y (coming from starboard).
// Incident wave in the ship frame moving at speed U [m/s] along +x:
//   EQ-WAVE-1  zeta(x, y, t) = Re{ zeta_a exp(i (w_e t - k x cos mu - k y sin mu)) },
//              k = w^2 / g (deep water),  w_e = w - k U cos mu.
// So the wave crest is at the origin at t = 0. Every complex amplitude X of a
// force or motion means X(t) = Re{ X exp(i w_e t) } with the SIGNED w_e: a
// positive phase is a lead on the crest at midships. For w_e < 0 the same
// real motion is Re{ conj(X) exp(i |w_e| t) }.
// Units: SI (m, kg, s, N, rad). Forces per unit wave amplitude in N/m,
// moments in N m/m = N; RAOs of translations in m/m, of rotations in rad/m.
//
// ---------------------------------------------------------------------------
// LEWIS SECTIONS (Lewis 1929; Tasai 1959; Journee & Adegeest 2003, TUD 1370)
// ---------------------------------------------------------------------------
// Solver plane (Ursell's): X horizontal (= ship y), Y DOWN (= -ship z), Z = X + iY.
//   EQ-LEWIS-1  Z = M (zeta + a1/zeta + a3/zeta^3), zeta = e^{alpha + i theta};
//               on the contour (alpha = 0): X = M((1+a1) cos t + a3 cos 3t),
//               Y = M((1-a1) sin t - a3 sin 3t); t = 0 waterline, pi/2 keel.
//               Half beam b = M(1+a1+a3), draft T = M(1-a1+a3).
//   EQ-LEWIS-2  H0 = B/(2T) gives a1 = (H0-1)(1+a3)/(H0+1); the area coefficient
//               sigma = A/(BT) = (pi/4)(1 - a1^2 - 3 a3^2)/((1+a3)^2 - a1^2)
//               is then a quadratic in a3; the root with a3 = 0 at sigma = pi/4.
//   EQ-LEWIS-3  Valid forms: dZ/dzeta = M(1 - a1 w - 3 a3 w^2), w = zeta^-2,
//               has no zero with |w| <= 1 + margin, and X, Y >= 0 on the half
//               contour. Otherwise sigma is moved toward pi/4 (the ellipse,
//               always valid) to the nearest valid value (bisection), flagged.
//   EQ-LEWIS-4  Infinite-frequency heave added mass (Lewis 1929):
//               a33(inf) = rho (pi/2) M^2 ((1+a1)^2 + 3 a3^2).
//   EQ-LEWIS-5  B/(2T) is clamped to [0.05, 15] (options): beyond, the wave
//               source/dipole at the origin lies too close to the contour for
//               the multipole series to converge. Near a pointed end this
//               widens a very thin strip (its coefficients are small anyway).
//
// ---------------------------------------------------------------------------
// SECTION RADIATION PROBLEMS (Ursell 1949; Tasai 1959; Porter 1960)
// ---------------------------------------------------------------------------
// Potential Phi = Re{phi e^{i w t}}, K = w^2/g. Free surface (Y = 0):
//   EQ-SECTION-1  K phi + d phi / dY = 0  <=>  Re{K W + i dW/dZ} = 0 for the
//               complex potential W = phi + i psi (psi the stream function).
//   EQ-SECTION-2  Wave-free multipoles (Tasai), n = 2m (heave) or 2m+1 (sway, roll):
//               W_n = zeta^-n - i K M [zeta^-(n-1)/(n-1) - a1 zeta^-(n+1)/(n+1)
//                                      - 3 a3 zeta^-(n+3)/(n+3)]
//               (substitution in EQ-SECTION-1 with dZ/dzeta real on the real axis).
//   EQ-SECTION-3  Symmetric wave source at the origin, G(w) = e^w E1(w), w = iKZ:
//               f_c = pi e^{iKZ},  f_s = -(G(iKZ) + i pi e^{iKZ})  (X >= 0),
//               K f_s + i f_s' = i/Z (real part 0 on Y = 0, X != 0);
//               far field Re f_c -> pi e^{-KY} cos KX, Re f_s -> pi e^{-KY} sin K|X|.
//               Antisymmetric (horizontal dipole): f_ac = i pi e^{iKZ},
//               f_as = f_s'/K = -i G + 1/(K Z) + pi e^{iKZ}.
//   EQ-SECTION-4  Radiation condition (outgoing e^{i(wt - K|X|)}): the source
//               column is phi_c - i phi_s (both symmetry classes), so
//               phi = A (phi_c - i phi_s) + sum_m p_m Re W_n, A, p_m complex.
//   EQ-SECTION-5  Body condition through the stream function, collocated on the
//               half contour and solved by least squares (columns scaled):
//               psi(t) - psi(keel) = U (Y - T) - V X - Omega (X^2 + Y^2 - T^2)/2
//               for a body velocity (U, V) along (X, Y) and rotation Omega
//               (X toward Y) about the origin. The number of multipoles N grows
//               from min_terms until every impedance changes by less than
//               convergence_tolerance (relative) from N-1 to N.
//   EQ-SECTION-6  Force on the body F = i w rho int phi n ds (n out of the body),
//               F_i / V_j = -b_ij - i w a_ij. Ship axes: heave w = -V and roll
//               p = -Omega, so a33, a22, a44 keep their sign and
//               a24 = -a_{X,Omega}, a42 = -a_{Omega,X} (reciprocal: a24 = a42).
//   EQ-SECTION-7  Far field: eta_rad = -(i w/g) phi(Y=0); damping equals the
//               radiated energy flux: b_jj = rho g^2 |eta_j|^2 / w (both sides,
//               eta_j per unit velocity).
//   EQ-SECTION-8  K -> infinity: phi = 0 on Y = 0; basis -i L_n(zeta) (the
//               K-multiplied part of EQ-SECTION-2); real weights.
//   EQ-SECTION-9  Froude-Krylov per unit length, unit wave amplitude:
//               f_j = -int p n_j ds, p = rho g e^{kz - i k y sin mu} (strip at x = 0),
//               n_4 = y n_3 - z n_2 (roll about the waterline centre).
//   EQ-SECTION-10 Diffraction (Haskind form, STF 1970): with psi_j the section
//               potential per unit velocity at the encounter frequency,
//               D_j = rho int phi_D n_j ds = -rho int psi_j d(phi_0)/dn ds,
//               phi_0 = (i g/w) e^{kz - i k y sin mu},
//               d(phi_0)/dn = k phi_0 (n_3 - i sin mu n_2);
//               the zero-speed diffraction force of the strip is i w_e D_j.
//               2-D check (beam seas, zero speed): b_jj = w |X_j|^2 / (rho g^2).
//   EQ-SECTION-11 w_e < 0: the outgoing solution in e^{i w_e t} is the complex
//               conjugate of the one at |w_e|: a, b are evaluated at |w_e| and
//               the potentials conjugated.
//
// ---------------------------------------------------------------------------
// STRIP THEORY AT FORWARD SPEED (STF 1970, re-derived)
// ---------------------------------------------------------------------------
// Sectional impedance Z_pq(x) = a_pq + b_pq / (i w), p, q in {sway, heave, roll}.
// Ship mode j acts on section mode s(j) with shape c_j(x): heave, sway, roll
// c = 1; pitch c = -x (on heave); yaw c = +x (on sway). With the steady flow
// -U along x, the relative normal velocity of a strip is
//   EQ-STRIP-1  w_j(x) = (i w - U d/dx)(c_j eta_j) = (i w c_j - U c_j') eta_j.
// Momentum theorem on the strip, pressure p = -rho (d/dt - U d/dx) phi:
//   EQ-STRIP-2  F_i = -int c_i (i w - U d/dx)[Z w_j] dx
//                   = -int (i w c_i + U c_i') Z w_j dx - U c_i(x_A) Z_A w_j(x_A)
//               (integration by parts; the bow term vanishes for a bow of zero
//               section; the aft-end term is STF's transom term).
//   EQ-STRIP-3  K_ij = -F_i / eta_j = -w^2 A_ij + i w B_ij.
//               This gives STF's table: A33 = int a33 - (U/w^2) b33_A,
//               B33 = int b33 + U a33_A, A35 = -int x a33 - (U/w^2) B33_0
//               + (U/w^2) x_A b33_A - (U^2/w^2) a33_A, B35 = -int x b33
//               + U A33_0 - U x_A a33_A - (U^2/w^2) b33_A, A53 = -int x a33
//               + (U/w^2) B33_0 + (U/w^2) x_A b33_A, B53 = -int x b33 - U A33_0
//               - U x_A a33_A, A55 = int x^2 a33 + (U^2/w^2) A33_0 - (U/w^2)
//               x_A^2 b33_A + (U^2/w^2) x_A a33_A, ... (sway/yaw/roll alike).
//   EQ-STRIP-4  Wave exciting force per unit amplitude,
//               F_i = int c_i f^FK_s(i)(x) e^{-ikx cos mu} dx
//                   + int (i w c_i + U c_i') D_s(i)(x) e^{-ikx cos mu} dx
//                   + U c_i(x_A) D_s(i)(x_A) e^{-ik x_A cos mu}.
//   EQ-STRIP-5  Hydrostatics (origin on the waterline): C33 = rho g int B dx,
//               C35 = C53 = -rho g int x B dx, C44 = m g GM,
//               C55 = rho g int x^2 B dx + rho g V z_B - m g z_G, V = m / rho.
//   EQ-STRIP-6  Rigid-body mass about the origin, G at r_G = (x_G, 0, KG - T):
//               M = [[m I, -m S(r_G)], [m S(r_G), I_G - m S(r_G)^2]], S(r) v = r x v,
//               I_G = m diag(k_xx^2, k_yy^2, k_zz^2).
//   EQ-STRIP-7  Surge (no strip radiation): A11 = surge_added_mass_ratio m,
//               B11 = 0 (the wave-induced surge damping is separate, EQ-AR-3);
//               Froude-Krylov force by Gauss' theorem on the hull volume:
//               F1 = i k cos mu rho g int e^{-ikx cos mu} int int_A e^{kz - iky sin mu} dA dx;
//               likewise the z n_1 part of the pitch moment (n_5 = z n_1 - x n_3),
//               F5 += i k cos mu rho g int e^{-ikx cos mu} int int_A z e^{kz - iky sin mu} dA dx,
//               which with the mass coupling M15 = m z_G makes pitch -> wave slope.
//               Diffraction (ResponseOptions::surge_diffraction, on since 0.4.0): the
//               long-wave limit of the exciting force on a body, F = (rho V + A11) du/dt
//               (G. I. Taylor; Newman, Marine Hydrodynamics, 1977, sec. 4.15), with the
//               added-mass part driven by the fluid acceleration the moving hull meets,
//               i w_e u, while Froude-Krylov's pressure gradient carries i w u:
//               F1_D = (A11 / (rho V)) (w_h / w) F1_FK. With it a free hull in long waves
//               at rest surges with the water (|x1| -> 1); without, m / (m + A11).
//   EQ-STRIP-8  Roll: B44 += 2 zeta_roll sqrt((M44 + A44) C44) (hull.roll_damping_ratio).
//   EQ-STRIP-9  Motions: [-w^2 (M + A) + i w B + C] x = F.
//   EQ-STRIP-10 Encounter frequency floor: the hydrodynamics and the motion
//               equation use w_h = sign(w_e) max(|w_e|, f sqrt(g/L)),
//               f = min_encounter_frequency_nondim (the 2-D heave added mass
//               diverges like ln(1/K) as w -> 0 and the speed terms like U/w^2).
//               w_e = 0 counts as positive.
//
// ---------------------------------------------------------------------------
// ADDED RESISTANCE (Gerritsma & Beukelman 1972, radiated energy)
// ---------------------------------------------------------------------------
//   EQ-AR-1  R_aw / zeta_a^2 = -(k cos mu / (2 w_e)) int b'33(x) |V_z(x)|^2 dx,
//            b'33 = b33 - U d a33/dx,
//            V_z = i w_e (eta3 - x eta5) + U eta5 - i w zeta* e^{-ikx cos mu},
//            zeta* = e^{-k T*(x)} (Smith correction), T* = A(x)/B(x).
//            Positive = a resistance (force toward -x). Head seas: cos mu = -1.
//   EQ-AR-4  Aft of beam (cos mu > 0, following and quartering seas) the
//            radiated-energy method breaks down: waves overtake the ship,
//            w_e passes through 0 and the 1/w_e factor of EQ-AR-1 grows
//            without bound while the motions vanish (FFG 7 at 9 kt in
//            following seas: R_aw/zeta^2 = -6e5 N/m^2 near w_e = 0, ten times
//            the head-sea peak). By default R_aw = 0 there, the thesis's own
//            directional rule (eq. 2.9: sea-state resistance only forward of
//            beam; "slightly negative for trailing seas"). The option
//            added_resistance_aft_of_beam keeps EQ-AR-1 everywhere.
//   EQ-AR-2  Mean added resistance in a sea (thesis eq. 2.2):
//            R = 2 int R_aw/zeta^2 (w) S(w) dw, S in m^2 s/rad.
//   EQ-AR-3  Wave-induced surge damping (thesis 3.5):
//            B_w = (R(U + 1 ft/s) - R(U)) / (1 ft/s)  [N s/m].
//
// Sources: Salvesen, Tuck & Faltinsen, Ship motions and sea loads, Trans.
// SNAME 78 (1970); Ursell, Q. J. Mech. Appl. Math. 2 (1949); Tasai, Rep. Res.
// Inst. Appl. Mech. Kyushu Univ. 7 (1959); Lewis, Trans. SNAME 37 (1929);
// Gerritsma & Beukelman, Int. Shipbuilding Progress 19 (1972); Journee &
// Adegeest, Theoretical Manual of SEAWAY, TU Delft report 1370 (2003).
#ifndef TOWDB_SEAKEEPING_SEAKEEPING_HPP
#define TOWDB_SEAKEEPING_SEAKEEPING_HPP

#include <complex>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "common/units.hpp"
#include "model/vessel.hpp"
#include "seakeeping/lewis_section.hpp"

namespace towdb::seakeeping {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6cd = Eigen::Matrix<std::complex<double>, 6, 1>;

enum Dof : int { kSurge = 0, kSway = 1, kHeave = 2, kRoll = 3, kPitch = 4, kYaw = 5 };

struct ResponseOptions {
  SectionOptions section;                      // Lewis mapping and multipole solver
  double min_encounter_frequency_nondim = 0.1;  // floor of |w_e| sqrt(L/g) (EQ-STRIP-10)
  bool transom_terms = true;                   // STF aft-end terms (EQ-STRIP-2, -4)
  // EQ-AR-4: Gerritsma-Beukelman aft of beam (cos mu > 0) when true; else R_aw = 0 there.
  bool added_resistance_aft_of_beam = false;
  // EQ-STRIP-7: the surge diffraction force (A11 / rho V)(w_h / w) F1_FK when
  // true (the chain's default since 0.4.0, issue 17); Froude-Krylov alone when
  // false (0.3.0 and the thesis's 5D surge force; a diagnostic now).
  bool surge_diffraction = true;
  int num_threads = 1;                         // frequencies in parallel; <= 0 = all cores

  void validate() const;
};

// Response of one vessel to a regular wave of unit amplitude at one frequency.
struct VesselResponse {
  double omega_rad_s = 0.0;            // absolute wave frequency w
  double wavenumber_rad_m = 0.0;       // k = w^2 / g
  double omega_e_rad_s = 0.0;          // encounter frequency w - k U cos mu (signed)
  double omega_hydro_rad_s = 0.0;      // w_h actually used (EQ-STRIP-10), same sign as w_e
  double heading_rad = 0.0;
  double speed_m_s = 0.0;
  Matrix6d mass = Matrix6d::Zero();         // EQ-STRIP-6 [kg, kg m, kg m^2]
  Matrix6d added_mass = Matrix6d::Zero();   // EQ-STRIP-3, -7
  Matrix6d damping = Matrix6d::Zero();      // EQ-STRIP-3, -8 [N s/m, ...]
  Matrix6d restoring = Matrix6d::Zero();    // EQ-STRIP-5 [N/m, N, N m]
  Vector6cd froude_krylov_per_m = Vector6cd::Zero();  // per unit wave amplitude
  Vector6cd diffraction_per_m = Vector6cd::Zero();
  Vector6cd exciting_force_per_m = Vector6cd::Zero();  // Froude-Krylov + diffraction
  Vector6cd rao = Vector6cd::Zero();                   // motion per unit wave amplitude
  double added_resistance_n_per_m2 = 0.0;              // R_aw / zeta_a^2 (EQ-AR-1)
};

// Strip-theory response at every w in omegas_rad_s (> 0), speed U >= 0 and
// heading mu [rad]. The hull needs >= 3 stations with increasing x; stations
// with zero beam, draft or area coefficient contribute nothing. Throws
// InputError for bad inputs and NumericalError if a section does not converge.
// Results are bit-identical for any num_threads.
std::vector<VesselResponse> compute_response(const model::Vessel& vessel, double speed_m_s,
                                             double heading_rad,
                                             const std::vector<double>& omegas_rad_s,
                                             const ResponseOptions& options = {});

// EQ-STRIP-6 and EQ-STRIP-5 alone.
Matrix6d rigid_body_mass_matrix(const model::Hull& hull);
Matrix6d hydrostatic_restoring_matrix(const model::Hull& hull,
                                      const LewisOptions& lewis = {});

// ---- Added resistance (EQ-AR-2, EQ-AR-3) -----------------------------------

// Wave spectrum S(w) [m^2 s/rad] as a callable of w [rad/s].
using Spectrum = std::function<double(double)>;

struct AddedResistanceOptions {
  ResponseOptions response;     // strip theory settings
  double omega_min_rad_s = 0.2;  // lower end of the frequency grid (below it S ~ 0 for seas of interest)
  double omega_max_rad_s = 2.5;  // upper end (R_aw and S both small beyond for ships > 30 m)
  int omega_count = 48;          // grid points (trapezoid rule), >= 3
  double speed_step_m_s = units::ft_s_to_m_s(1.0);  // the thesis's +1 ft/s difference (EQ-AR-3)

  void validate() const;
};

// R = 2 sum trapezoid(R_aw/zeta^2 S) over the responses' frequencies
// (which must be increasing) [N].
double mean_added_resistance_n(const std::vector<VesselResponse>& responses,
                               const Spectrum& spectrum);

// Same, computing the responses on the options' uniform grid [N].
double mean_added_resistance_n(const model::Vessel& vessel, double speed_m_s, double heading_rad,
                               const Spectrum& spectrum, const AddedResistanceOptions& options = {});

// EQ-AR-3 [N s/m].
double wave_surge_damping_n_s_m(const model::Vessel& vessel, double speed_m_s, double heading_rad,
                                const Spectrum& spectrum, const AddedResistanceOptions& options = {});

}  // namespace towdb::seakeeping

#endif  // TOWDB_SEAKEEPING_SEAKEEPING_HPP
