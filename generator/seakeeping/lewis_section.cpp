#include "seakeeping/lewis_section.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "seakeeping/exponential_integral.hpp"
#include "seakeeping/gauss_legendre.hpp"

namespace towdb::seakeeping {

namespace {

using Complex = std::complex<double>;
constexpr Complex kI(0.0, 1.0);

// Contour samples used to check that a Lewis half contour stays in X >= 0, Y >= 0.
constexpr int kValiditySamples = 400;
// Relative slack of that check (round-off of the map at the end points).
constexpr double kContourSlack = 1e-9;

// Solver-plane map Z(zeta) = M (zeta + a1/zeta + a3/zeta^3) (EQ-LEWIS-1).
struct Map {
  double m = 0.0;
  double a1 = 0.0;
  double a3 = 0.0;

  Complex z(Complex zeta) const {
    const Complex inv = 1.0 / zeta;
    return m * (zeta + a1 * inv + a3 * inv * inv * inv);
  }
  // dZ/dtheta on zeta = e^{i theta}: i zeta Z'(zeta).
  Complex dz_dtheta(Complex zeta) const {
    const Complex inv2 = 1.0 / (zeta * zeta);
    return kI * zeta * m * (1.0 - a1 * inv2 - 3.0 * a3 * inv2 * inv2);
  }
};

// a3 from H0 = B/(2T) and sigma (EQ-LEWIS-2): the root that is 0 for the
// semicircle. Returns false when the quadratic has no real root.
bool solve_a3(double h0, double sigma, double* a3) {
  const double c = (h0 - 1.0) / (h0 + 1.0);
  const double q = 1.0 - c * c;
  const double qa = sigma * q + 0.25 * kPi * (c * c + 3.0);
  const double qb = 2.0 * sigma * q + 0.5 * kPi * c * c;
  const double qc = (sigma - 0.25 * kPi) * q;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (!(disc >= 0.0)) return false;
  const double root = std::sqrt(disc);
  *a3 = qb >= 0.0 ? -2.0 * qc / (qb + root) : (-qb + root) / (2.0 * qa);
  return true;
}

double a1_of(double h0, double a3) { return (h0 - 1.0) * (a3 + 1.0) / (h0 + 1.0); }

}  // namespace

void LewisOptions::validate() const {
  require_in_range("LewisOptions.conformal_margin", conformal_margin, 0.0, 0.5);
  require_in_range("LewisOptions.adjust_iterations", adjust_iterations, 10, 200);
  require_in_range("LewisOptions.min_half_beam_draft_ratio", min_half_beam_draft_ratio, 1e-3, 1.0);
  require_in_range("LewisOptions.max_half_beam_draft_ratio", max_half_beam_draft_ratio, 1.0, 1e3);
}

bool lewis_form_is_valid(double a1, double a3, const LewisOptions& options) {
  if (!std::isfinite(a1) || !std::isfinite(a3) || std::abs(a1) >= 1.0 + 3.0 * a3 + 1e-12) {
    // |a1| < 1 + 3 a3 is necessary for dZ/dzeta != 0 at zeta = +-1, +-i.
    if (!(a3 == 0.0 && std::abs(a1) < 1.0)) return false;
  }
  // Zeros of dZ/dzeta in w = zeta^-2: 3 a3 w^2 + a1 w - 1 = 0 must lie outside
  // |w| <= 1 + margin (|zeta| >= 1 is |w| <= 1). The ellipse (a3 = 0, |a1| < 1)
  // is always accepted: its map is exact for any B/T.
  if (a3 != 0.0) {
    const Complex disc = std::sqrt(Complex(a1 * a1 + 12.0 * a3, 0.0));
    const Complex w1 = (-a1 + disc) / (6.0 * a3);
    const Complex w2 = (-a1 - disc) / (6.0 * a3);
    const double limit = 1.0 + options.conformal_margin;
    if (std::abs(w1) <= limit || std::abs(w2) <= limit) return false;
  } else if (std::abs(a1) >= 1.0) {
    return false;
  }
  const Map map{1.0, a1, a3};
  for (int i = 0; i <= kValiditySamples; ++i) {
    const double theta = 0.5 * kPi * static_cast<double>(i) / kValiditySamples;
    const Complex z = map.z(std::polar(1.0, theta));
    if (z.real() < -kContourSlack || z.imag() < -kContourSlack) return false;
  }
  return true;
}

LewisForm lewis_form(double beam_m, double draft_m, double area_coefficient,
                     const LewisOptions& options) {
  options.validate();
  require_positive("Lewis section beam_m", beam_m);
  require_positive("Lewis section draft_m", draft_m);
  require_input(area_coefficient > 0.0 && area_coefficient <= 1.0, "Lewis section area_coefficient",
                area_coefficient, "0 < sigma <= 1");
  // EQ-LEWIS-5: proportions outside [min, max] are mapped at the limit
  // (wider beam for a thin section, deeper draft for a flat one).
  const double h0_given = 0.5 * beam_m / draft_m;
  const double h0 = std::clamp(h0_given, options.min_half_beam_draft_ratio,
                               options.max_half_beam_draft_ratio);
  if (h0 > h0_given) beam_m = 2.0 * h0 * draft_m;
  if (h0 < h0_given) draft_m = 0.5 * beam_m / h0;
  const double ellipse_sigma = 0.25 * kPi;  // a3 = 0 for any H0 (EQ-LEWIS-2)
  auto valid_at = [&](double sigma, double* a1, double* a3) {
    if (!solve_a3(h0, sigma, a3)) return false;
    *a1 = a1_of(h0, *a3);
    return lewis_form_is_valid(*a1, *a3, options);
  };
  LewisForm form;
  form.requested_area_coefficient = area_coefficient;
  double a1 = 0.0;
  double a3 = 0.0;
  double sigma = area_coefficient;
  if (!valid_at(sigma, &a1, &a3)) {
    // Bisection between the invalid sigma and the always-valid ellipse.
    double good = ellipse_sigma;
    double bad = sigma;
    for (int i = 0; i < options.adjust_iterations; ++i) {
      const double mid = 0.5 * (good + bad);
      double t1 = 0.0;
      double t3 = 0.0;
      if (valid_at(mid, &t1, &t3)) {
        good = mid;
      } else {
        bad = mid;
      }
    }
    sigma = good;
    if (!valid_at(sigma, &a1, &a3)) {
      a3 = 0.0;
      a1 = a1_of(h0, 0.0);
      sigma = ellipse_sigma;
    }
    form.area_coefficient_adjusted = true;
  }
  form.proportions_adjusted = h0 != h0_given;
  form.a1 = a1;
  form.a3 = a3;
  form.scale_m = 0.5 * beam_m / (1.0 + a1 + a3);
  form.half_beam_m = 0.5 * beam_m;
  form.draft_m = form.scale_m * (1.0 - a1 + a3);
  form.area_coefficient = sigma;
  return form;
}

ContourPoint lewis_contour_point(const LewisForm& form, double theta_rad) {
  const Map map{form.scale_m, form.a1, form.a3};
  const Complex z = map.z(std::polar(1.0, theta_rad));
  return ContourPoint{z.real(), -z.imag()};
}

SectionArea lewis_section_area(const LewisForm& form, int quadrature_points) {
  require_input(quadrature_points >= 4, "lewis_section_area quadrature_points", quadrature_points,
                "at least 4");
  const Map map{form.scale_m, form.a1, form.a3};
  const QuadratureRule& rule = cached_gauss_legendre(quadrature_points, 0.0, kPi);
  // int int f dA = -int_0^pi F(y(theta)) dX/dtheta dtheta with F = int_{z_b}^0 f dz:
  // f = 1 gives F = -z, f = z gives F = -z^2/2 (z = -Y on the contour).
  double area = 0.0;
  double moment = 0.0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const Complex zeta = std::polar(1.0, rule.nodes[i]);
    const double z = -map.z(zeta).imag();
    const double xt = map.dz_dtheta(zeta).real();
    area += rule.weights[i] * z * xt;
    moment += rule.weights[i] * 0.5 * z * z * xt;
  }
  SectionArea out;
  out.area_m2 = area;
  out.centroid_z_m = area > 0.0 ? moment / area : 0.0;
  return out;
}

double lewis_heave_added_mass_infinite_frequency_kg_m(const LewisForm& form) {
  const double m = form.scale_m;
  return kRhoSeawater_kg_m3 * 0.5 * kPi * m * m *
         ((1.0 + form.a1) * (1.0 + form.a1) + 3.0 * form.a3 * form.a3);
}

void SectionOptions::validate() const {
  require_in_range("SectionOptions.min_terms", min_terms, 1, 200);
  require_in_range("SectionOptions.max_terms", max_terms, min_terms + 1, 200);
  require_in_range("SectionOptions.convergence_tolerance", convergence_tolerance, 1e-12, 1e-1);
  require_in_range("SectionOptions.collocation_per_unknown", collocation_per_unknown, 2, 20);
  require_in_range("SectionOptions.quadrature_points", quadrature_points, 8, 1000);
  lewis.validate();
}

namespace {

enum class Symmetry { kSymmetric, kAntisymmetric };

// Values of one basis function at one contour point: phi and psi are the
// real potential and stream function; the wave-source column combines two
// real functions with complex weights (phi_c - i phi_s), so both are complex.
struct BasisValue {
  Complex phi;
  Complex psi;
};

// Basis at zeta = e^{i theta} for wavenumber K (EQ-SECTION-2..4). Column 0 is
// the radiating wave source (symmetric) or dipole (antisymmetric), columns
// 1..n the wave-free multipoles of Tasai.
void evaluate_basis(const Map& map, double wavenumber, Symmetry symmetry, double theta,
                    int terms, std::vector<BasisValue>* out) {
  out->assign(static_cast<std::size_t>(terms + 1), BasisValue{});
  const Complex zeta = std::polar(1.0, theta);
  Complex z = map.z(zeta);
  // Right half only: X >= +0 keeps iKZ on the upper side of the E1 cut.
  if (!(z.real() > 0.0)) z = Complex(0.0, z.imag());
  const Complex w = kI * wavenumber * z;
  const Complex e = std::exp(w);
  const Complex g = scaled_exponential_integral(w);  // e^{iKZ} E1(iKZ)
  Complex fc;
  Complex fs;
  if (symmetry == Symmetry::kSymmetric) {
    fc = kPi * e;                // Re: pi e^{-KY} cos KX
    fs = -(g + kI * kPi * e);    // Re: pi e^{-KY} sin K|X| + O(1/r)
  } else {
    fc = kI * kPi * e;                                  // Re: -pi e^{-KY} sin KX
    fs = -kI * g + 1.0 / (wavenumber * z) + kPi * e;    // d/dZ of the symmetric fs, over K
  }
  (*out)[0].phi = Complex(fc.real(), 0.0) - kI * fs.real();
  (*out)[0].psi = Complex(fc.imag(), 0.0) - kI * fs.imag();
  const double km = wavenumber * map.m;
  // zeta^-n on the unit circle, n = 0 .. 2 terms + 4, by recurrence.
  const int max_power = 2 * terms + 5;
  // Scratch kept per thread: this runs at every collocation point of every
  // section, frequency and trial, and a fresh allocation each call showed in
  // profiles.
  thread_local std::vector<Complex> powers;
  powers.resize(static_cast<std::size_t>(max_power + 1));
  powers[0] = Complex(1.0, 0.0);
  const Complex inv_zeta = std::conj(zeta);
  for (int p = 1; p <= max_power; ++p) {
    powers[static_cast<std::size_t>(p)] = powers[static_cast<std::size_t>(p - 1)] * inv_zeta;
  }
  auto inv_pow = [](int n) { return powers[static_cast<std::size_t>(n)]; };
  for (int m = 1; m <= terms; ++m) {
    const int n = symmetry == Symmetry::kSymmetric ? 2 * m : 2 * m + 1;
    const double dn = static_cast<double>(n);
    const Complex wf =
        inv_pow(n) - kI * km *
                         (inv_pow(n - 1) / (dn - 1.0) - map.a1 * inv_pow(n + 1) / (dn + 1.0) -
                          3.0 * map.a3 * inv_pow(n + 3) / (dn + 3.0));
    (*out)[static_cast<std::size_t>(m)].phi = Complex(wf.real(), 0.0);
    (*out)[static_cast<std::size_t>(m)].psi = Complex(wf.imag(), 0.0);
  }
}

// Trial numbers of multipoles: min_terms, then growing by a factor
// kTermGrowth (at least +1) up to max_terms. Comparing trials a factor apart
// (not N and N+1) keeps the change an honest error estimate when the
// coefficients decay algebraically (waterline corner of the flow).
constexpr double kTermGrowth = 1.4;
// Fewest least-squares rows of a trial (keeps small trials overdetermined).
constexpr int kMinCollocationRows = 16;
std::vector<int> trial_terms(const SectionOptions& options) {
  std::vector<int> out;
  int n = options.min_terms;
  while (n < options.max_terms) {
    out.push_back(n);
    n = std::max(n + 1, static_cast<int>(std::ceil(kTermGrowth * n)));
  }
  out.push_back(options.max_terms);
  return out;
}

// Geometry of the half contour at the quadrature nodes and the collocation points.
struct HalfContour {
  std::vector<double> theta;
  std::vector<double> weight;
  std::vector<Complex> z;       // solver plane X + iY
  std::vector<Complex> dz;      // dZ/dtheta
};

HalfContour make_quadrature(const Map& map, int points) {
  const QuadratureRule& rule = cached_gauss_legendre(points, 0.0, 0.5 * kPi);
  HalfContour h;
  h.theta = rule.nodes;
  h.weight = rule.weights;
  for (double t : h.theta) {
    const Complex zeta = std::polar(1.0, t);
    h.z.push_back(map.z(zeta));
    h.dz.push_back(map.dz_dtheta(zeta));
  }
  return h;
}

// Solution of one symmetry class: coefficients per mode, potentials at the
// quadrature nodes per mode.
struct ClassSolution {
  int terms = 0;
  std::vector<Eigen::VectorXcd> coefficients;    // per mode
  std::vector<std::vector<Complex>> potentials;  // per mode, per quadrature node
};

using BodyStream = double (*)(Complex z, double draft);
// Body stream functions minus their keel values (EQ-SECTION-5), unit velocity.
double stream_heave(Complex z, double) { return -z.real(); }                 // V = 1 along +Y
double stream_sway(Complex z, double draft) { return z.imag() - draft; }      // U = 1 along +X
double stream_roll(Complex z, double draft) {                                 // Omega = 1, X -> Y
  return -0.5 * (std::norm(z) - draft * draft);
}

// Impedances F_i / V_j = -b_ij - i omega a_ij in solver coordinates
// (EQ-SECTION-6): generalised forces (X force, Y force, moment X F_Y - Y F_X).
Complex solver_force(const HalfContour& q, const std::vector<Complex>& phi, Symmetry symmetry,
                     int component, double omega) {
  // Sum over both halves: the mirror node of (X, Y, X', Y') is (-X, Y, X', -Y')
  // and carries +phi (symmetric) or -phi (antisymmetric).
  const double parity = symmetry == Symmetry::kSymmetric ? 1.0 : -1.0;
  Complex sum(0.0, 0.0);
  for (std::size_t i = 0; i < phi.size(); ++i) {
    const double x = q.z[i].real();
    const double y = q.z[i].imag();
    const double xt = q.dz[i].real();
    const double yt = q.dz[i].imag();
    double right = 0.0;
    double mirror = 0.0;
    switch (component) {
      case 0:  // n_X ds = Y' dtheta
        right = yt;
        mirror = -yt;
        break;
      case 1:  // n_Y ds = -X' dtheta
        right = -xt;
        mirror = -xt;
        break;
      default:  // (X n_Y - Y n_X) ds = (-X X' - Y Y') dtheta
        right = -x * xt - y * yt;
        mirror = -(-x) * xt - y * (-yt);
        break;
    }
    sum += q.weight[i] * phi[i] * (right + parity * mirror);
  }
  return kI * omega * kRhoSeawater_kg_m3 * sum;
}

ClassSolution solve_class(const Map& map, double wavenumber, double omega, Symmetry symmetry,
                          const std::vector<BodyStream>& modes, const HalfContour& quad,
                          const SectionOptions& options, double draft) {
  const std::size_t mode_count = modes.size();
  std::vector<Complex> previous;
  double last_change = 0.0;
  for (int terms : trial_terms(options)) {
    const Eigen::Index cols = terms + 1;
    // Collocation points theta_j = (pi/2) j / rows, j = 0..rows-1 (waterline
    // included, keel excluded: the keel is the stream-function reference).
    const int rows = std::max(options.collocation_per_unknown * (terms + 1), kMinCollocationRows);
    std::vector<std::vector<BasisValue>> colloc(static_cast<std::size_t>(rows));
    Eigen::MatrixXcd rhs(rows, static_cast<Eigen::Index>(mode_count));
    for (int j = 0; j < rows; ++j) {
      const double theta = 0.5 * kPi * static_cast<double>(j) / rows;
      evaluate_basis(map, wavenumber, symmetry, theta, terms, &colloc[static_cast<std::size_t>(j)]);
      const Complex zc = map.z(std::polar(1.0, theta));
      for (std::size_t k = 0; k < mode_count; ++k) {
        rhs(j, static_cast<Eigen::Index>(k)) = modes[k](zc, draft);
      }
    }
    std::vector<BasisValue> keel;
    evaluate_basis(map, wavenumber, symmetry, 0.5 * kPi, terms, &keel);
    std::vector<std::vector<BasisValue>> at_nodes(quad.theta.size());
    for (std::size_t i = 0; i < quad.theta.size(); ++i) {
      evaluate_basis(map, wavenumber, symmetry, quad.theta[i], terms, &at_nodes[i]);
    }
    Eigen::MatrixXcd a(rows, cols);
    for (int j = 0; j < rows; ++j) {
      for (Eigen::Index c = 0; c < cols; ++c) {
        a(j, c) = colloc[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)].psi -
                  keel[static_cast<std::size_t>(c)].psi;
      }
    }
    // Column scaling keeps the least-squares problem well conditioned when
    // K M is large or small.
    Eigen::VectorXd scale(cols);
    for (Eigen::Index c = 0; c < cols; ++c) {
      const double norm = a.col(c).norm();
      scale(c) = norm > 0.0 ? 1.0 / norm : 1.0;
      a.col(c) *= scale(c);
    }
    const Eigen::MatrixXcd solution = a.colPivHouseholderQr().solve(rhs);
    ClassSolution current;
    current.terms = terms;
    std::vector<Complex> impedances;
    for (std::size_t k = 0; k < mode_count; ++k) {
      Eigen::VectorXcd coef = solution.col(static_cast<Eigen::Index>(k)).cwiseProduct(scale.cast<Complex>());
      std::vector<Complex> phi(quad.theta.size());
      for (std::size_t i = 0; i < quad.theta.size(); ++i) {
        Complex value(0.0, 0.0);
        for (Eigen::Index c = 0; c < cols; ++c) {
          value += coef(c) * at_nodes[i][static_cast<std::size_t>(c)].phi;
        }
        phi[i] = value;
      }
      current.coefficients.push_back(coef);
      current.potentials.push_back(phi);
    }
    // Convergence measure: every generalised impedance of the class.
    if (symmetry == Symmetry::kSymmetric) {
      impedances.push_back(solver_force(quad, current.potentials[0], symmetry, 1, omega));
    } else {
      for (std::size_t k = 0; k < mode_count; ++k) {
        impedances.push_back(solver_force(quad, current.potentials[k], symmetry, 0, omega));
        impedances.push_back(solver_force(quad, current.potentials[k], symmetry, 2, omega));
      }
    }
    if (!previous.empty()) {
      double scale_ref = 0.0;
      for (const Complex& z : impedances) scale_ref = std::max(scale_ref, std::abs(z));
      double change = 0.0;
      for (std::size_t i = 0; i < impedances.size(); ++i) {
        change = std::max(change, std::abs(impedances[i] - previous[i]) / scale_ref);
      }
      last_change = change;
      if (change <= options.convergence_tolerance) return current;
    }
    previous = impedances;
  }
  throw NumericalError("Ursell-Tasai multipole solver (" +
                       std::string(symmetry == Symmetry::kSymmetric ? "heave" : "sway/roll") +
                       "): iteration " + std::to_string(options.max_terms) + " terms, residual change " +
                       format_value(last_change) + " above tolerance " +
                       format_value(options.convergence_tolerance) + " (K M = " +
                       format_value(wavenumber * map.m) + ", a1 = " + format_value(map.a1) +
                       ", a3 = " + format_value(map.a3) + ")");
}

}  // namespace

SectionSolution solve_lewis_section(double beam_m, double draft_m, double area_coefficient,
                                    double omega_rad_s, const SectionOptions& options) {
  options.validate();
  require_positive("section omega_rad_s", omega_rad_s);
  require_input(beam_m >= 0.0 && std::isfinite(beam_m), "section beam_m", beam_m, "finite and >= 0");
  require_input(draft_m >= 0.0 && std::isfinite(draft_m), "section draft_m", draft_m, "finite and >= 0");
  require_input(area_coefficient >= 0.0 && area_coefficient <= 1.0, "section area_coefficient",
                area_coefficient, "0 <= sigma <= 1");
  SectionSolution out;
  out.coefficients.omega_rad_s = omega_rad_s;
  if (beam_m == 0.0 || draft_m == 0.0 || area_coefficient == 0.0) {
    out.degenerate = true;
    return out;
  }
  out.form = lewis_form(beam_m, draft_m, area_coefficient, options.lewis);
  const Map map{out.form.scale_m, out.form.a1, out.form.a3};
  const double k = omega_rad_s * omega_rad_s / kGravity_m_s2;
  const HalfContour quad = make_quadrature(map, options.quadrature_points);
  const double draft = out.form.draft_m;

  const ClassSolution sym = solve_class(map, k, omega_rad_s, Symmetry::kSymmetric, {&stream_heave},
                                        quad, options, draft);
  const ClassSolution anti = solve_class(map, k, omega_rad_s, Symmetry::kAntisymmetric,
                                         {&stream_sway, &stream_roll}, quad, options, draft);

  const double w = omega_rad_s;
  auto a_of = [w](Complex f) { return -f.imag() / w; };
  auto b_of = [](Complex f) { return -f.real(); };
  const Complex f_vv = solver_force(quad, sym.potentials[0], Symmetry::kSymmetric, 1, w);
  const Complex f_uu = solver_force(quad, anti.potentials[0], Symmetry::kAntisymmetric, 0, w);
  const Complex f_mu = solver_force(quad, anti.potentials[0], Symmetry::kAntisymmetric, 2, w);
  const Complex f_uo = solver_force(quad, anti.potentials[1], Symmetry::kAntisymmetric, 0, w);
  const Complex f_oo = solver_force(quad, anti.potentials[1], Symmetry::kAntisymmetric, 2, w);

  // Ship axes (EQ-SECTION-6): heave w = -V and roll p = -Omega flip signs; the
  // diagonal terms are unchanged, the sway-roll couplings change sign.
  SectionCoefficients& c = out.coefficients;
  c.a33 = a_of(f_vv);
  c.b33 = b_of(f_vv);
  c.a22 = a_of(f_uu);
  c.b22 = b_of(f_uu);
  c.a44 = a_of(f_oo);
  c.b44 = b_of(f_oo);
  c.a24 = -a_of(f_uo);
  c.b24 = -b_of(f_uo);
  c.a42 = -a_of(f_mu);
  c.b42 = -b_of(f_mu);
  c.heave_terms = sym.terms;
  c.antisymmetric_terms = anti.terms;

  // Far-field wave per unit velocity (EQ-SECTION-7).
  const double og = omega_rad_s / kGravity_m_s2;
  out.wave_per_velocity_heave = -(-kI * og * kPi * sym.coefficients[0](0));
  out.wave_per_velocity_sway = -og * kPi * anti.coefficients[0](0);
  out.wave_per_velocity_roll = -(-og * kPi * anti.coefficients[1](0));

  // Contour nodes, both halves, theta increasing, ship axes.
  const std::size_t nq = quad.theta.size();
  out.nodes.resize(2 * nq);
  for (std::size_t i = 0; i < nq; ++i) {
    const double x = quad.z[i].real();
    const double y = quad.z[i].imag();
    const double xt = quad.dz[i].real();
    const double yt = quad.dz[i].imag();
    const double wq = quad.weight[i];
    ContourNode right;
    right.y_m = x;
    right.z_m = -y;
    right.n2_ds_m = yt * wq;
    right.n3_ds_m = xt * wq;
    right.potential_heave = -sym.potentials[0][i];
    right.potential_sway = anti.potentials[0][i];
    right.potential_roll = -anti.potentials[1][i];
    ContourNode mirror;
    mirror.y_m = -x;
    mirror.z_m = -y;
    mirror.n2_ds_m = -yt * wq;
    mirror.n3_ds_m = xt * wq;
    mirror.potential_heave = right.potential_heave;
    mirror.potential_sway = -right.potential_sway;
    mirror.potential_roll = -right.potential_roll;
    out.nodes[i] = right;
    out.nodes[2 * nq - 1 - i] = mirror;
  }
  return out;
}

SectionCoefficients lewis_section(double beam_m, double draft_m, double area_coefficient,
                                  double omega_rad_s, const SectionOptions& options) {
  return solve_lewis_section(beam_m, draft_m, area_coefficient, omega_rad_s, options).coefficients;
}

double lewis_heave_added_mass_high_frequency_limit_kg_m(double beam_m, double draft_m,
                                                         double area_coefficient,
                                                         const SectionOptions& options) {
  options.validate();
  const LewisForm form = lewis_form(beam_m, draft_m, area_coefficient, options.lewis);
  const Map map{form.scale_m, form.a1, form.a3};
  const HalfContour quad = make_quadrature(map, options.quadrature_points);
  const int max_terms = options.max_terms;
  const int rows = options.collocation_per_unknown * max_terms;
  // K -> infinity: phi = 0 on the free surface; the basis is the K-multiplied
  // part of Tasai's multipoles, f_m = -i L_m(zeta) (EQ-SECTION-8), real weights.
  auto basis = [&](double theta, int m, double* phi, double* psi) {
    auto inv_pow = [theta](int n) { return std::polar(1.0, -static_cast<double>(n) * theta); };
    const int n = 2 * m;
    const double dn = static_cast<double>(n);
    const Complex l = inv_pow(n - 1) / (dn - 1.0) - form.a1 * inv_pow(n + 1) / (dn + 1.0) -
                      3.0 * form.a3 * inv_pow(n + 3) / (dn + 3.0);
    const Complex f = -kI * l;
    *phi = f.real();
    *psi = f.imag();
  };
  double previous = 0.0;
  double change = 0.0;
  bool first = true;
  for (int terms : trial_terms(options)) {
    Eigen::MatrixXd a(rows, terms);
    Eigen::VectorXd rhs(rows);
    for (int j = 0; j < rows; ++j) {
      const double theta = 0.5 * kPi * static_cast<double>(j) / rows;
      rhs(j) = stream_heave(map.z(std::polar(1.0, theta)), form.draft_m);
      for (int m = 1; m <= terms; ++m) {
        double phi = 0.0;
        double psi = 0.0;
        double phik = 0.0;
        double psik = 0.0;
        basis(theta, m, &phi, &psi);
        basis(0.5 * kPi, m, &phik, &psik);
        a(j, m - 1) = psi - psik;
      }
    }
    const Eigen::VectorXd coef = a.colPivHouseholderQr().solve(rhs);
    // a33 = -rho int phi n_Y ds over both halves (phi real, symmetric).
    double sum = 0.0;
    for (std::size_t i = 0; i < quad.theta.size(); ++i) {
      double phi = 0.0;
      for (int m = 1; m <= terms; ++m) {
        double p = 0.0;
        double s = 0.0;
        basis(quad.theta[i], m, &p, &s);
        phi += coef(m - 1) * p;
      }
      sum += quad.weight[i] * phi * (-quad.dz[i].real());
    }
    const double added_mass = -kRhoSeawater_kg_m3 * 2.0 * sum;
    if (!first) {
      change = std::abs(added_mass - previous) / std::abs(added_mass);
      if (change <= options.convergence_tolerance) return added_mass;
    }
    first = false;
    previous = added_mass;
  }
  throw NumericalError("infinite-frequency multipole solver: iteration " + std::to_string(max_terms) +
                       " terms, residual change " + format_value(change));
}

SectionWaveLoads section_wave_loads(const SectionSolution& section, double wavenumber_rad_m,
                                    double omega_rad_s, double sin_heading, int encounter_sign) {
  SectionWaveLoads out;
  if (section.degenerate) return out;
  const double k = wavenumber_rad_m;
  const double rho = kRhoSeawater_kg_m3;
  for (const ContourNode& node : section.nodes) {
    // Incident wave at the node, unit amplitude, x = 0: e^{kz - i k y sin mu}.
    const Complex e = std::exp(Complex(k * node.z_m, -k * node.y_m * sin_heading));
    const double n4_ds = node.y_m * node.n3_ds_m - node.z_m * node.n2_ds_m;
    // Froude-Krylov: -int p n ds with p = rho g e (EQ-SECTION-9).
    const Complex p = rho * kGravity_m_s2 * e;
    out.froude_krylov_n_m[0] -= p * node.n2_ds_m;
    out.froude_krylov_n_m[1] -= p * node.n3_ds_m;
    out.froude_krylov_n_m[2] -= p * n4_ds;
    // Haskind: D_j = -rho int psi_j dphi0/dn ds, dphi0/dn = k phi0 (n3 - i sin mu n2),
    // phi0 = (i g / omega) e, so D_j = -i rho omega int psi_j e (n3 - i sin mu n2) ds
    // (EQ-SECTION-10); conjugate potentials for omega_e < 0 (EQ-SECTION-11).
    const Complex dn = e * Complex(node.n3_ds_m, -sin_heading * node.n2_ds_m);
    auto pot = [encounter_sign](Complex v) { return encounter_sign < 0 ? std::conj(v) : v; };
    const Complex factor = -kI * rho * omega_rad_s;
    out.diffraction_momentum_n_s_m[0] += factor * pot(node.potential_sway) * dn;
    out.diffraction_momentum_n_s_m[1] += factor * pot(node.potential_heave) * dn;
    out.diffraction_momentum_n_s_m[2] += factor * pot(node.potential_roll) * dn;
    // Weighted area by Green's theorem: int int f dA = -sum (1 - e^{kz})/k g(y) dY/dtheta ...
    // in ship axes dY_solver/dtheta ds-weight is n3 ds (EQ-STRIP-9).
    const double depth_factor = k > 0.0 ? -std::expm1(k * node.z_m) / k : -node.z_m;
    const Complex lateral = std::exp(Complex(0.0, -k * node.y_m * sin_heading));
    out.weighted_area_m2 += -depth_factor * lateral * node.n3_ds_m;
    // F = int_{z_b}^0 z e^{kz} dz = -1/k^2 - e^{k z_b} (z_b/k - 1/k^2)
    //   = -(z_b^2/2) (1 + 2 k z_b/3 + ...) for small k z_b.
    const double zb = node.z_m;
    const double kz = k * zb;
    const double moment_factor =
        std::abs(kz) < 1e-3 ? -0.5 * zb * zb * (1.0 + 2.0 * kz / 3.0 + kz * kz / 4.0)
                            : (-1.0 - std::exp(kz) * (kz - 1.0)) / (k * k);
    out.weighted_first_moment_m3 += -moment_factor * lateral * node.n3_ds_m;
  }
  return out;
}

}  // namespace towdb::seakeeping
