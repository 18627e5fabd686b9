#include "simulation/case_runner.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "common/units.hpp"
#include "coupled/coupled.hpp"
#include "propulsion/hull_damping.hpp"
#include "simulation/response_cache.hpp"
#include "simulation/tension_laws.hpp"
#include "statistics/bootstrap.hpp"
#include "statistics/distributions.hpp"
#include "statistics/fit.hpp"
#include "statistics/goodness_of_fit.hpp"

namespace towdb::simulation {

namespace {

using Complex = std::complex<double>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The thesis's speed step for the wave-induced surge damping (3.5): 1 ft/s.
constexpr double kWaveDampingSpeedStep_m_s = units::ft_s_to_m_s(1.0);

// Record-series indices.
enum Linear : std::size_t { kF1Tug = 0, kF1Tow = 1, kXiNs = 2, kXiNsDot = 3, kLinearCount = 4 };
enum Drift : std::size_t { kF2Tug = 0, kF2Tow = 1, kDriftCount = 2 };


// Linear interpolation of y(x) on an increasing grid, clamped at the ends.
template <typename T>
T interpolate(const std::vector<double>& x, const std::vector<T>& y, double xq) {
  if (xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), xq);
  const std::size_t i = static_cast<std::size_t>(it - x.begin());
  const double t = (xq - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + (y[i] - y[i - 1]) * t;
}

}  // namespace

struct CaseModel {
  CaseInputs inputs;
  CaseOptions options;
  std::shared_ptr<const towline::TowlineFit> fit;
  SurgeParameters surge;
  std::unique_ptr<sea::DaySynthesizer> synthesizer;
  // Per component: the first-order transfer functions (for the linear check).
  std::vector<Complex> h_f1_tug, h_f1_tow, h_xi_ns;
  CaseResult partial;  // everything known before the days are simulated
};

std::vector<double> response_grid(const CaseOptions& options) {
  const int n = options.response_frequencies;
  const double lo = options.response_omega_min_rad_s, hi = options.response_omega_max_rad_s;
  std::vector<double> omega;
  for (int i = 0; i < n; ++i) omega.push_back(lo + (hi - lo) * i / (n - 1));
  return omega;
}

void CaseInputs::validate() const {
  if (!tug || !tow) throw InputError("case: tug and tow must be given");
  if (tug->role != model::VesselRole::kTug) throw InputError("case: '" + tug->name + "' is not a tug");
  model::validate(towline);
  require_in_range("case: speed (kt)", units::m_s_to_kt(speed_m_s), 0.5, 20.0);
  sea.validate();
  require_positive("case: mean tension (N)", mean_tension_n);
  require_input(mean_tension_n < towline.breaking_strength_n(), "case: mean tension (lbf)",
                units::n_to_lbf(mean_tension_n),
                "must be below the towline's breaking strength " +
                    format_value(units::n_to_lbf(towline.breaking_strength_n())) + " lbf");
  require_in_range("case: days", days, 3, 1000000);
}

void CaseOptions::validate() const {
  towline.validate();
  response.validate();
  require_in_range("case options: response_frequencies", response_frequencies, 8, 2000);
  require_in_range("case options: response_omega_min_rad_s", response_omega_min_rad_s, 0.01, 2.0);
  require_input(response_omega_max_rad_s > response_omega_min_rad_s + 0.1, "case options: response_omega_max_rad_s",
                response_omega_max_rad_s, "must exceed response_omega_min_rad_s by at least 0.1 rad/s");
  tug_propeller.validate();
  tow_propeller.validate();
  record.validate();
  integrator.validate();
  require_in_range("case options: confidence_level", confidence_level, 0.5, 0.999);
  require_in_range("case options: bootstrap_replicates", bootstrap_replicates, 100, 1000000);
}

namespace {

// The record plan's size and coverage, copied into the case result.
void record_plan_summary(const sea::RecordPlan& plan, CaseResult& r) {
  r.record_time_step_s = plan.time_step_s();
  r.record_samples = plan.samples();
  r.wave_components = plan.components().size();
  r.retained_variance_fraction = plan.retained_variance_m2() / plan.spectrum_variance_m2();
}

// The tow points and line angles of the 12-DOF model; the separation is the
// tug's origin to the tow's, along the track.
coupled::LineGeometry line_geometry(const model::Vessel& tug, const model::Vessel& tow,
                                    const towline::FitSummary& towline) {
  coupled::LineGeometry geometry;
  geometry.tug_angle_rad = towline.tug_angle_rad;
  geometry.tow_angle_rad = towline.tow_angle_rad;
  geometry.tug_point = tug.tow_point;
  geometry.tow_point = tow.tow_point;
  geometry.separation_m = -tug.tow_point.x_m + towline.span_m + tow.tow_point.x_m;
  return geometry;
}

// The linearised line of the 12-DOF model: a10 and a01 of the polynomial.
// A very slack wire's polynomial fit can give a10 <= 0 (the cubic follows the
// large runs, not the small-motion slope; docs/physics.md 2.3); then the
// static catenary stiffness dH/dX (EQ-TOWLINE-4) stands in (always > 0).
coupled::LinearLine linearised_line(const towline::TowlineFit& fit) {
  const double a10 = fit.coefficients().a10();
  return coupled::LinearLine{a10 > 0.0 ? a10 : fit.summary().static_stiffness_n_m,
                             std::max(0.0, fit.coefficients().a01())};
}

// One wave system's vessel responses and coupled transfer functions on a
// frequency grid spanning its components (empty when none survived the cut-off).
struct SystemGrid {
  std::vector<double> omega;
  std::vector<Complex> f1_tug, f1_tow, xi_p, xi_q;
  std::vector<double> drift_tug, drift_tow;
  double heading_rad = 0.0;
  std::vector<seakeeping::VesselResponse> tug_response, tow_response;  // at U
};

// Per wave system: the strip-theory responses at U, and the mean added
// resistance and wave-induced surge damping each adds to the case result.
std::vector<SystemGrid> system_responses(const CaseInputs& inputs, const CaseOptions& options,
                                         const std::vector<sea::WaveComponent>& comps, CaseResult& r) {
  const model::Vessel& tug = *inputs.tug;
  const model::Vessel& tow = *inputs.tow;
  const double u = inputs.speed_m_s;
  const std::size_t n_systems = inputs.sea.systems.size();
  std::vector<SystemGrid> grids(n_systems);
  for (std::size_t s = 0; s < n_systems; ++s) {
    const sea::WaveSystem& system = inputs.sea.systems[s];
    bool has_components = false;
    for (const auto& c : comps) has_components = has_components || c.system == static_cast<int>(s);
    SystemGrid& g = grids[s];
    g.heading_rad = system.heading_rad;
    if (!has_components) continue;  // no component of this system survived the cut-off
    g.omega = response_grid(options);
    g.tug_response = *cached_responses(tug, u, system.heading_rad, g.omega, options.response);
    g.tow_response = *cached_responses(tow, u, system.heading_rad, g.omega, options.response);
    const auto spectrum = [&system](double w) { return system.spectrum.density_m2_s(w); };
    const double r_tug_u = seakeeping::mean_added_resistance_n(g.tug_response, spectrum);
    const double r_tow_u = seakeeping::mean_added_resistance_n(g.tow_response, spectrum);
    r.tug_added_resistance_n += r_tug_u;
    r.tow_added_resistance_n += r_tow_u;
    if (options.wave_surge_damping) {
      const double u2 = u + kWaveDampingSpeedStep_m_s;
      const auto r_tug2 = cached_responses(tug, u2, system.heading_rad, g.omega, options.response);
      const auto r_tow2 = cached_responses(tow, u2, system.heading_rad, g.omega, options.response);
      r.tug_wave_damping_n_s_m +=
          (seakeeping::mean_added_resistance_n(*r_tug2, spectrum) - r_tug_u) / kWaveDampingSpeedStep_m_s;
      r.tow_wave_damping_n_s_m +=
          (seakeeping::mean_added_resistance_n(*r_tow2, spectrum) - r_tow_u) / kWaveDampingSpeedStep_m_s;
    }
  }
  return grids;
}

// Hull + propeller + wave-induced surge damping of each vessel; both must be
// positive.
coupled::SurgeDampings total_dampings(const propulsion::SurgeDamping& tug_damping,
                                      const propulsion::SurgeDamping& tow_damping, const CaseOptions& options,
                                      CaseResult& r) {
  // A negative wave-induced damping (a resistance that falls with speed) is
  // kept: it is physics. The total surge damping must stay positive. (The
  // diagnostic nonnegative_wave_damping holds it at 0, issue 17 lead 4.)
  if (options.nonnegative_wave_damping) {
    r.tug_wave_damping_n_s_m = std::max(0.0, r.tug_wave_damping_n_s_m);
    r.tow_wave_damping_n_s_m = std::max(0.0, r.tow_wave_damping_n_s_m);
  }
  const coupled::SurgeDampings dampings{tug_damping.total_n_s_m + r.tug_wave_damping_n_s_m,
                                        tow_damping.total_n_s_m + r.tow_wave_damping_n_s_m};
  require_input(dampings.tug_n_s_m > 0.0, "tug total surge damping (N s/m)", dampings.tug_n_s_m,
                "must be positive (hull + propeller + wave-induced)");
  require_input(dampings.tow_n_s_m > 0.0, "tow total surge damping (N s/m)", dampings.tow_n_s_m,
                "must be positive (hull + wave-induced)");
  return dampings;
}

// Couples each system's responses (once the surge dampings of all systems
// are known) into its surge forces, non-surge extension and drift coefficients.
void couple_systems(std::vector<SystemGrid>& grids, const coupled::LineGeometry& geometry,
                    const coupled::LinearLine& line, const coupled::SurgeDampings& dampings,
                    const CaseOptions& options) {
  for (SystemGrid& g : grids) {
    if (g.omega.empty()) continue;
    const auto c = coupled::couple(g.tug_response, g.tow_response, geometry, line, dampings);
    for (const auto& ci : c) {
      g.f1_tug.push_back(ci.surge_force_tug_n_per_m);
      g.f1_tow.push_back(ci.surge_force_tow_n_per_m);
      g.xi_p.push_back(ci.xi_ns_p);
      g.xi_q.push_back(ci.xi_ns_q);
      // Newman's approximation needs D >= 0; a negative added resistance
      // (small, following seas) gives no slowly varying force here.
      g.drift_tug.push_back(options.signed_drift ? ci.drift_tug_n_per_m2 : std::max(0.0, ci.drift_tug_n_per_m2));
      g.drift_tow.push_back(options.signed_drift ? ci.drift_tow_n_per_m2 : std::max(0.0, ci.drift_tow_n_per_m2));
    }
  }
}

// The day synthesizer of the case: transfer functions per component
// (EQ-COUPLED-4: the tow's lag applied here), interpolated from the system
// grids; the first-order ones are kept in the model for the linear check.
std::unique_ptr<sea::DaySynthesizer> make_synthesizer(const sea::RecordPlan& plan,
                                                      const std::vector<SystemGrid>& grids,
                                                      double separation_m, const CaseOptions& options,
                                                      CaseModel& m) {
  const auto& comps = plan.components();
  std::vector<std::vector<Complex>> linear(kLinearCount, std::vector<Complex>(comps.size()));
  std::vector<std::vector<double>> drift(kDriftCount, std::vector<double>(comps.size(), 0.0));
  // EQ-CASE-2: where each second-order series acts. The tug's origin is the
  // reference. The thesis drives both vessels' slowly varying forces with one
  // envelope (the default); with options.tow_drift_at_tow the tow's is the
  // envelope at the tow, G astern, phase k G cos mu per component (thesis
  // eq. 3-21's lag, as its first-order force has).
  std::vector<std::vector<double>> drift_phase(kDriftCount, std::vector<double>(comps.size(), 0.0));
  m.h_f1_tug.resize(comps.size());
  m.h_f1_tow.resize(comps.size());
  m.h_xi_ns.resize(comps.size());
  for (std::size_t j = 0; j < comps.size(); ++j) {
    const auto& c = comps[j];
    const SystemGrid& g = grids[static_cast<std::size_t>(c.system)];
    const Complex lag = std::exp(Complex(0.0, c.wavenumber_rad_m * separation_m * std::cos(c.heading_rad)));
    const Complex f1_tug = interpolate(g.omega, g.f1_tug, c.omega_rad_s);
    const Complex f1_tow = interpolate(g.omega, g.f1_tow, c.omega_rad_s) * lag;
    const Complex xi = interpolate(g.omega, g.xi_p, c.omega_rad_s) + interpolate(g.omega, g.xi_q, c.omega_rad_s) * lag;
    linear[kF1Tug][j] = f1_tug;
    linear[kF1Tow][j] = f1_tow;
    linear[kXiNs][j] = xi;
    linear[kXiNsDot][j] = Complex(0.0, c.encounter_omega_rad_s) * xi;
    m.h_f1_tug[j] = f1_tug;
    m.h_f1_tow[j] = f1_tow;
    m.h_xi_ns[j] = xi;
    if (options.second_order_forces) {
      drift[kF2Tug][j] = interpolate(g.omega, g.drift_tug, c.omega_rad_s);
      drift[kF2Tow][j] = interpolate(g.omega, g.drift_tow, c.omega_rad_s);
      if (options.tow_drift_at_tow) {
        drift_phase[kF2Tow][j] = c.wavenumber_rad_m * separation_m * std::cos(c.heading_rad);
      }
    }
  }
  return std::make_unique<sea::DaySynthesizer>(plan, linear, drift, drift_phase);
}

// The two-vessel surge model's masses, dampings and line angles.
SurgeParameters surge_parameters(const model::Vessel& tug, const model::Vessel& tow,
                                 const coupled::SurgeDampings& dampings, const towline::FitSummary& towline,
                                 const coupled::LinearLine& line, const CaseOptions& options) {
  SurgeParameters p;
  p.tug_mass_kg = tug.hull.displacement_kg * (1.0 + tug.hull.surge_added_mass_ratio);
  p.tow_mass_kg = tow.hull.displacement_kg * (1.0 + tow.hull.surge_added_mass_ratio);
  p.tug_damping_n_s_m = dampings.tug_n_s_m;
  p.tow_damping_n_s_m = dampings.tow_n_s_m;
  p.cos_alpha_tug = std::cos(towline.tug_angle_rad);
  p.cos_alpha_tow = std::cos(towline.tow_angle_rad);
  if (options.linear_non_surge_tension) {  // EQ-SURGE-6 with the 12-DOF model's line
    p.linear_non_surge_tension = true;
    p.non_surge_stiffness_n_m = line.stiffness_n_m;
    p.non_surge_damping_n_s_m = line.damping_n_s_m;
  }
  p.validate();
  return p;
}

// The first-order extension of component j per unit wave amplitude: EQ-SURGE-1..3
// with the linear line tau = (k + i w c) xi, harmonic at the encounter frequency w.
Complex linear_extension(const CaseModel& m, std::size_t j, double w, double k, double c) {
  const SurgeParameters& p = m.surge;
  const double c1 = p.cos_alpha_tug, c2 = p.cos_alpha_tow;
  const Complex kc(k, w * c);
  const Complex a11 = -w * w * p.tug_mass_kg + Complex(0, w * p.tug_damping_n_s_m) + kc * c1 * c1;
  const Complex a22 = -w * w * p.tow_mass_kg + Complex(0, w * p.tow_damping_n_s_m) + kc * c2 * c2;
  const Complex a12 = -kc * c1 * c2;
  const Complex b1 = m.h_f1_tug[j] - kc * c1 * m.h_xi_ns[j];
  const Complex b2 = m.h_f1_tow[j] + kc * c2 * m.h_xi_ns[j];
  const Complex det = a11 * a22 - a12 * a12;
  const Complex x1 = (b1 * a22 - a12 * b2) / det;
  const Complex x7 = (a11 * b2 - a12 * b1) / det;
  return c1 * x1 - c2 * x7 + m.h_xi_ns[j];
}

// EQ-SURGE-7 (diagnostic): the line that carries the non-surge tension under
// EQ-SURGE-6, the polynomial's Gaussian equivalent (EQ-TOWLINE-18) over the
// non-surge extension (kEquivalentNonSurge) or over the whole first-order
// extension of the linear surge system (kEquivalentTotal), which depends on
// the line itself: iterated to a fixed point.
coupled::LinearLine equivalent_line(const CaseModel& m) {
  const auto& comps = m.synthesizer->plan().components();
  const auto& a = m.fit->coefficients();
  const bool total = m.options.non_surge_stiffness == CaseOptions::NonSurgeStiffness::kEquivalentTotal;
  coupled::LinearLine line{a.a10(), a.a01()};
  constexpr int kMaxIterations = 200;
  constexpr double kRelativeChange = 1e-9;  // far below any effect on a daily maximum
  for (int it = 0; it < kMaxIterations; ++it) {
    double s2 = 0.0, v2 = 0.0;
    for (std::size_t j = 0; j < comps.size(); ++j) {
      const double w = comps[j].encounter_omega_rad_s;
      const Complex xi = total ? linear_extension(m, j, w, line.stiffness_n_m, line.damping_n_s_m) : m.h_xi_ns[j];
      const double e = 0.5 * comps[j].amplitude_m * comps[j].amplitude_m * std::norm(xi);
      s2 += e;
      v2 += w * w * e;
    }
    const towline::EquivalentLinearLine eq = towline::gaussian_equivalent_line(a, s2, v2);
    const coupled::LinearLine next{eq.stiffness_n_m, eq.damping_n_s_m};
    if (!(next.stiffness_n_m > 0.0)) {
      throw NumericalError("equivalent linear towline: stiffness " + format_value(next.stiffness_n_m) +
                           " N/m is not positive");
    }
    const bool settled = std::abs(next.stiffness_n_m - line.stiffness_n_m) <= kRelativeChange * next.stiffness_n_m &&
                         std::abs(next.damping_n_s_m - line.damping_n_s_m) <=
                             kRelativeChange * std::max(std::abs(next.damping_n_s_m), 1.0);
    line = next;
    if (!total || settled) return line;
  }
  throw NumericalError("equivalent linear towline: no fixed point in " + std::to_string(kMaxIterations) +
                       " iterations");
}

}  // namespace

std::shared_ptr<const CaseModel> prepare_case(const CaseInputs& inputs, const CaseOptions& options) {
  inputs.validate();
  options.validate();
  auto m = std::make_shared<CaseModel>();
  m->inputs = inputs;
  m->options = options;
  CaseResult& r = m->partial;
  const model::Vessel& tug = *inputs.tug;
  const model::Vessel& tow = *inputs.tow;
  const double u = inputs.speed_m_s;
  const double h = inputs.mean_tension_n;

  // 1. Towline.
  auto t0 = Clock::now();
  m->fit = towline::global_fit_cache().get(inputs.towline, towline::TowPoints{tug.tow_point.z_m, tow.tow_point.z_m},
                                           h, options.towline);
  r.towline = m->fit->summary();
  r.timings.towline_s = seconds_since(t0);

  // 2-4. Hydrodynamics, damping, coupling.
  t0 = Clock::now();
  const sea::RecordPlan plan(inputs.sea, u, options.record);
  record_plan_summary(plan, r);
  const coupled::LineGeometry geometry = line_geometry(tug, tow, r.towline);
  r.separation_m = geometry.separation_m;
  const coupled::LinearLine line = linearised_line(*m->fit);

  const propulsion::SurgeDamping tug_damping = propulsion::tug_surge_damping(tug, u, h, {}, options.tug_propeller);
  const propulsion::SurgeDamping tow_damping = propulsion::tow_surge_damping(tow, u, {}, options.tow_propeller);
  r.tug_hull_damping_n_s_m = tug_damping.hull_n_s_m;
  r.tug_propeller_damping_n_s_m = tug_damping.propeller_n_s_m;
  r.tow_hull_damping_n_s_m = tow_damping.hull_n_s_m;
  r.tow_propeller_damping_n_s_m = tow_damping.propeller_n_s_m;

  std::vector<SystemGrid> grids = system_responses(inputs, options, plan.components(), r);
  const coupled::SurgeDampings dampings = total_dampings(tug_damping, tow_damping, options, r);
  couple_systems(grids, geometry, line, dampings, options);
  m->synthesizer = make_synthesizer(plan, grids, geometry.separation_m, options, *m);
  r.fft_plan_from_stored_wisdom = m->synthesizer->plan_from_stored_wisdom();

  m->surge = surge_parameters(tug, tow, dampings, r.towline, line, options);
  if (options.linear_non_surge_tension && options.non_surge_stiffness != CaseOptions::NonSurgeStiffness::kA10) {
    const coupled::LinearLine eq = equivalent_line(*m);
    m->surge.non_surge_stiffness_n_m = eq.stiffness_n_m;
    m->surge.non_surge_damping_n_s_m = eq.damping_n_s_m;
  }
  r.tug_mass_kg = m->surge.tug_mass_kg;
  r.tow_mass_kg = m->surge.tow_mass_kg;
  r.timings.hydrodynamics_s = seconds_since(t0);
  return m;
}

namespace {

// Per-worker scratch: the synthesizer's buffers and the day's forcing.
struct DayScratch {
  sea::DaySynthesizer::Workspace workspace;
  DayForcing forcing;
};

// The four records the integrator reads, from a synthesised day's workspace:
// tug and tow forces f1 + f2, xi_ns and xi_ns', written every Stride values
// from the four pointers (Stride = K: one lane of a lock-step group).
template <std::size_t Stride>
void write_records(const sea::DaySynthesizer::Workspace& w, double* tug, double* tow, double* xi, double* xi_dot) {
  const auto f1_tug = w.linear(kF1Tug), f1_tow = w.linear(kF1Tow);
  const auto f2_tug = w.drift(kF2Tug), f2_tow = w.drift(kF2Tow);
  const auto xi_ns = w.linear(kXiNs), xi_ns_dot = w.linear(kXiNsDot);
  for (std::size_t i = 0; i < f1_tug.size(); ++i) {
    tug[i * Stride] = f1_tug[i] + f2_tug[i];
    tow[i * Stride] = f1_tow[i] + f2_tow[i];
    xi[i * Stride] = xi_ns[i];
    xi_dot[i * Stride] = xi_ns_dot[i];
  }
}

void fill_forcing(const CaseModel& m, std::uint64_t seed, std::uint64_t day, DayScratch& s) {
  m.synthesizer->synthesize(seed, day, s.workspace);
  DayForcing& f = s.forcing;
  f.dt_s = m.synthesizer->plan().time_step_s();
  const std::size_t n = s.workspace.linear(kF1Tug).size();
  for (auto* r : {&f.tug_force_n, &f.tow_force_n, &f.xi_ns_m, &f.xi_ns_dot_m_s}) r->resize(n);
  write_records<1>(s.workspace, f.tug_force_n.data(), f.tow_force_n.data(), f.xi_ns_m.data(), f.xi_ns_dot_m_s.data());
}

// A lock-step group's scratch: the synthesizer's buffers and the days'
// records interleaved for integrate_days.
struct GroupScratch {
  sea::DaySynthesizer::Workspace workspace;
  LockstepForcing<kLockstepDays> forcing;
};

// Synthesises day `day` into lane l of the group (written right after the
// synthesis, while the records are in cache; a single pass over four
// synthesised days was no faster and needs four workspaces).
void fill_lane(const CaseModel& m, std::uint64_t seed, std::uint64_t day, std::size_t l, GroupScratch& s) {
  constexpr std::size_t K = kLockstepDays;
  m.synthesizer->synthesize(seed, day, s.workspace);
  LockstepForcing<K>& f = s.forcing;
  f.dt_s = m.synthesizer->plan().time_step_s();
  const std::size_t n = s.workspace.linear(kF1Tug).size();
  if (f.size() != n) f.resize(n);
  write_records<K>(s.workspace, f.tug_force_n.data() + l, f.tow_force_n.data() + l, f.xi_ns_m.data() + l,
                   f.xi_ns_dot_m_s.data() + l);
}

}  // namespace

DayForcing day_forcing(const CaseModel& m, std::uint64_t seed, std::uint64_t day) {
  DayScratch s{m.synthesizer->make_workspace(), {}};
  fill_forcing(m, seed, day, s);
  return std::move(s.forcing);
}

namespace {

// Calls fn with the case's tension law (the integrator is a template on it).
template <typename Fn>
auto with_tension_law(const CaseModel& m, Fn&& fn) {
  if (m.options.tension_law == TensionLaw::kLinear) {
    return fn(LinearLaw{m.fit->coefficients().a10(), m.fit->coefficients().a01()});
  }
  return fn(PolynomialLaw(m.fit.get(), m.options.above_breaking));
}

// CaseResult::extension from the days (pooled time mean and variance: every
// day has the same number of samples) and the fitted range in r.towline.
void summarise_extension(CaseResult& r) {
  ExtensionSummary& e = r.extension;
  e.min_m = std::numeric_limits<double>::infinity();
  e.max_m = -std::numeric_limits<double>::infinity();
  double mean = 0.0, second = 0.0;
  for (const DayResult& d : r.days) {
    e.min_m = std::min(e.min_m, d.extension_min_m);
    e.max_m = std::max(e.max_m, d.extension_max_m);
    mean += d.extension_mean_m;
    second += d.extension_variance_m2 + d.extension_mean_m * d.extension_mean_m;
    if (d.extension_min_m < r.towline.fit_xi_min_m || d.extension_max_m > r.towline.fit_xi_max_m) {
      ++e.days_outside_fit;
    }
  }
  const double n = static_cast<double>(r.days.size());
  e.mean_m = mean / n;
  e.sd_m = std::sqrt(std::max(0.0, second / n - e.mean_m * e.mean_m));
}

}  // namespace

DayStatistics simulate_day(const CaseModel& m, const DayForcing& forcing, const IntegratorOptions& options,
                           std::vector<double>* trace) {
  return with_tension_law(m, [&](const auto& law) { return integrate_day(m.surge, forcing, law, options, trace); });
}

std::array<DayStatistics, kLockstepDays> simulate_days(const CaseModel& m,
                                                      const LockstepForcing<kLockstepDays>& forcing,
                                                      const IntegratorOptions& options, LaneIsa isa) {
  static_assert(kLockstepDays == 4, "integrate_days_fastest integrates four days");
  return with_tension_law(
      m, [&](const auto& law) { return integrate_days_fastest(m.surge, forcing, law, options, {}, isa); });
}

double linear_tension_variance_n2(const CaseInputs& inputs, const CaseOptions& options) {
  const auto m = prepare_case(inputs, options);
  const auto& comps = m->synthesizer->plan().components();
  const double k = m->fit->coefficients().a10(), c = m->fit->coefficients().a01();
  double variance = 0.0;
  for (std::size_t j = 0; j < comps.size(); ++j) {
    const double w = comps[j].encounter_omega_rad_s;
    const Complex kc(k, w * c);
    const Complex tau = kc * linear_extension(*m, j, w, k, c);
    variance += 0.5 * comps[j].amplitude_m * comps[j].amplitude_m * std::norm(tau);
  }
  return variance;
}

std::vector<double> linear_tension_sigma_by_heading_n(const CaseInputs& inputs, const CaseOptions& options,
                                                       const std::vector<double>& headings_deg) {
  if (inputs.sea.systems.size() != 1) {
    throw InputError("linear heading profile: the sea has " + std::to_string(inputs.sea.systems.size()) +
                     " wave systems; allowed: one (a heading profile turns one system)");
  }
  CaseInputs at = inputs;
  std::vector<double> sigma;
  sigma.reserve(headings_deg.size());
  for (double h : headings_deg) {
    at.sea.systems[0].heading_rad = units::deg_to_rad(h);
    sigma.push_back(std::sqrt(linear_tension_variance_n2(at, options)));
  }
  return sigma;
}

CaseResult run_case(const CaseInputs& inputs, const CaseOptions& options) {
  const auto start = Clock::now();
  const auto m = prepare_case(inputs, options);
  CaseResult r = m->partial;
  const int days = inputs.days;
  r.days.resize(static_cast<std::size_t>(days));
  std::vector<double> synth_s(static_cast<std::size_t>(days)), integ_s(static_cast<std::size_t>(days));
  std::vector<long> substeps(static_cast<std::size_t>(days));
  std::mutex progress_mutex;
  int done = 0;
  // Days in groups of kLockstepDays consecutive days, each group's surge
  // equations integrated in lock step (integrate_days): the grouping depends
  // only on the day numbers, and a day's result not even on its group. A last,
  // partial group repeats its first day in the unused lanes (results dropped).
  r.lane_isa = with_tension_law(
      *m, [](const auto& law) { return lane_isa_for<std::decay_t<decltype(law)>>(fastest_lane_isa()); });
  std::vector<std::unique_ptr<GroupScratch>> scratch(static_cast<std::size_t>(workers(options.num_threads)));
  const int groups = (days + static_cast<int>(kLockstepDays) - 1) / static_cast<int>(kLockstepDays);
  parallel_for_workers(0, groups, options.num_threads, [&](std::int64_t g, int worker) {
    const std::size_t first = static_cast<std::size_t>(g) * kLockstepDays;
    const std::size_t count = std::min(kLockstepDays, static_cast<std::size_t>(days) - first);
    auto& s = scratch[static_cast<std::size_t>(worker)];
    if (!s) s = std::make_unique<GroupScratch>(GroupScratch{m->synthesizer->make_workspace(), {}});
    for (std::size_t l = 0; l < count; ++l) {
      const auto t = Clock::now();
      fill_lane(*m, inputs.seed, static_cast<std::uint64_t>(first + l), l, *s);
      synth_s[first + l] = seconds_since(t);
    }
    for (std::size_t l = count; l < kLockstepDays; ++l) s->forcing.copy_lane(0, l);
    const auto t = Clock::now();
    const std::array<DayStatistics, kLockstepDays> st = simulate_days(*m, s->forcing, options.integrator, r.lane_isa);
    const double integration_s = seconds_since(t) / static_cast<double>(count);
    for (std::size_t l = 0; l < count; ++l) {
      const std::size_t i = first + l;
      integ_s[i] = integration_s;
      DayResult& out = r.days[i];
      out.max_dynamic_tension_n = st[l].max_tension_n;
      out.slack_time_s = st[l].slack_time_s;
      out.snatch_events = st[l].snatch_events;
      const double n = static_cast<double>(st[l].samples);
      // Time mean and variance of a quantity from its sum and sum of squares over the samples.
      const auto moments = [n](double sum, double sum_sq, double& mean, double& variance) {
        mean = sum / n;
        variance = std::max(0.0, sum_sq / n - mean * mean);
      };
      moments(st[l].tension_sum_n, st[l].tension_sum_sq_n2, out.tension_mean_n, out.tension_variance_n2);
      out.extension_min_m = st[l].extension_min_m;
      out.extension_max_m = st[l].extension_max_m;
      moments(st[l].extension_sum_m, st[l].extension_sum_sq_m2, out.extension_mean_m, out.extension_variance_m2);
      substeps[i] = st[l].substeps;
    }
    if (options.progress) {
      std::lock_guard<std::mutex> lock(progress_mutex);
      for (std::size_t l = 0; l < count; ++l) options.progress(++done, days);
    }
  });
  for (int d = 0; d < days; ++d) {
    const std::size_t i = static_cast<std::size_t>(d);
    r.timings.synthesis_s += synth_s[i];
    r.timings.integration_s += integ_s[i];
    r.substeps += substeps[i];
    r.slack_fraction += r.days[i].slack_time_s;
    r.snatch_events_per_day += r.days[i].snatch_events;
  }
  r.slack_fraction /= days * m->synthesizer->plan().duration_s();
  r.snatch_events_per_day /= days;
  summarise_extension(r);

  // 7. Statistics of the daily maxima.
  auto t = Clock::now();
  std::vector<double> maxima(r.days.size());
  for (std::size_t i = 0; i < maxima.size(); ++i) maxima[i] = r.days[i].max_dynamic_tension_n;
  CaseStatistics& st = r.statistics;
  double mean = 0.0;
  for (double x : maxima) mean += x;
  mean /= static_cast<double>(maxima.size());
  double var = 0.0;
  for (double x : maxima) var += (x - mean) * (x - mean);
  var /= static_cast<double>(maxima.size() - 1);
  st.daily_max_mean_n = mean;
  st.daily_max_variance_n2 = var;
  st.max_daily_max_n = *std::max_element(maxima.begin(), maxima.end());
  const statistics::Gumbel g = statistics::fit_gumbel_moments(maxima);
  st.gumbel_u_n = g.location;
  st.gumbel_alpha_per_n = g.alpha();
  st.dynamic_999_n = g.quantile(0.999);
  st.dynamic_99_n = g.quantile(0.99);
  const auto enough = [&](double f) { return static_cast<double>(maxima.size()) >= 5.0 / (1.0 - f); };
  st.empirical_999_n = enough(0.999) ? statistics::empirical_quantile(maxima, 0.999)
                                     : std::numeric_limits<double>::quiet_NaN();
  st.empirical_99_n = enough(0.99) ? statistics::empirical_quantile(maxima, 0.99)
                                   : std::numeric_limits<double>::quiet_NaN();
  statistics::BootstrapOptions bo;
  bo.level = options.confidence_level;
  bo.replicates = options.bootstrap_replicates;
  bo.seed = inputs.seed;
  bo.num_threads = options.num_threads;
  const auto ci = statistics::bootstrap_quantile_interval(maxima, 0.999, bo);
  st.ci_level = ci.level;
  st.ci_low_n = ci.lower;
  st.ci_high_n = ci.upper;
  // The maximum-likelihood Gumbel and GEV fits are secondary (the database
  // value is the moments fit, as in the thesis): they need at least
  // kMinDaysForMlFits days, and a fit that does not converge is recorded as
  // NaN (NULL in the database) rather than failing the case.
  constexpr std::size_t kMinDaysForMlFits = 10;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  st.gumbel_ml_u_n = st.gumbel_ml_alpha_per_n = st.gev_mu_n = st.gev_sigma_n = st.gev_xi = nan;
  if (maxima.size() >= kMinDaysForMlFits) {
    try {
      const auto ml = statistics::fit_gumbel_ml(maxima);
      st.gumbel_ml_u_n = ml.distribution.location;
      st.gumbel_ml_alpha_per_n = ml.distribution.alpha();
    } catch (const NumericalError&) {
    }
    try {
      const auto gev = statistics::fit_gev_ml(maxima);
      st.gev_mu_n = gev.distribution.location;
      st.gev_sigma_n = gev.distribution.scale;
      st.gev_xi = gev.distribution.shape;
    } catch (const NumericalError&) {
    }
  }
  st.anderson_darling = statistics::anderson_darling(maxima, g);
  st.ppcc = statistics::probability_plot_correlation(maxima, g);
  r.above_breaking_strength = inputs.mean_tension_n + st.dynamic_999_n > inputs.towline.breaking_strength_n();
  r.timings.statistics_s = seconds_since(t);
  r.timings.total_s = seconds_since(start);
  return r;
}

}  // namespace towdb::simulation
