// Mean added resistance in a sea and the wave-induced surge damping
// (EQ-AR-2, EQ-AR-3).
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "seakeeping/seakeeping.hpp"

namespace towdb::seakeeping {

void AddedResistanceOptions::validate() const {
  response.validate();
  require_positive("AddedResistanceOptions.omega_min_rad_s", omega_min_rad_s);
  require_input(omega_max_rad_s > omega_min_rad_s && std::isfinite(omega_max_rad_s),
                "AddedResistanceOptions.omega_max_rad_s", omega_max_rad_s,
                "finite and > omega_min_rad_s");
  require_in_range("AddedResistanceOptions.omega_count", omega_count, 3, 100000);
  require_positive("AddedResistanceOptions.speed_step_m_s", speed_step_m_s);
}

double mean_added_resistance_n(const std::vector<VesselResponse>& responses,
                               const Spectrum& spectrum) {
  require_input(responses.size() >= 2, "mean_added_resistance responses",
                static_cast<double>(responses.size()), "at least 2 frequencies");
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < responses.size(); ++i) {
    const VesselResponse& a = responses[i];
    const VesselResponse& b = responses[i + 1];
    require_input(b.omega_rad_s > a.omega_rad_s, "mean_added_resistance omega_rad_s", b.omega_rad_s,
                  "frequencies strictly increasing");
    const double sa = spectrum(a.omega_rad_s);
    const double sb = spectrum(b.omega_rad_s);
    require_input(std::isfinite(sa) && sa >= 0.0, "spectrum value", sa, "finite and >= 0");
    require_input(std::isfinite(sb) && sb >= 0.0, "spectrum value", sb, "finite and >= 0");
    sum += 0.5 * (b.omega_rad_s - a.omega_rad_s) *
           (a.added_resistance_n_per_m2 * sa + b.added_resistance_n_per_m2 * sb);
  }
  return 2.0 * sum;
}

namespace {

std::vector<double> grid(const AddedResistanceOptions& o) {
  std::vector<double> w(static_cast<std::size_t>(o.omega_count));
  for (int i = 0; i < o.omega_count; ++i) {
    w[static_cast<std::size_t>(i)] =
        o.omega_min_rad_s + (o.omega_max_rad_s - o.omega_min_rad_s) * static_cast<double>(i) /
                                static_cast<double>(o.omega_count - 1);
  }
  return w;
}

}  // namespace

double mean_added_resistance_n(const model::Vessel& vessel, double speed_m_s, double heading_rad,
                               const Spectrum& spectrum, const AddedResistanceOptions& options) {
  options.validate();
  return mean_added_resistance_n(
      compute_response(vessel, speed_m_s, heading_rad, grid(options), options.response), spectrum);
}

double wave_surge_damping_n_s_m(const model::Vessel& vessel, double speed_m_s, double heading_rad,
                                const Spectrum& spectrum, const AddedResistanceOptions& options) {
  options.validate();
  const double r0 = mean_added_resistance_n(vessel, speed_m_s, heading_rad, spectrum, options);
  const double r1 =
      mean_added_resistance_n(vessel, speed_m_s + options.speed_step_m_s, heading_rad, spectrum, options);
  return (r1 - r0) / options.speed_step_m_s;
}

}  // namespace towdb::seakeeping
