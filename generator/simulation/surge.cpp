#include "simulation/surge.hpp"

#include "common/error.hpp"

namespace towdb::simulation {

void SurgeParameters::validate() const {
  require_positive("surge: tug_mass_kg", tug_mass_kg);
  require_positive("surge: tow_mass_kg", tow_mass_kg);
  require_in_range("surge: tug_damping_n_s_m", tug_damping_n_s_m, 0.0, 1e12);
  require_in_range("surge: tow_damping_n_s_m", tow_damping_n_s_m, 0.0, 1e12);
  require_in_range("surge: cos_alpha_tug", cos_alpha_tug, 0.0, 1.0);
  require_in_range("surge: cos_alpha_tow", cos_alpha_tow, 0.0, 1.0);
  require_in_range("surge: non_surge_stiffness_n_m", non_surge_stiffness_n_m, 0.0, 1e12);
  require_in_range("surge: non_surge_damping_n_s_m", non_surge_damping_n_s_m, 0.0, 1e12);
}

void DayForcing::validate() const {
  require_positive("forcing: dt_s", dt_s);
  const std::size_t n = tug_force_n.size();
  require_input(n >= 4, "forcing: samples", static_cast<double>(n), "at least 4 samples are needed");
  require_input(tow_force_n.size() == n && xi_ns_m.size() == n && xi_ns_dot_m_s.size() == n, "forcing: samples",
                static_cast<double>(n), "all four records must have the same length");
}

void IntegratorOptions::validate() const {
  require_in_range("integrator: warmup_s", warmup_s, 0.0, 1e6);
  require_in_range("integrator: max_omega_h", max_omega_h, 1e-3, 1.0);
  require_in_range("integrator: max_substeps", max_substeps, 1, 1 << 20);
}

LaneIsa fastest_lane_isa() {
#if defined(TOWDB_SURGE_HAVE_AVX2_PATH)
  // libgcc's check includes the operating system's support of the AVX
  // register state (XGETBV), not only the CPUID bit. __builtin_cpu_init
  // first: libgcc's own initialiser may not have run yet when this is
  // called from another static initialiser.
  static const bool avx2 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  if (avx2) return LaneIsa::kAvx2;
#endif
  return LaneIsa::kBaseline;
}

const char* lane_isa_name(LaneIsa isa) { return isa == LaneIsa::kAvx2 ? "avx2" : "baseline"; }

}  // namespace towdb::simulation
