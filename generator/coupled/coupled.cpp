#include "coupled/coupled.hpp"

#include <cmath>

#include <Eigen/LU>

#include "common/error.hpp"

namespace towdb::coupled {

void LineGeometry::validate() const {
  require_in_range("line geometry: tug_angle_rad", tug_angle_rad, -1.5, 1.5);
  require_in_range("line geometry: tow_angle_rad", tow_angle_rad, -1.5, 1.5);
  require_positive("line geometry: separation_m", separation_m);
}

Vector12d extension_vector(const LineGeometry& g) {
  const double c1 = std::cos(g.tug_angle_rad), s1 = std::sin(g.tug_angle_rad);
  const double c2 = std::cos(g.tow_angle_rad), s2 = std::sin(g.tow_angle_rad);
  Vector12d s = Vector12d::Zero();
  s[0] = c1;
  s[2] = s1;
  s[4] = g.tug_point.z_m * c1 - g.tug_point.x_m * s1;
  s[6] = -c2;
  s[8] = s2;
  s[10] = -g.tow_point.z_m * c2 - g.tow_point.x_m * s2;
  return s;
}

Vector12d non_surge_extension_vector(const LineGeometry& g) {
  Vector12d s = extension_vector(g);
  s[0] = 0.0;
  s[6] = 0.0;
  return s;
}

Matrix12cd impedance(const seakeeping::VesselResponse& tug, const seakeeping::VesselResponse& tow,
                     const LineGeometry& geometry, const LinearLine& line, const SurgeDampings& surge) {
  // The strip-theory coefficients were evaluated at the floored encounter
  // frequency w_h (seakeeping EQ-STRIP-10); the equation of motion uses the same.
  const double w = tug.omega_hydro_rad_s;
  using C = std::complex<double>;
  Matrix12cd z = Matrix12cd::Zero();
  auto block = [&](const seakeeping::VesselResponse& r, int offset) {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        z(offset + i, offset + j) = C(-w * w * (r.mass(i, j) + r.added_mass(i, j)) + r.restoring(i, j),
                                      w * r.damping(i, j));
      }
    }
  };
  block(tug, 0);
  block(tow, 6);
  z(0, 0) += C(0.0, w * surge.tug_n_s_m);
  z(6, 6) += C(0.0, w * surge.tow_n_s_m);
  const Vector12d s = extension_vector(geometry);
  const C line_impedance(line.stiffness_n_m, w * line.damping_n_s_m);
  z += line_impedance * (s * s.transpose()).cast<C>();
  return z;
}

std::vector<CoupledResponse> couple(const std::vector<seakeeping::VesselResponse>& tug,
                                    const std::vector<seakeeping::VesselResponse>& tow,
                                    const LineGeometry& geometry, const LinearLine& line,
                                    const SurgeDampings& surge) {
  geometry.validate();
  if (tug.size() != tow.size()) {
    throw InputError("coupled model: tug has " + std::to_string(tug.size()) + " frequencies, tow " +
                     std::to_string(tow.size()) + "; they must match");
  }
  using C = std::complex<double>;
  const Vector12d s_ns = non_surge_extension_vector(geometry);
  std::vector<CoupledResponse> out;
  out.reserve(tug.size());
  for (std::size_t i = 0; i < tug.size(); ++i) {
    const auto& a = tug[i];
    const auto& b = tow[i];
    if (a.omega_rad_s != b.omega_rad_s || a.speed_m_s != b.speed_m_s || a.heading_rad != b.heading_rad) {
      throw InputError("coupled model: response " + std::to_string(i) + " of tug and tow differ in frequency, "
                       "speed or heading (omega " + format_value(a.omega_rad_s) + " vs " +
                       format_value(b.omega_rad_s) + ")");
    }
    const Matrix12cd z = impedance(a, b, geometry, line, surge);
    const Eigen::PartialPivLU<Matrix12cd> lu(z);
    Vector12cd f_tug = Vector12cd::Zero(), f_tow = Vector12cd::Zero();
    f_tug.head<6>() = a.exciting_force_per_m;
    f_tow.tail<6>() = b.exciting_force_per_m;
    CoupledResponse r;
    r.omega_rad_s = a.omega_rad_s;
    r.omega_e_rad_s = a.omega_e_rad_s;
    r.wavenumber_rad_m = a.wavenumber_rad_m;
    r.motion_p = lu.solve(f_tug);
    r.motion_q = lu.solve(f_tow);
    r.xi_ns_p = (s_ns.cast<C>().transpose() * r.motion_p)(0, 0);
    r.xi_ns_q = (s_ns.cast<C>().transpose() * r.motion_q)(0, 0);
    r.surge_force_tug_n_per_m = a.exciting_force_per_m[0];
    r.surge_force_tow_n_per_m = b.exciting_force_per_m[0];
    r.drift_tug_n_per_m2 = a.added_resistance_n_per_m2;
    r.drift_tow_n_per_m2 = b.added_resistance_n_per_m2;
    out.push_back(r);
  }
  return out;
}

}  // namespace towdb::coupled
