// towdb::propulsion: hull resistance and surge damping, tug propeller damping
// at constant RPM (Wageningen B-series), the tow's locked or free-spinning
// propeller drag, and the mean (steady) towline tension.
//
// This is the module's main header: it states every equation the module
// implements and includes the sub-headers that declare the functions.
//
// ---------------------------------------------------------------------------
// CONVENTIONS (re-derived for this module; every interface keeps them)
// ---------------------------------------------------------------------------
//   Surge: x forward (the towing direction). Speed V >= 0 is the steady
//   speed of the tow through still water. A resistance R(V) > 0 acts aft.
//   Surge damping B = dR_net/dV [N s/m] is the slope of the net aft force
//   with respect to forward speed, so a perturbation dv > 0 produces the
//   force -B dv: B > 0 is stabilising. For the hull, R_net = R(V) and
//   B = +dR/dV. For the tug's propeller, the forward thrust T(V) counts as
//   a negative aft force, so B_P = -dT/dV, positive when thrust falls as
//   speed rises (constant RPM). Signs re-derived here from the equations
//   below, not copied.
//   Headings (wind and waves) use towdb's convention: mu = 0 following
//   (travelling with the ship), mu = pi head (coming at the bow). The
//   thesis's eq. 2.9 measures theta from HEAD seas; the conversion is
//   theta = pi - |mu| (after wrapping mu into (-pi, pi]), done explicitly in
//   EQ-PROPULSION-11.
//
// ---------------------------------------------------------------------------
// UNITS (SI inside; every name carries its unit)
// ---------------------------------------------------------------------------
//   speeds m/s; forces N; damping N s/m; areas m^2; lengths m; densities
//   kg/m^3; rotation rate rev/s (n) and rpm only in model::Propellers;
//   torque N m; power W; angles rad. Coefficients K_T, K_Q, C_T, C_D, J,
//   P/D, A_E/A_0 are dimensionless. The Navy formulas quoted in lbf, ft^2
//   and kt are re-expressed with dimensionless drag coefficients (derived
//   below) so that no dimensional factor appears in the code.
//
// ---------------------------------------------------------------------------
// EQUATIONS
// ---------------------------------------------------------------------------
// EQ-PROPULSION-1  Hull resistance from the drag file (thesis eq. 2.3;
//   PNA vol. II):  R_H(V) = (1/2) rho S V^2 C_T(V)
//   rho sea-water density, S wetted surface, C_T(V) piecewise linear in V
//   between the tabulated speeds and held constant outside the table
//   (model::DragCurve). A margin factor (1 + m) multiplies R_H in the mean
//   tension (thesis: m = 0.10; Towing Manual: m = 0.25).
//
// EQ-PROPULSION-2  Hull surge damping (thesis 3.3 "slopes of the resistance
//   versus speed curves"), analytic derivative of EQ-PROPULSION-1:
//     B_H = dR_H/dV = rho S V C_T(V) + (1/2) rho S V^2 dC_T/dV
//   with dC_T/dV = (C_{i+1} - C_i)/(V_{i+1} - V_i) on segment i, and 0
//   outside the table. At a table speed (a kink) the one-sided slopes
//   differ; KinkRule chooses: the mean of the two (default, the derivative
//   of the local linear fit through both neighbouring segments' ends), the
//   lower-speed side, or the upper-speed side. A speed within 1e-9 relative
//   of a tabulated speed counts as that speed. Optionally a forward
//   difference (R(V + dV) - R(V))/dV, as the thesis's programs took slopes:
//   for the T-ATF at 10 ft/s the thesis's 754 lbf s/ft is matched by the
//   1 ft/s step (763) rather than by the tangent (705); the default stays
//   the analytic tangent, the damping of a small surge oscillation.
//
// EQ-PROPULSION-3  Wageningen B-series open-water polynomials (Oosterveld &
//   van Oossanen 1975, Re = 2e6; thesis eqs. 3.18-3.19):
//     K_T = sum_{39 terms} C_stuv J^s (P/D)^t (A_E/A_0)^u Z^v
//     K_Q = sum_{47 terms} C_stuv J^s (P/D)^t (A_E/A_0)^u Z^v
//   Validity: 2 <= Z <= 7, 0.30 <= A_E/A_0 <= 1.05, 0.5 <= P/D <= 1.4.
//   The coefficient table is data (bseries_coefficients.cpp, with its
//   source and cross-check notes).
//
// EQ-PROPULSION-4  Open-water propeller (thesis eqs. 3.14-3.16):
//     V_A = V (1 - w),  J = V_A / (n D),
//     T = rho n^2 D^4 K_T(J, P/D),  Q = rho n^2 D^5 K_Q(J, P/D),
//     P_D = 2 pi n Q  (delivered power per propeller).
//   w Taylor wake fraction, n rev/s, D diameter.
//
// EQ-PROPULSION-5  Thrust balance of the tug at speed V (thesis 3.6 steps
//   3-4):  T_req = (f_R R_tug(V) + T_mean) / (N_p (1 - t))
//   N_p number of propellers, f_R a resistance factor (thesis: 1), t the
//   thrust-deduction fraction (thesis: not applied, t := 0).
//   n = f_n n_max with f_n = 0.8 (thesis step 1). P/D solves
//   K_T(J, P/D) = T_req / (rho n^2 D^4) on [0.5, 1.4] (bracketed Newton).
//
// EQ-PROPULSION-6  Tug propeller surge damping at constant RPM and fixed
//   pitch (thesis 3.6 steps 8-9):
//     B_P,1 = -(T(V + dV) - T(V)) / dV,  dV = 1 ft/s (thesis),
//   whose dV -> 0 limit is
//     B_P,1 = -dT/dV = -rho n D^3 (1 - w) dK_T/dJ   (per propeller).
//   The thesis keeps ONE propeller's damping (conservative: lower damping,
//   higher dynamic tension); the option kAllPropellers uses N_p B_P,1.
//   When T_req exceeds what the propeller gives at P/D = 1.4 (the thesis's
//   negative-damping case, mean tension > 140,000 lbf), or the computed
//   damping is below a floor, the damping is set to the floor
//   B_P,min (a named option; thesis: "a small positive value").
//
// EQ-PROPULSION-7  Locked propeller drag, Towing Manual form (thesis eq.
//   2.5): R_P = 3.737 A_P V^2 [lbf; ft^2; kt]. With rho = 1.9905 slug/ft^3
//   and 1 kt = 1.68781 ft/s this is R_P = (1/2) rho C_DP A_P V^2 with
//     C_DP = 2 * 3.737 / (1.9905 * 1.68781^2) = 1.3181  (dimensionless).
//   Projected area from the expanded area when not given (UFC 4-159-03
//   eq. 4-22, after Taylor):  A_P = N_p (pi D^2 / 4) (A_E/A_0) (1.067 - 0.229 P/D).
//   The thesis's ch. 2 calculation applies the wake: V -> V (1 - w).
//
// EQ-PROPULSION-8  Locked propeller drag, disk-area form (thesis eq. 2.4;
//   Hoerner bluff-body C_D = 1.17): R_P = (1/2) rho C_D A_0 V_p^2,
//   A_0 = N_p pi D^2 / 4, V_p = V (1 - w) (wake-reduced) or V.
//   Check (thesis below eq. 2.5): with A_P/A_0 = 0.72 and w ~= 0.1 the two
//   forms agree: 1.17 * 0.81 = 0.948 vs 1.3181 * 0.72 = 0.949.
//
// EQ-PROPULSION-9  Free-spinning propeller: R_P,free = (1/2) R_P,locked
//   (Towing Manual, thesis ch. 2). Removed propeller: R_P = 0. Tow
//   propeller surge damping (thesis 6.1 / future work item 4):
//   B_P,tow = dR_P/dV = 2 R_P / V (every form above is quadratic in V).
//
// EQ-PROPULSION-10  Wind drag. Relative wind (true wind speed U, wind
//   heading mu_w in the wave convention): along-ship component from ahead
//   u_R = V - U cos(mu_w), across v_R = U sin(mu_w), V_R^2 = u_R^2 + v_R^2.
//   Towing Manual (thesis eq. 2.8): R_W = 0.00506 C_w K A_T V_R^2
//   [lbf; ft^2; kt]; with rho_air = 0.002377 slug/ft^3 this is
//     R_W = (1/2) rho_air C_W0 C_w K A_T V_R^2,
//     C_W0 = 2 * 0.00506 / (0.002377 * 1.68781^2) = 1.4945.
//   Taylor (thesis eq. 2.6): R_W = 1.28 (1/2) rho_air A_T V_R^2 K.
//   The two agree for C_w = 1.28 / 1.4945 = 0.857 (default C_w = 0.85,
//   middle of the manual's 0.7-1.0). Heading coefficient: the manual's K = 1
//   for head wind; its table for other angles was not available, so K is
//   the along-ship projection K = cos(a)|cos(a)| (a = relative wind angle
//   off the bow), i.e. R_W = (1/2) rho_air C A_T u_R |u_R|. A following
//   wind faster than the tow gives R_W < 0 (it pushes the tow).
//
// EQ-PROPULSION-11  Sea-state added resistance R_S is supplied by the
//   caller (seakeeping: thesis eq. 2.2, R_S = 2 int R_aw/zeta^2 S dw). For
//   a head-seas value R_S,head (e.g. the Towing Manual's), thesis eq. 2.9:
//     R_S = R_S,head cos(theta) for 0 <= theta <= pi/2, else 0,
//   theta the angle of the seas from HEAD seas. In towdb's convention
//   theta = pi - |mu| with mu wrapped into (-pi, pi]; so R_S = -R_S,head cos(mu)
//   for |mu| >= pi/2 and 0 for |mu| < pi/2.
//
// EQ-PROPULSION-12  Mean towline tension (thesis ch. 2; U.S. Navy Towing
//   Manual App. G; docs/physics.md 4.5):
//     R_tow = (1 + m) R_H + R_P + R_W + R_S
//     R_line = f_line * max(R_tow, 0)     (f_line = 0.10, the manual's rule)
//     T_mean = R_tow + R_line
//   unless the caller supplies R_line (e.g. from a towline drag model).
//
// ---------------------------------------------------------------------------
// SOURCES
// ---------------------------------------------------------------------------
//   Desroches, A. S. (1997), Calculation of Extreme Towline Tension During
//     Open Ocean Towing, MIT thesis: ch. 2 (eqs. 2.2-2.9), 3.6, 6.1.
//   Oosterveld, M. W. C. & van Oossanen, P. (1975), Further computer-analyzed
//     data of the Wageningen B-screw series, Int. Shipbuilding Progress 22.
//   U.S. Navy Towing Manual (SL740-AA-MAN-010), App. G, as reproduced in
//     Army TB 55-1900-232-10 (1991), App. G.
//   UFC 4-159-03 (Moorings), eq. 4-22, projected-area ratio of a propeller.
//   Hoerner, S. F. (1965), Fluid-Dynamic Drag (C_D = 1.17 for a disk).
#ifndef TOWDB_PROPULSION_PROPULSION_HPP
#define TOWDB_PROPULSION_PROPULSION_HPP

#include "propulsion/bseries.hpp"
#include "propulsion/hull_damping.hpp"
#include "propulsion/mean_tension.hpp"
#include "propulsion/tow_propeller.hpp"
#include "propulsion/tug_propeller.hpp"

#endif  // TOWDB_PROPULSION_PROPULSION_HPP
