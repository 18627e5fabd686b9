// towdb::towline: the towline model of the long-time towing simulation.
//
// From a towline (segments tug -> tow), the tow-point heights and the mean
// tension, it builds the static elastic catenary, runs the shallow-sag cable
// dynamics for a set of prescribed extensions, and fits the 9-coefficient
// polynomial tau(xi, xi_dot) of Desroches (1997) section 3.2 / Appendix A
// (programs cabnexp and t3fer97). Headers: towline/catenary.hpp (statics),
// towline/shallow_sag.hpp (dynamics), towline/polynomial.hpp (model and fit);
// this header adds the fit builder, its summary and the fit cache.
//
// SOURCES
//   Desroches, A. S. (1997), Calculation of extreme towline tension during
//     open ocean towing, MIT thesis: eqs. 3.1-3.4, sections 3.2, 6.1, 6.3.
//   Triantafyllou, M. S. (1987), Dynamics of cables and chains, Shock Vib.
//     Dig. 19(12) (the shallow-sag equations); Milgram, J. H. et al. (1988),
//     multi-segment compatibility.
//   Irvine, H. M. (1981), Cable Structures, MIT Press, ch. 2-4 (elastic
//     catenary, lambda^2); Irvine, H. M. & Caughey, T. K. (1974), The linear
//     theory of free vibrations of a suspended cable, Proc. R. Soc. A 341.
//
// AXES, SIGNS, UNITS (SI throughout: m, kg, s, N, rad)
//   x horizontal from the tug's tow point towards the tow; y upward; heights of
//   the end points above the waterline. s = unstretched arc length from the
//   tug end, p = stretched arc length. Segments are ordered tug -> tow.
//   Mean tension = H, the HORIZONTAL tension component (equal all along the
//   line and at the tow, where it balances the tow's resistance).
//   Modelling choice: the submerged weight w_i (weight_in_water_n_m) acts along
//   the whole line, including the short lengths above the water near the ends.
//   End angles alpha_1 (tug), alpha_2 (tow): depression angles, positive when
//   the line leaves the fitting downward. q: normal displacement of the line,
//   positive towards the centre of curvature (upward for a sagging line).
//   xi = p0: extension of the chord (tow point separation increase) [m];
//   tau: dynamic tension = total minus static, uniform along the line [N].
//
// STATICS (elastic catenary, Irvine 1981 eqs. 2.x generalised to segments)
//   EQ-TOWLINE-1  H = const;  V(s) = V_0 + W(s),  W(s) = int_0^s w ds',
//                 T(s) = sqrt(H^2 + V^2). V_0 < 0 when the line descends from the tug.
//   EQ-TOWLINE-2  dx/ds = H/T + H/(EA)_i,   dy/ds = V/T + V/(EA)_i,
//                 dp/ds = 1 + T/(EA)_i   (closed form per segment, see
//                 segment_integrals.hpp).
//   EQ-TOWLINE-3  closure: sum_i dy_i = h_tow - h_tug, solved for V_0 by a
//                 bracketed, safeguarded Newton method (dY/dV_0 > 0, so the
//                 bracket always exists); span X = sum_i dx_i.
//   EQ-TOWLINE-4  static axial stiffness at fixed heights:
//                 dH/dX = 1 / (X_H - X_V Y_H / Y_V), X_H = dX/dH etc.; the
//                 flexibility [X_H X_V; Y_H Y_V] is symmetric (X_V = Y_H).
//   EQ-TOWLINE-5  curvature kappa = d phi/dp = H w / (T^2 (1 + T/EA)),
//                 phi = atan(V/H); kappa > 0 (concave up) for a sagging line.
//   Limits: EA -> inf gives the inextensible catenary
//     X = (H/w) asinh terms, L^2 - dh^2 = (2H/w)^2 sinh^2(w X / 2H) (one segment);
//   w -> 0 gives the straight spring T = (chord - L) / sum_i L_i/(EA)_i.
//
// DYNAMICS (shallow sag about the static profile; Desroches eqs. 3.1, 3.3)
//   EQ-TOWLINE-6  m q_tt = d/dp[(T + tau) q_p] + tau kappa - (1/2) rho C_D D |q_t| q_t,
//                 m = mass per stretched length + C_A rho pi D^2/4, q = 0 at both ends.
//   EQ-TOWLINE-7  tau sum_i L_i/(EA)_i = p0(t) - int kappa q dp + (1/2) int q_p^2 dp.
//     Sign re-derived here: the arc length of the displaced profile exceeds
//     the static one by -int kappa q dp + (1/2) int q_p^2 dp (integration by
//     parts, q = 0 at the ends), and the chord adds p0, so the material
//     stretch tau c = p0 + (that change). Check: with U = (1/2) int T q_p^2 +
//     (c/2) tau^2, -dU/dq gives exactly EQ-TOWLINE-6 (lifting a sagging line,
//     q > 0, slackens it; the (1/2) int q_p^2 term stiffens it as a string).
//     The OCR of thesis eq. 3.2 reads "p0 - int .. q ds + 1/2 int ..^2 ds",
//     which agrees; both integral signs reversed would make EQ-TOWLINE-6
//     non-conservative (docs/physics.md 2.2).
//   EQ-TOWLINE-8  slack constraint: T + tau >= 0 everywhere, i.e.
//                 tau = max(tau, -min_p T(p)). While slack the compatibility
//                 is not enforced (the line hangs with zero tension at its
//                 lowest point and falls under its own weight).
//   EQ-TOWLINE-9  small-amplitude free vibration (single level segment):
//                 symmetric modes tan(W/2) = W/2 - (4/lambda^2)(W/2)^3,
//                 W = omega L / sqrt(H/m), lambda^2 = (w L / H)^2 L EA / (H L_e)
//                 (Irvine & Caughey 1974); antisymmetric modes W = 2 n pi.
//   EQ-TOWLINE-10 quasi-static limit: tau/p0 -> 1 / (c + int kappa q_hat dp),
//                 T q_hat'' = -kappa; one uniform shallow segment:
//                 k = 1 / (L/EA + w^2 L^3 / (12 H^3)).
//
// POLYNOMIAL MODEL (Desroches eq. 3.4; programs cabnexp and t3fer97)
//   EQ-TOWLINE-11 tau(xi, xi_dot) = sum_{1 <= m+n <= 3} a_mn xi^m xi_dot^n,
//                 coefficients a10, a01, a20, a11, a02, a30, a21, a12, a03.
//   EQ-TOWLINE-12 a_mn minimise sum (tau_run - tau(xi, xi_dot))^2 over the
//                 samples (last periodic cycle of each run) with
//                 H + tau_run <= breaking strength (samples above it left out).
//   EQ-TOWLINE-13 above breaking strength (thesis 6.1 eq. 6.4, 7.2 item 6),
//                 selectable: the line is straight, k = 1 / sum_i L_i/(EA)_i,
//                 tau = P(xi_b, xi_dot) + k (xi - xi_b) for xi > xi_b, where
//                 xi_b is the static extension at which H reaches the breaking
//                 strength (catenary solved at H = breaking strength).
//                 tau is continuous in xi and xi_dot.
//   EQ-TOWLINE-14 excitation set p0 = a sin(omega t): see ExcitationOptions.
//   EQ-TOWLINE-15 resolution criterion: N elements (time step dt) are used
//                 once max_p |tau_p(N) - tau_p(2N)|_rms / |tau_p(2N)|_rms
//                 <= resolution_tolerance over the probe runs p, compared at
//                 the same phases of their last cycle. A run that never
//                 becomes periodic (a slack line snapping irregularly) has no
//                 phase-locked state to compare: when the search would fail
//                 with every probe counted, the first resolution at which the
//                 probes periodic at both resolutions agree is used, if at
//                 least one probe was left out and one remained
//                 (FitSummary::resolution_probes_left_out).
//   EQ-TOWLINE-16 small-motion fit (beyond the thesis; default, selectable):
//                 the least squares of EQ-TOWLINE-12 subject to the
//                 quasi-static limit: for xi = A sin(w t) with A, w -> 0 the
//                 tension is k_s A, k_s = dH/dX (EQ-TOWLINE-4), and only a10
//                 survives; at A = 1 ft, T = 100 s the first harmonic of P
//                 (EQ-TOWLINE-17) must lie within small_motion_tolerance
//                 (10 %) of k_s A. The plain fit is kept where it does. Else
//                 the samples of run r are weighted (rms_max / rms_r)^e,
//                 rms_r = the run's RMS tau, for e = 0, 0.25, ..., 1 in turn:
//                 the first e whose fit with a10 held at k_s meets the
//                 tolerance is used, a10 moved back toward that weighting's
//                 free value as far as the tolerance allows (bisection).
//                 The thesis's plain least squares lets the largest runs
//                 (+-6 m) set the slope; slack-prone lines then answer small,
//                 slow motions with up to 5.7 times k_s A (T-ATF 166 / YRBM,
//                 2000 ft wire at 2,500 lbf), where their shallow-sag runs at
//                 0.03-0.07 rad/s give 0.93-0.96 k_s A. Measured figures:
//                 docs/validation.md, "Towline small motion".
//   EQ-TOWLINE-17 first harmonic of P(A sin wt, A w cos wt): see
//                 first_harmonic_n in polynomial.hpp.
//   EQ-TOWLINE-19 the damping a periodic run's motion meets, from the energy
//                 dissipated per cycle: c_eq = (integral of tau xi_dot dt over
//                 one cycle) / (pi w A^2), the linear damping that dissipates
//                 as much (run_damping). On a harmonic extension the polynomial
//                 gives c_eq = a01 + a21 A^2 / 4 + 3 a03 (A w)^2 / 4 (the other
//                 terms dissipate nothing over a cycle); the cable's normal drag
//                 gives c_eq proportional to A w at low frequency (Morison:
//                 energy per cycle ~ A^3 w^2). A diagnostic: the fit of
//                 EQ-TOWLINE-12 matches tension samples, in which the damping
//                 is a small quadrature part, and does not match this.
//   The simulation's slack limit is applied by dynamic_tension_n:
//   tau >= -min T (EQ-TOWLINE-8; -H when the line has a horizontal tangent).
//   Beyond the thesis (default, selectable): samples taken while the run was
//   slack only ask P <= tau in the fit (SlackFit::kOneSided), so the fit
//   targets the limited model max(P, -min T) that the simulation evaluates.
//
// NUMERICS (details in shallow_sag.hpp and polynomial.hpp)
//   Lumped-mass elements (at least 2 per segment, distributed by wave travel
//   time); implicit trapezoidal rule with Newton iterations (default) or
//   explicit velocity Verlet; output at 32 fixed phases per period; runs stop
//   at a periodic state. Resolution is chosen per fit by convergence, not
//   fixed: elements double from min_elements until four probe runs change by
//   <= resolution_tolerance (RMS tau), then the implicit time step halves
//   likewise; both choices and changes are reported in FitSummary. The 56
//   runs go through towdb::parallel_for (bit-identical for any thread count).
//
// KNOWN LIMITS
//   * Shallow sag: the quasi-static dynamic stiffness falls below the exact
//     catenary's dH/dX by about the line's mean square slope (2% at
//     sag/span ~ 0.07; 27% for a 2000 ft wire at 2,500 lbf).
//   * For catenary-dominated wire lines (static stiffness well below EA/L)
//     the RMS fit error over the excitation set is 12-42% of the RMS tension;
//     for nearly straight wire and for fiber it is below 10%. Two causes
//     (tests/validation/towline_calibration_test.cpp prints both): the tension
//     depends on the extension's frequency, which no tau(xi, xi_dot)
//     represents (2000 ft wire at 40,000-98,000 lbf: 12-28% with one
//     polynomial, 3-7% with one per excitation frequency), and slack-prone or
//     short lines are not a cubic in (xi, xi_dot) over +-6 m even at one
//     frequency (about 10-22% with one polynomial per frequency). The fitted a10
//     can even be negative for very slack wire.
//   * Very slack lines: probe runs that snap and never become periodic make
//     the point-by-point comparison depend on the input's last digits (T-ATF
//     166 / YRBM on 800 ft of fiber: 256 elements at 4,635.9 lbf, 512 at
//     4,635.94285 lbf, no convergence up to 1,024 at 4,700 lbf with every
//     probe counted). The second criterion of EQ-TOWLINE-15 then decides on
//     the periodic probes alone (128 elements at 4,700 lbf), which trusts
//     that the irregular runs are resolved as well as the regular ones.
//     Fits that the first criterion settles are unchanged by it.
#ifndef TOWDB_TOWLINE_TOWLINE_HPP
#define TOWDB_TOWLINE_TOWLINE_HPP

#include <cstddef>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "model/towline.hpp"
#include "towline/catenary.hpp"
#include "towline/polynomial.hpp"
#include "towline/shallow_sag.hpp"

namespace towdb::towline {

// What dynamic_tension_n does where the polynomial passes breaking strength.
enum class AboveBreakingModel {
  kPolynomial,      // thesis: the polynomial everywhere
  kStraightSpring,  // EQ-TOWLINE-13: equivalent straight spring k = EA/L
};

const char* to_string(AboveBreakingModel model);

struct TowlineFitOptions {
  CatenaryOptions catenary;      // static solver tolerances
  DynamicsOptions dynamics;      // time integration and periodicity
  ExcitationOptions excitation;  // the runs the polynomial is fitted to
  // Resolution search starts at this many elements and doubles ...
  int min_elements = 16;
  // ... up to this many (NumericalError beyond).
  int max_elements = 1024;
  // Implicit integrator: the time-step search (halving dt) stops with
  // NumericalError beyond this many steps per excitation period.
  int max_steps_per_period = 4096;
  // Resolution criterion, for elements and for the implicit time step: use N
  // elements (time step dt) once the probe runs' RMS tau difference between
  // N and 2N (dt and dt/2) is at most this fraction of their RMS tau. 2% is a
  // fifth of the 10% fit-error budget, so discretisation hardly shows in it.
  double resolution_tolerance = 0.02;
  // How slack samples enter the fit: kOneSided (default, beyond the thesis)
  // fits the slack-limited model the simulation uses; kTwoSided is t3fer97.
  SlackFit slack_fit = SlackFit::kOneSided;
  // EQ-TOWLINE-16 (beyond the thesis): constrain the fit to the catenary's
  // static stiffness dH/dX in the small, slow motion limit; false fits
  // plainly (t3fer97).
  bool hold_static_stiffness = true;
  // EQ-TOWLINE-16: each run's samples are weighted by (rms_max / rms_run)^e,
  // rms = the run's RMS tau: e = 0 is the thesis's plain least squares, where
  // the largest runs decide everything; 1 weighs every run's relative error
  // alike. e is the first of 0, 0.25, 0.5, ... up to this maximum at which
  // the fit can meet small_motion_tolerance (else the held fit that comes
  // closest).
  double max_run_weight_exponent = 1.0;
  // EQ-TOWLINE-16: |small_motion_ratio - 1| a fit must meet: the project
  // issue's criterion. A tighter one costs fit error over the large runs
  // (a 9-term cubic cannot follow both ends of a slack line's range).
  double small_motion_tolerance = 0.10;
  // Threads for the runs (towdb::parallel_for; <= 0: all). Results are
  // bit-identical for any value.
  int num_threads = 0;
  void validate() const;
};

// Everything the CLI prints about one fit (SI).
struct FitSummary {
  double mean_tension_n = 0.0;        // H
  double breaking_strength_n = 0.0;   // weakest segment
  double unstretched_length_m = 0.0;
  double span_m = 0.0;                // horizontal distance between the tow points
  double chord_m = 0.0;
  double sag_m = 0.0;                 // largest distance below the chord
  double lowest_elevation_m = 0.0;    // below the waterline when negative
  double tug_angle_rad = 0.0;         // alpha_1, depression at the tug
  double tow_angle_rad = 0.0;         // alpha_2, depression at the tow
  double tug_tension_n = 0.0;         // static total tension at the ends
  double tow_tension_n = 0.0;
  double static_stiffness_n_m = 0.0;  // catenary dH/dX (EQ-TOWLINE-4)
  double dynamic_static_stiffness_n_m = 0.0;  // shallow-sag quasi-static (EQ-TOWLINE-10)
  double straight_spring_n_m = 0.0;   // 1 / sum L_i/(EA)_i
  double spring_onset_extension_m = 0.0;  // xi_b of EQ-TOWLINE-13
  double slack_limit_n = 0.0;         // tau >= this (-min T of the discretised line)
  PolynomialCoefficients coefficients;
  double fit_rms_error_n = 0.0;
  double fit_max_error_n = 0.0;
  double rms_tension_n = 0.0;         // RMS tau of the samples used in the fit
  // EQ-TOWLINE-17 at kSmallMotionAmplitudeM, kSmallMotionPeriodS: the first
  // harmonic of the polynomial over static_stiffness_n_m x amplitude (1 in
  // the quasi-static limit).
  double small_motion_ratio = 0.0;
  double run_weight_exponent = 0.0;   // the e EQ-TOWLINE-16 chose
  int samples_used = 0;
  int samples_excluded = 0;           // above breaking strength
  // Range of the samples used: the polynomial is an extrapolation outside it
  // (a cubic can turn back: check excursions, or use kStraightSpring above).
  double fit_xi_min_m = 0.0;
  double fit_xi_max_m = 0.0;
  double fit_xi_dot_max_m_s = 0.0;    // largest |xi_dot|
  int n_elements = 0;                 // chosen spatial resolution
  int steps_per_period = 0;           // chosen implicit time resolution
  int steps_per_line_period = 0;      //   (0 for the explicit integrator)
  double min_dt_s = 0.0;              // range of substeps used by the runs
  double max_dt_s = 0.0;
  double space_resolution_change = 0.0;  // probe RMS change N -> 2N / RMS tau
  double time_resolution_change = 0.0;   // probe RMS change dt -> dt/2 / RMS tau
  // Probe runs that never became periodic and were left out of the accepted
  // resolution's criterion (EQ-TOWLINE-15); 0 when every probe agreed.
  int resolution_probes_left_out = 0;
  int runs = 0;
  int runs_not_periodic = 0;          // stopped at max_cycles
};

// The small, slow motion at which FitSummary::small_motion_ratio is read:
// 1 ft at a 100 s period, inside the quasi-static range of every bundled line
// (its shallow-sag runs at 0.03-0.07 rad/s and 0.1-0.6 m give 0.93-0.96 of
// the static stiffness) and the size of the slow second-order surge motions.
inline constexpr double kSmallMotionAmplitudeM = 0.3048;
inline constexpr double kSmallMotionPeriodS = 100.0;

// EQ-TOWLINE-17 at that motion over static_stiffness_n_m x amplitude: 1 in the
// quasi-static limit (FitSummary::small_motion_ratio of a fit).
double small_motion_ratio(const PolynomialCoefficients& c, double static_stiffness_n_m);

class TowlineFit {
 public:
  TowlineFit(Catenary catenary, FitSummary summary, std::vector<HarmonicRun> runs);

  const FitSummary& summary() const { return summary_; }
  const PolynomialCoefficients& coefficients() const { return summary_.coefficients; }
  const Catenary& catenary() const { return catenary_; }
  const std::vector<HarmonicRun>& runs() const { return runs_; }

  // The polynomial alone (EQ-TOWLINE-11) [N].
  double polynomial_n(double xi_m, double xi_dot_m_s) const {
    return summary_.coefficients.evaluate_n(xi_m, xi_dot_m_s);
  }
  // The dynamic tension the simulation uses [N]: EQ-TOWLINE-11 or -13, then
  // the slack limit tau >= slack_limit_n (= -min T along the line, which is
  // -H when the line has a horizontal tangent).
  double dynamic_tension_n(double xi_m, double xi_dot_m_s, AboveBreakingModel model) const;

 private:
  Catenary catenary_;
  FitSummary summary_;
  std::vector<HarmonicRun> runs_;
};

// EQ-TOWLINE-19 for one excitation run of a fit.
struct RunDamping {
  double omega_rad_s = 0.0;
  double amplitude_m = 0.0;
  double cable_n_s_m = 0.0;       // the shallow-sag cable's, from the run's samples
  double polynomial_n_s_m = 0.0;  // the simulation's law (dynamic_tension_n) on the same motion
  double slack_fraction = 0.0;    // of the run's recorded samples
};

// EQ-TOWLINE-19 for every run of `fit` with a non-zero amplitude, in the
// order of fit.runs(). The samples cover one cycle at uniform phases, so the
// cycle integral is the rectangle rule: exact for the unlimited polynomial's
// trigonometric integrand, of degree 4, with more than 4 samples a period
// (DynamicsOptions::samples_per_period, 32 by default).
std::vector<RunDamping> run_damping(const TowlineFit& fit);

// Builds the catenary, chooses the resolution (probe runs at N and 2N
// elements, doubling until resolution_tolerance; then dt and dt/2 likewise),
// runs the excitation set in parallel and fits the polynomial. `mean_tension_n` is H; it must be below
// the breaking strength. Throws InputError / NumericalError.
std::shared_ptr<const TowlineFit> build_towline_fit(const model::Towline& towline,
                                                    const TowPoints& points, double mean_tension_n,
                                                    const TowlineFitOptions& options = {});

// Thread-safe memo of build_towline_fit: a sweep computes each (towline,
// tow points, mean tension, options) fit once; concurrent requests for the
// same key wait for the one computation. Keys are the exact bit patterns of
// every physical number (names and file paths are ignored). Failures are
// cached too (the same inputs fail the same way).
class TowlineFitCache {
 public:
  std::shared_ptr<const TowlineFit> get(const model::Towline& towline, const TowPoints& points,
                                        double mean_tension_n,
                                        const TowlineFitOptions& options = {});
  std::size_t size() const;
  std::size_t builds() const;  // fits actually computed
  void clear();

 private:
  using Future = std::shared_future<std::shared_ptr<const TowlineFit>>;
  mutable std::mutex mutex_;
  std::map<std::string, Future> entries_;
  std::size_t builds_ = 0;
};

// The process-wide cache.
TowlineFitCache& global_fit_cache();

}  // namespace towdb::towline

#endif  // TOWDB_TOWLINE_TOWLINE_HPP
