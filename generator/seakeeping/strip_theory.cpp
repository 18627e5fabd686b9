// Strip theory: assembly of the sections into the 6-DOF ship equations
// (EQ-STRIP-1..10) and the Gerritsma-Beukelman added resistance (EQ-AR-1).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include <Eigen/Dense>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "seakeeping/seakeeping.hpp"

namespace towdb::seakeeping {

namespace {

using Complex = std::complex<double>;
constexpr Complex kI(0.0, 1.0);

// Section modes inside a strip.
enum SectionMode : int { kSecSway = 0, kSecHeave = 1, kSecRoll = 2 };

// The five strip-theory ship modes: DOF, section mode, shape c(x) = c0 + c1 x.
struct StripMode {
  int dof;
  int section_mode;
  double c0;
  double c1;
};
constexpr std::array<StripMode, 5> kStripModes{{
    {kSway, kSecSway, 1.0, 0.0},
    {kHeave, kSecHeave, 1.0, 0.0},
    {kRoll, kSecRoll, 1.0, 0.0},
    {kPitch, kSecHeave, 0.0, -1.0},
    {kYaw, kSecSway, 0.0, 1.0},
}};

void check_hull(const model::Hull& h) {
  require_positive("hull length_pp_m", h.length_pp_m);
  require_positive("hull beam_m", h.beam_m);
  require_positive("hull draft_m", h.draft_m);
  require_positive("hull displacement_kg", h.displacement_kg);
  require_positive("hull kg_m", h.kg_m);
  require_positive("hull gm_m", h.gm_m);
  require_positive("hull radius_gyration_roll_m", h.radius_gyration_roll_m);
  require_positive("hull radius_gyration_pitch_m", h.radius_gyration_pitch_m);
  require_positive("hull radius_gyration_yaw_m", h.radius_gyration_yaw_m);
  require_in_range("hull roll_damping_ratio", h.roll_damping_ratio, 0.0, 1.0);
  require_in_range("hull surge_added_mass_ratio", h.surge_added_mass_ratio, 0.0, 1.0);
  if (h.stations.size() < 3) {
    throw InputError("hull stations: " + std::to_string(h.stations.size()) +
                     " given, strip theory needs at least 3");
  }
  for (std::size_t i = 0; i < h.stations.size(); ++i) {
    const model::Station& s = h.stations[i];
    const std::string f = "hull station " + std::to_string(i);
    if (i > 0) {
      require_input(s.x_m > h.stations[i - 1].x_m, f + " x_m", s.x_m,
                    "stations ordered aft to forward with increasing x");
    }
    require_input(s.beam_m >= 0.0 && std::isfinite(s.beam_m), f + " beam_m", s.beam_m, ">= 0");
    require_input(s.draft_m >= 0.0 && std::isfinite(s.draft_m), f + " draft_m", s.draft_m, ">= 0");
    require_input(s.area_coefficient >= 0.0 && s.area_coefficient <= 1.0, f + " area_coefficient",
                  s.area_coefficient, "0 <= sigma <= 1");
  }
}

bool has_section(const model::Station& s) {
  return s.beam_m > 0.0 && s.draft_m > 0.0 && s.area_coefficient > 0.0;
}

// Trapezoid weights over the station positions.
std::vector<double> trapezoid_weights(const std::vector<model::Station>& stations) {
  const std::size_t n = stations.size();
  std::vector<double> w(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double dx = stations[i + 1].x_m - stations[i].x_m;
    w[i] += 0.5 * dx;
    w[i + 1] += 0.5 * dx;
  }
  return w;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& r) {
  Eigen::Matrix3d s;
  s << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return s;
}

// Per station: the 3x3 sectional impedance Z = a + b/(i w) in (sway, heave,
// roll) and the wave loads.
struct StripData {
  Eigen::Matrix3cd impedance = Eigen::Matrix3cd::Zero();
  double a33 = 0.0;
  double b33 = 0.0;
  SectionWaveLoads loads;
  double mean_draft_m = 0.0;  // A / B for the Smith correction (EQ-AR-1)
};

// Sections (EQ-SECTION-*), at |w_h|; a, b are real so the impedance with the
// signed w is the correct one for w_e < 0 (EQ-SECTION-11).
std::vector<StripData> section_strips(const std::vector<model::Station>& st, double w_abs, double w, double k,
                                      double omega, double sin_mu, int sign, const ResponseOptions& options) {
  const std::size_t n = st.size();
  std::vector<StripData> strips(n);
  for (std::size_t i = 0; i < n; ++i) {
    const model::Station& s = st[i];
    if (!has_section(s)) continue;
    const SectionSolution sol =
        solve_lewis_section(s.beam_m, s.draft_m, s.area_coefficient, w_abs, options.section);
    const SectionCoefficients& c = sol.coefficients;
    Eigen::Matrix3d a;
    Eigen::Matrix3d b;
    a << c.a22, 0.0, c.a24, 0.0, c.a33, 0.0, c.a42, 0.0, c.a44;
    b << c.b22, 0.0, c.b24, 0.0, c.b33, 0.0, c.b42, 0.0, c.b44;
    strips[i].impedance = a.cast<Complex>() + b.cast<Complex>() / (kI * w);
    strips[i].a33 = c.a33;
    strips[i].b33 = c.b33;
    strips[i].loads = section_wave_loads(sol, k, omega, sin_mu, sign);
    strips[i].mean_draft_m = s.area_coefficient * s.draft_m;
  }
  return strips;
}

// What the strip integrals of one wave frequency share.
struct StripFrame {
  const std::vector<model::Station>& st;
  const std::vector<double>& wx;        // trapezoid weights over the stations
  const std::vector<StripData>& strips;
  double omega;     // wave frequency [rad/s]
  double w;         // hydrodynamic (floored, signed) encounter frequency [rad/s]
  double k;         // wavenumber [rad/m]
  double cos_mu;
  double u;         // speed [m/s]
  bool transom;     // transom terms at the aft station
  double x_aft;     // x of the aft station [m]
  double surge_diffraction_ratio;  // A11 / (rho V) with ResponseOptions::surge_diffraction, else 0
};

// Radiation: K_ij = int (i w c_i + U c_i') Z (i w c_j - U c_j') dx
//                 + U c_i(x_A) Z_A (i w c_j(x_A) - U c_j')   (EQ-STRIP-2, -3),
// stored as added mass -Re K / w^2 and damping Im K / w.
void add_radiation(const StripFrame& f, VesselResponse& r) {
  const std::size_t n = f.st.size();
  const std::size_t aft = 0;
  const double w = f.w, u = f.u;
  Eigen::Matrix<Complex, 6, 6> kmat = Eigen::Matrix<Complex, 6, 6>::Zero();
  for (const StripMode& mi : kStripModes) {
    for (const StripMode& mj : kStripModes) {
      Complex sum(0.0, 0.0);
      for (std::size_t s = 0; s < n; ++s) {
        const double x = f.st[s].x_m;
        const Complex z = f.strips[s].impedance(mi.section_mode, mj.section_mode);
        if (z == Complex(0.0, 0.0)) continue;
        const Complex left = kI * w * (mi.c0 + mi.c1 * x) + u * mi.c1;
        const Complex right = kI * w * (mj.c0 + mj.c1 * x) - u * mj.c1;
        sum += f.wx[s] * left * z * right;
      }
      if (f.transom) {
        const Complex z = f.strips[aft].impedance(mi.section_mode, mj.section_mode);
        const Complex right = kI * w * (mj.c0 + mj.c1 * f.x_aft) - u * mj.c1;
        sum += u * (mi.c0 + mi.c1 * f.x_aft) * z * right;
      }
      kmat(mi.dof, mj.dof) = sum;
    }
  }
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      r.added_mass(i, j) = -kmat(i, j).real() / (w * w);
      r.damping(i, j) = kmat(i, j).imag() / w;
    }
  }
}

// Exciting forces per wave amplitude, Froude-Krylov and diffraction
// (EQ-STRIP-4, EQ-STRIP-7).
void add_exciting_forces(const StripFrame& f, VesselResponse& r) {
  const std::size_t n = f.st.size();
  const std::size_t aft = 0;
  const double w = f.w, u = f.u, k = f.k, cos_mu = f.cos_mu;
  const double rho_g = kRhoSeawater_kg_m3 * kGravity_m_s2;
  for (const StripMode& mi : kStripModes) {
    Complex fk(0.0, 0.0);
    Complex dif(0.0, 0.0);
    for (std::size_t s = 0; s < n; ++s) {
      const double x = f.st[s].x_m;
      const Complex phase = std::exp(Complex(0.0, -k * x * cos_mu));
      const double c = mi.c0 + mi.c1 * x;
      fk += f.wx[s] * c * f.strips[s].loads.froude_krylov_n_m[static_cast<std::size_t>(mi.section_mode)] * phase;
      dif += f.wx[s] * (kI * w * c + u * mi.c1) *
             f.strips[s].loads.diffraction_momentum_n_s_m[static_cast<std::size_t>(mi.section_mode)] * phase;
    }
    if (f.transom) {
      const Complex phase = std::exp(Complex(0.0, -k * f.x_aft * cos_mu));
      dif += u * (mi.c0 + mi.c1 * f.x_aft) *
             f.strips[aft].loads.diffraction_momentum_n_s_m[static_cast<std::size_t>(mi.section_mode)] * phase;
    }
    r.froude_krylov_per_m(mi.dof) = fk;
    r.diffraction_per_m(mi.dof) = dif;
  }
  Complex volume(0.0, 0.0);
  for (std::size_t s = 0; s < n; ++s) {
    volume += f.wx[s] * f.strips[s].loads.weighted_area_m2 * std::exp(Complex(0.0, -k * f.st[s].x_m * cos_mu));
  }
  r.froude_krylov_per_m(kSurge) = kI * k * cos_mu * rho_g * volume;
  // Its diffraction part (EQ-STRIP-7, optional): the added mass driven at the
  // rate the hull meets the water, i w_h u, against Froude-Krylov's i w u.
  if (f.surge_diffraction_ratio > 0.0) {
    r.diffraction_per_m(kSurge) = f.surge_diffraction_ratio * (w / f.omega) * r.froude_krylov_per_m(kSurge);
  }
  // The z n_1 part of n_5 (Gauss: -int p z n_1 dS = i k cos mu int z p dV):
  // it makes the long-wave pitch equal the wave slope (EQ-STRIP-7).
  Complex moment(0.0, 0.0);
  for (std::size_t s = 0; s < n; ++s) {
    moment += f.wx[s] * f.strips[s].loads.weighted_first_moment_m3 * std::exp(Complex(0.0, -k * f.st[s].x_m * cos_mu));
  }
  r.froude_krylov_per_m(kPitch) += kI * k * cos_mu * rho_g * moment;
  r.exciting_force_per_m = r.froude_krylov_per_m + r.diffraction_per_m;
}

// Motions (EQ-STRIP-9): the RAOs of the 6x6 system at the hydrodynamic frequency w.
void solve_motions(double w, VesselResponse& r) {
  const Eigen::Matrix<Complex, 6, 6> system =
      (-w * w * (r.mass + r.added_mass) + r.restoring).cast<Complex>() + kI * w * r.damping.cast<Complex>();
  Eigen::FullPivLU<Eigen::Matrix<Complex, 6, 6>> lu(system);
  if (!lu.isInvertible()) {
    throw NumericalError("strip theory motion equations: iteration 1, singular 6x6 system at w_e = " +
                         format_value(w) + " rad/s (residual rank " + std::to_string(lu.rank()) + ")");
  }
  r.rao = lu.solve(r.exciting_force_per_m);
  if (!r.rao.allFinite()) {
    throw NumericalError("strip theory motion equations: iteration 1, non-finite RAO at w_e = " +
                         format_value(w) + " rad/s");
  }
}

// Added resistance per wave amplitude squared (EQ-AR-1): b'33 = b33 - U da33/dx
// by central differences.
double added_resistance_n_per_m2(const StripFrame& f, const VesselResponse& r) {
  const std::size_t n = f.st.size();
  const double w = f.w, u = f.u, k = f.k, cos_mu = f.cos_mu;
  double integral = 0.0;
  const Complex heave = r.rao(kHeave);
  const Complex pitch = r.rao(kPitch);
  for (std::size_t s = 0; s < n; ++s) {
    if (!has_section(f.st[s])) continue;
    const std::size_t lo = s == 0 ? 0 : s - 1;
    const std::size_t hi = s + 1 == n ? s : s + 1;
    const double da_dx = (f.strips[hi].a33 - f.strips[lo].a33) / (f.st[hi].x_m - f.st[lo].x_m);
    const double b_eff = f.strips[s].b33 - u * da_dx;
    const double x = f.st[s].x_m;
    const Complex wave = std::exp(Complex(-k * f.strips[s].mean_draft_m, -k * x * cos_mu));
    const Complex vz = kI * w * (heave - x * pitch) + u * pitch - kI * f.omega * wave;
    integral += f.wx[s] * b_eff * std::norm(vz);
  }
  return -k * cos_mu / (2.0 * w) * integral;
}

VesselResponse respond(const model::Vessel& vessel, double speed, double heading, double omega,
                       const ResponseOptions& options, const Matrix6d& mass,
                       const Matrix6d& restoring) {
  const model::Hull& hull = vessel.hull;
  const auto& st = hull.stations;
  const std::vector<double> wx = trapezoid_weights(st);

  VesselResponse r;
  r.omega_rad_s = omega;
  r.wavenumber_rad_m = omega * omega / kGravity_m_s2;
  r.heading_rad = heading;
  r.speed_m_s = speed;
  const double k = r.wavenumber_rad_m;
  const double cos_mu = std::cos(heading);
  const double sin_mu = std::sin(heading);
  r.omega_e_rad_s = omega - k * speed * cos_mu;
  const double floor_rad_s =
      options.min_encounter_frequency_nondim * std::sqrt(kGravity_m_s2 / hull.length_pp_m);
  const int sign = r.omega_e_rad_s < 0.0 ? -1 : 1;
  const double w_abs = std::max(std::abs(r.omega_e_rad_s), floor_rad_s);
  const double w = sign * w_abs;  // EQ-STRIP-10
  r.omega_hydro_rad_s = w;
  r.mass = mass;
  r.restoring = restoring;

  const std::vector<StripData> strips = section_strips(st, w_abs, w, k, omega, sin_mu, sign, options);
  const StripFrame frame{st,     wx,  strips,
                         omega,  w,   k,
                         cos_mu, speed, options.transom_terms && has_section(st[0]),
                         st[0].x_m,
                         // A11 / (rho V): the displacement mass is rho V.
                         options.surge_diffraction ? hull.surge_added_mass_ratio : 0.0};

  add_radiation(frame, r);
  // Surge (EQ-STRIP-7).
  r.added_mass(kSurge, kSurge) = hull.surge_added_mass_ratio * hull.displacement_kg;
  add_exciting_forces(frame, r);

  // Roll viscous damping (EQ-STRIP-8).
  const double c44 = restoring(kRoll, kRoll);
  const double i44 = mass(kRoll, kRoll) + r.added_mass(kRoll, kRoll);
  if (c44 > 0.0 && i44 > 0.0) {
    r.damping(kRoll, kRoll) += 2.0 * hull.roll_damping_ratio * std::sqrt(i44 * c44);
  }

  solve_motions(w, r);
  r.added_resistance_n_per_m2 = added_resistance_n_per_m2(frame, r);
  if (cos_mu > 0.0 && !options.added_resistance_aft_of_beam) r.added_resistance_n_per_m2 = 0.0;  // EQ-AR-4
  return r;
}

}  // namespace

void ResponseOptions::validate() const {
  section.validate();
  require_in_range("ResponseOptions.min_encounter_frequency_nondim", min_encounter_frequency_nondim,
                   1e-3, 2.0);
  require_in_range("ResponseOptions.num_threads", num_threads, -1, 1024);
}

Matrix6d rigid_body_mass_matrix(const model::Hull& hull) {
  const double m = hull.displacement_kg;
  const Eigen::Vector3d rg(hull.lcg_m, 0.0, hull.kg_m - hull.draft_m);
  const Eigen::Matrix3d s = skew(rg);
  Eigen::Matrix3d ig = Eigen::Matrix3d::Zero();
  ig(0, 0) = m * hull.radius_gyration_roll_m * hull.radius_gyration_roll_m;
  ig(1, 1) = m * hull.radius_gyration_pitch_m * hull.radius_gyration_pitch_m;
  ig(2, 2) = m * hull.radius_gyration_yaw_m * hull.radius_gyration_yaw_m;
  Matrix6d out = Matrix6d::Zero();
  out.topLeftCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
  out.topRightCorner<3, 3>() = -m * s;
  out.bottomLeftCorner<3, 3>() = m * s;
  out.bottomRightCorner<3, 3>() = ig - m * s * s;
  return out;
}

Matrix6d hydrostatic_restoring_matrix(const model::Hull& hull, const LewisOptions& lewis) {
  const auto& st = hull.stations;
  const std::vector<double> wx = trapezoid_weights(st);
  double awp = 0.0;
  double first = 0.0;
  double second = 0.0;
  double volume = 0.0;
  double volume_z = 0.0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const double b = st[i].beam_m;
    awp += wx[i] * b;
    first += wx[i] * st[i].x_m * b;
    second += wx[i] * st[i].x_m * st[i].x_m * b;
    if (has_section(st[i])) {
      const LewisForm form = lewis_form(st[i].beam_m, st[i].draft_m, st[i].area_coefficient, lewis);
      const SectionArea area = lewis_section_area(form);
      volume += wx[i] * area.area_m2;
      volume_z += wx[i] * area.area_m2 * area.centroid_z_m;
    }
  }
  const double rho_g = kRhoSeawater_kg_m3 * kGravity_m_s2;
  const double m = hull.displacement_kg;
  const double z_b = volume > 0.0 ? volume_z / volume : 0.0;
  const double z_g = hull.kg_m - hull.draft_m;
  Matrix6d c = Matrix6d::Zero();
  c(kHeave, kHeave) = rho_g * awp;
  c(kHeave, kPitch) = -rho_g * first;
  c(kPitch, kHeave) = -rho_g * first;
  c(kRoll, kRoll) = m * kGravity_m_s2 * hull.gm_m;
  c(kPitch, kPitch) = rho_g * second + m * kGravity_m_s2 * (z_b - z_g);
  return c;
}

std::vector<VesselResponse> compute_response(const model::Vessel& vessel, double speed_m_s,
                                             double heading_rad,
                                             const std::vector<double>& omegas_rad_s,
                                             const ResponseOptions& options) {
  options.validate();
  check_hull(vessel.hull);
  require_input(speed_m_s >= 0.0 && std::isfinite(speed_m_s), "speed_m_s", speed_m_s,
                "finite and >= 0 (the ship moves along +x)");
  require_input(std::isfinite(heading_rad), "heading_rad", heading_rad, "finite");
  for (double w : omegas_rad_s) require_positive("omega_rad_s", w);
  const Matrix6d mass = rigid_body_mass_matrix(vessel.hull);
  const Matrix6d restoring = hydrostatic_restoring_matrix(vessel.hull, options.section.lewis);
  std::vector<VesselResponse> out(omegas_rad_s.size());
  parallel_for(0, static_cast<std::int64_t>(omegas_rad_s.size()), options.num_threads,
               [&](std::int64_t i) {
                 const std::size_t j = static_cast<std::size_t>(i);
                 out[j] = respond(vessel, speed_m_s, heading_rad, omegas_rad_s[j], options, mass, restoring);
               });
  return out;
}

}  // namespace towdb::seakeeping
