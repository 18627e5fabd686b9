// Lewis-form sections and their two-dimensional hydrodynamics by the
// Ursell-Tasai multipole method (frequency domain, deep water).
//
// The equations, conventions and sources are stated once, in
// seakeeping/seakeeping.hpp (EQ-LEWIS-*, EQ-SECTION-*); this header only
// declares the section-level API.
//
// Section plane coordinates used inside the solver (Ursell's): X horizontal,
// Y positive DOWNWARD, complex Z = X + i Y, fluid in Y > 0. Every quantity
// returned is converted to ship axes (y to port, z up; origin on the
// waterline at the centre plane): y = X, z = -Y.
#ifndef TOWDB_SEAKEEPING_LEWIS_SECTION_HPP
#define TOWDB_SEAKEEPING_LEWIS_SECTION_HPP

#include <array>
#include <complex>
#include <vector>

namespace towdb::seakeeping {

// EQ-LEWIS-1..3: the Lewis conformal map of one section.
struct LewisForm {
  double scale_m = 0.0;                // M, Z = M (zeta + a1/zeta + a3/zeta^3)
  double a1 = 0.0;                     // first Lewis coefficient [-]
  double a3 = 0.0;                     // second Lewis coefficient [-]
  double half_beam_m = 0.0;            // b = B/2 = M (1 + a1 + a3)
  double draft_m = 0.0;                // T = M (1 - a1 + a3)
  double area_coefficient = 0.0;       // sigma actually mapped (after any adjustment)
  double requested_area_coefficient = 0.0;  // sigma asked for
  bool area_coefficient_adjusted = false;   // true when sigma was moved into the valid range
  bool proportions_adjusted = false;        // true when B/(2T) was clamped (EQ-LEWIS-5)
};

struct LewisOptions {
  // Smallest allowed |w| of a zero of dZ/dzeta (w = zeta^-2) over 1: a zero on
  // |zeta| = 1 is a cusp in the contour, which the multipole series cannot fit.
  double conformal_margin = 0.02;
  // Bisection steps when sigma must be pulled back into the valid range.
  int adjust_iterations = 60;
  // B/(2T) below this is mapped with a wider beam: the antisymmetric wave
  // dipole at the origin lies within B/2 of the contour and the multipole
  // series stops converging (about 150 terms at 0.02; 100 at 0.05).
  double min_half_beam_draft_ratio = 0.05;
  // B/(2T) above this is mapped with a deeper draft (same reason, flat forms).
  double max_half_beam_draft_ratio = 15.0;

  void validate() const;
};

// Lewis coefficients for beam B [m], draft T [m] and area coefficient
// sigma = A/(B T) [-]. B/(2T) outside the options' range is clamped (the
// beam widened or the draft deepened, flagged). An area coefficient outside the range the Lewis family
// can represent for this B/T (non-conformal or re-entrant contour) is moved
// to the nearest valid value toward the ellipse (sigma = pi/4, a3 = 0), and
// the result says so. Throws InputError for B <= 0, T <= 0, sigma outside (0, 1].
LewisForm lewis_form(double beam_m, double draft_m, double area_coefficient,
                     const LewisOptions& options = {});

// True when the map of (a1, a3) is conformal outside the unit circle with the
// margin above and the half contour stays in X >= 0, Y >= 0.
bool lewis_form_is_valid(double a1, double a3, const LewisOptions& options = {});

// Contour point of the section at parameter theta in [0, pi] (0 = starboard
// waterline X = +b in solver coordinates, pi/2 = keel, pi = other waterline):
// ship-axis coordinates y [m], z [m] (z <= 0).
struct ContourPoint {
  double y_m = 0.0;
  double z_m = 0.0;
};
ContourPoint lewis_contour_point(const LewisForm& form, double theta_rad);

// Immersed area [m^2] and centroid height z [m, ship axes, <= 0] of a Lewis
// section (Green's theorem on the mapped contour, Gauss-Legendre).
struct SectionArea {
  double area_m2 = 0.0;
  double centroid_z_m = 0.0;
};
SectionArea lewis_section_area(const LewisForm& form, int quadrature_points = 64);

// EQ-LEWIS-4: Lewis (1929) closed-form infinite-frequency heave added mass
// per unit length [kg/m] = rho pi/2 M^2 ((1 + a1)^2 + 3 a3^2).
double lewis_heave_added_mass_infinite_frequency_kg_m(const LewisForm& form);

struct SectionOptions {
  int min_terms = 4;                    // wave-free multipoles in the first trial
  int max_terms = 120;                  // last trial; not converged by then -> NumericalError
  double convergence_tolerance = 2e-4;  // max |change of an impedance| / max |impedance| between trials N, ~1.4 N
  int collocation_per_unknown = 2;      // least-squares rows per unknown at max_terms (fixed point set)
  int quadrature_points = 48;           // Gauss-Legendre nodes on each half contour
  LewisOptions lewis;                   // mapping of (B, T, sigma)

  void validate() const;
};

// Sectional coefficients per unit length in ship axes (EQ-SECTION-6):
// the hydrodynamic force of one strip, per unit length, is
//   f_i = -(a_ij d^2/dt^2 + b_ij d/dt) eta_j,   i, j in {sway 2, heave 3, roll 4},
// about the waterline centre. Units: a22, a33 [kg/m], b22, b33 [kg/(m s)];
// a44 [kg m], b44 [kg m/s]; a24 = a42 [kg], b24 = b42 [kg/s].
struct SectionCoefficients {
  double omega_rad_s = 0.0;  // the (positive) frequency of the oscillation
  double a33 = 0.0, b33 = 0.0;
  double a22 = 0.0, b22 = 0.0;
  double a44 = 0.0, b44 = 0.0;
  double a24 = 0.0, b24 = 0.0;  // sway force per roll motion
  double a42 = 0.0, b42 = 0.0;  // roll moment per sway motion (equal to a24, b24 by reciprocity)
  int heave_terms = 0;          // multipoles used (convergence criterion)
  int antisymmetric_terms = 0;
};

// One node of the discretised contour (both halves), ship axes.
struct ContourNode {
  double y_m = 0.0;
  double z_m = 0.0;
  double n2_ds_m = 0.0;  // n_y ds: outward (into the fluid) normal times arc length weight [m]
  double n3_ds_m = 0.0;  // n_z ds [m]
  // Radiation potentials per unit velocity [m] of heave (w up), sway (v to
  // port) and roll (p, right hand about +x), for the time factor e^{i omega t}.
  std::complex<double> potential_heave;
  std::complex<double> potential_sway;
  std::complex<double> potential_roll;
};

struct SectionSolution {
  LewisForm form;
  SectionCoefficients coefficients;
  std::vector<ContourNode> nodes;  // 2 * quadrature_points, theta increasing
  // Complex amplitude of the radiated wave elevation far to port (ship
  // y -> +infinity, solver X -> +infinity) per unit velocity of each mode [s],
  // as the coefficient of e^{i(omega t - k y)} (EQ-SECTION-7). |.|^2 sets the radiation damping.
  std::complex<double> wave_per_velocity_heave;
  std::complex<double> wave_per_velocity_sway;
  std::complex<double> wave_per_velocity_roll;
  bool degenerate = false;  // B or T (or sigma) zero: no strip, all zero
};

// Full solution of the heave, sway and roll radiation problems at
// omega_rad_s > 0. A section with B = 0, T = 0 or sigma = 0 gives
// degenerate = true and zero coefficients.
SectionSolution solve_lewis_section(double beam_m, double draft_m, double area_coefficient,
                                    double omega_rad_s, const SectionOptions& options = {});

// The coefficients alone.
SectionCoefficients lewis_section(double beam_m, double draft_m, double area_coefficient,
                                  double omega_rad_s, const SectionOptions& options = {});

// Infinite-frequency heave added mass [kg/m] computed by the same collocation
// with the high-frequency free-surface condition phi = 0 (EQ-SECTION-8).
double lewis_heave_added_mass_high_frequency_limit_kg_m(double beam_m, double draft_m,
                                                         double area_coefficient,
                                                         const SectionOptions& options = {});

// Wave loads on one section per unit wave amplitude (EQ-SECTION-9, -10), for
// the incident wave zeta = Re{ e^{i(omega_e t - k x cos mu - k y sin mu)} }
// evaluated at the strip's x = 0 (the strip theory multiplies by e^{-i k x cos mu}).
// Index 0 = sway, 1 = heave, 2 = roll.
struct SectionWaveLoads {
  // -int p n_j ds [N/m per m of wave amplitude].
  std::array<std::complex<double>, 3> froude_krylov_n_m{};
  // D_j = rho int phi_D n_j ds [N s/m per m]: the diffraction force of the
  // strip is i omega_e D_j at zero speed (Haskind form, STF 1970).
  std::array<std::complex<double>, 3> diffraction_momentum_n_s_m{};
  // int int e^{kz - i k y sin mu} dA over the immersed section [m^2] (surge
  // Froude-Krylov force, EQ-STRIP-9).
  std::complex<double> weighted_area_m2;
  // int int z e^{kz - i k y sin mu} dA [m^3] (the z n_1 part of the pitch
  // Froude-Krylov moment, EQ-STRIP-7).
  std::complex<double> weighted_first_moment_m3;
};

// k = omega^2/g [rad/m], omega_rad_s the absolute wave frequency (> 0; a
// negative value represents the time-reversed incident wave, used only by the
// conjugation test),
// sin_heading = sin(mu), encounter_sign = sign of omega_e: for a negative
// encounter frequency the radiation potentials are conjugated (EQ-SECTION-11).
SectionWaveLoads section_wave_loads(const SectionSolution& section, double wavenumber_rad_m,
                                    double omega_rad_s, double sin_heading, int encounter_sign);

}  // namespace towdb::seakeeping

#endif  // TOWDB_SEAKEEPING_LEWIS_SECTION_HPP
