#include "towline/towline.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "common/error.hpp"
#include "common/parallel_for.hpp"

namespace towdb::towline {

const char* to_string(AboveBreakingModel model) {
  switch (model) {
    case AboveBreakingModel::kPolynomial: return "polynomial";
    case AboveBreakingModel::kStraightSpring: return "straight-spring";
  }
  return "?";
}

void TowlineFitOptions::validate() const {
  catenary.validate();
  dynamics.validate();
  excitation.validate();
  require_in_range("towline_fit.min_elements", min_elements, 4, 1 << 16);
  require_in_range("towline_fit.max_elements", max_elements, 2 * min_elements, 1 << 18);
  require_in_range("towline_fit.resolution_tolerance", resolution_tolerance, 1e-6, 0.5);
  require_in_range("towline_fit.max_run_weight_exponent", max_run_weight_exponent, 0.0, 1.0);
  require_in_range("towline_fit.small_motion_tolerance", small_motion_tolerance, 1e-6, 1.0);
  require_in_range("towline_fit.max_steps_per_period", max_steps_per_period, dynamics.steps_per_period,
                   1 << 20);
}

TowlineFit::TowlineFit(Catenary catenary, FitSummary summary, std::vector<HarmonicRun> runs)
    : catenary_(std::move(catenary)), summary_(std::move(summary)), runs_(std::move(runs)) {}

double TowlineFit::dynamic_tension_n(double xi_m, double xi_dot_m_s, AboveBreakingModel model) const {
  double tau = 0.0;
  const double xi_b = summary_.spring_onset_extension_m;
  if (model == AboveBreakingModel::kStraightSpring && xi_m > xi_b) {
    tau = polynomial_n(xi_b, xi_dot_m_s) + summary_.straight_spring_n_m * (xi_m - xi_b);
  } else {
    tau = polynomial_n(xi_m, xi_dot_m_s);
  }
  return std::max(tau, summary_.slack_limit_n);
}

namespace {

// RMS difference of two runs' tau at the same phases over the RMS of `fine`.
double relative_rms_change(const HarmonicRun& coarse, const HarmonicRun& fine) {
  double d2 = 0.0;
  double t2 = 0.0;
  for (std::size_t k = 0; k < fine.samples.size(); ++k) {
    const double d = fine.samples[k].tau_n - coarse.samples[k].tau_n;
    d2 += d * d;
    t2 += fine.samples[k].tau_n * fine.samples[k].tau_n;
  }
  return t2 > 0.0 ? std::sqrt(d2 / t2) : std::sqrt(d2);
}

// Probe runs for the resolution search: the highest frequency at its largest
// and smallest amplitude (shortest waves along the line, snap loads, the
// lightly damped linear response), the middle frequency at its largest
// amplitude and the lowest frequency at its largest (longest time steps).
std::vector<std::size_t> probe_indices(const std::vector<Excitation>& set) {
  std::vector<double> freqs;
  for (const auto& e : set) {
    if (std::find(freqs.begin(), freqs.end(), e.omega_rad_s) == freqs.end()) freqs.push_back(e.omega_rad_s);
  }
  std::sort(freqs.begin(), freqs.end());
  auto extreme = [&](double w, bool largest) {
    std::size_t best = set.size();
    for (std::size_t i = 0; i < set.size(); ++i) {
      if (set[i].omega_rad_s != w) continue;
      if (best == set.size() || (largest ? set[i].amplitude_m > set[best].amplitude_m
                                         : set[i].amplitude_m < set[best].amplitude_m)) {
        best = i;
      }
    }
    return best;
  };
  std::vector<std::size_t> probes = {extreme(freqs.back(), true), extreme(freqs.back(), false),
                                     extreme(freqs[freqs.size() / 2], true), extreme(freqs.front(), true)};
  std::sort(probes.begin(), probes.end());
  probes.erase(std::unique(probes.begin(), probes.end()), probes.end());
  return probes;
}

std::vector<HarmonicRun> run_set(const ShallowSagModel& model, const std::vector<Excitation>& set,
                                 const std::vector<std::size_t>& indices, const DynamicsOptions& options,
                                 int num_threads) {
  std::vector<HarmonicRun> out(indices.size());
  parallel_for(0, static_cast<std::int64_t>(indices.size()), num_threads, [&](std::int64_t i) {
    const auto k = static_cast<std::size_t>(i);
    const Excitation& e = set[indices[k]];
    out[k] = model.run_harmonic(e.amplitude_m, e.omega_rad_s, options);
  });
  return out;
}

// Relative RMS change between two resolutions over the probes. Runs that
// stopped after different cycle counts are compared after re-running the
// shorter one for as many cycles, so a slowly decaying start-up transient is
// not mistaken for discretisation error.
struct ProbeChange {
  double all = 0.0;       // largest over every probe
  double periodic = 0.0;  // largest over the probes periodic at both resolutions
  int not_periodic = 0;   // probes left out of `periodic`
};

ProbeChange probe_change(const ShallowSagModel& model_a, std::vector<HarmonicRun>& runs_a,
                         const DynamicsOptions& options_a, const ShallowSagModel& model_b,
                         std::vector<HarmonicRun>& runs_b, const DynamicsOptions& options_b,
                         const std::vector<Excitation>& set, const std::vector<std::size_t>& probes,
                         int num_threads) {
  std::vector<double> change(probes.size(), 0.0);
  parallel_for(0, static_cast<std::int64_t>(probes.size()), num_threads, [&](std::int64_t i) {
    const auto k = static_cast<std::size_t>(i);
    const Excitation& e = set[probes[k]];
    const int cycles = std::max(runs_a[k].cycles, runs_b[k].cycles);
    if (runs_a[k].cycles < cycles) {
      DynamicsOptions o = options_a;
      o.min_cycles = o.max_cycles = cycles;
      runs_a[k] = model_a.run_harmonic(e.amplitude_m, e.omega_rad_s, o);
    }
    if (runs_b[k].cycles < cycles) {
      DynamicsOptions o = options_b;
      o.min_cycles = o.max_cycles = cycles;
      runs_b[k] = model_b.run_harmonic(e.amplitude_m, e.omega_rad_s, o);
    }
    change[k] = relative_rms_change(runs_a[k], runs_b[k]);
  });
  ProbeChange c;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    c.all = std::max(c.all, change[k]);
    if (runs_a[k].periodic && runs_b[k].periodic) {
      c.periodic = std::max(c.periodic, change[k]);
    } else {
      ++c.not_periodic;
    }
  }
  return c;
}

// The resolution search's second criterion (EQ-TOWLINE-15): the first
// comparison at which the probes that reached a periodic state at both
// resolutions agree, provided some did and some did not. `Resolution` is the
// coarser side of that comparison (elements, or the dynamics options).
template <typename Resolution>
struct PeriodicFallback {
  bool found = false;
  Resolution resolution{};
  double change = 0.0;
  int left_out = 0;
  void consider(const ProbeChange& c, const Resolution& coarser, std::size_t probes, double tolerance) {
    if (!found && c.not_periodic > 0 && static_cast<std::size_t>(c.not_periodic) < probes &&
        c.periodic <= tolerance) {
      found = true;
      resolution = coarser;
      change = c.periodic;
      left_out = c.not_periodic;
    }
  }
};

// EQ-TOWLINE-16: one weight per sample, (rms_max / rms_run)^exponent, where
// rms_run is the RMS tau of the sample's run; a run with no tension at all
// (rms 0) gets the weight of the smallest non-zero one.
std::vector<double> run_weights(const std::vector<HarmonicRun>& runs, double exponent) {
  std::vector<double> rms(runs.size(), 0.0);
  double rms_max = 0.0;
  double rms_min = std::numeric_limits<double>::infinity();
  for (std::size_t r = 0; r < runs.size(); ++r) {
    double sum = 0.0;
    for (const auto& q : runs[r].samples) sum += q.tau_n * q.tau_n;
    if (!runs[r].samples.empty()) rms[r] = std::sqrt(sum / static_cast<double>(runs[r].samples.size()));
    rms_max = std::max(rms_max, rms[r]);
    if (rms[r] > 0.0) rms_min = std::min(rms_min, rms[r]);
  }
  std::vector<double> weights;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const double own = rms[r] > 0.0 ? rms[r] : rms_min;
    const double weight = exponent == 0.0 || !(own > 0.0) ? 1.0 : std::pow(rms_max / own, exponent);
    weights.insert(weights.end(), runs[r].samples.size(), weight);
  }
  return weights;
}

struct SmallMotionChoice {
  PolynomialFit fit;
  double exponent = 0.0;
  double ratio = 0.0;  // EQ-TOWLINE-17 over k_s A
};

// EQ-TOWLINE-16: the least-squares fit subject to |ratio - 1| <= tolerance.
//  1. The plain fit (a10 free, e = 0), kept when it meets the tolerance.
//  2. Else, for e = 0, 0.25, ... up to the maximum: the free fit with those
//     weights, kept if it meets it; else, if the fit with a10 held at k_s
//     does, a10 is moved from k_s toward the free fit's value as far as the
//     tolerance allows (bisection), so that the slope departs from what the
//     runs ask only as much as the limit needs.
//  3. If no weight meets it, the held fit closest to it.
// Without hold_static_stiffness: the plain fit (t3fer97).
SmallMotionChoice fit_small_motion(const std::vector<TensionSample>& samples, const std::vector<HarmonicRun>& runs,
                                   double static_stiffness_n_m, double max_dynamic_n, double min_dynamic_n,
                                   const TowlineFitOptions& options) {
  constexpr double kExponentStep = 0.25;
  constexpr int kBisections = 30;  // a10 to 1e-9 of |k_s - free a10|
  const double tol = options.small_motion_tolerance;
  // One weight vector per exponent, shared by its free, held and bisection fits.
  auto fit_with = [&](double exponent, const std::vector<double>& weights, double a10) {
    SmallMotionFit small;
    small.weights = weights;
    small.fixed_a10_n_m = a10;
    SmallMotionChoice c;
    c.fit = fit_polynomial(samples, max_dynamic_n, min_dynamic_n, options.slack_fit, small);
    c.exponent = exponent;
    c.ratio = small_motion_ratio(c.fit.coefficients, static_stiffness_n_m);
    return c;
  };
  auto meets = [&](const SmallMotionChoice& c) { return std::abs(c.ratio - 1.0) <= tol; };
  const double free_a10 = std::numeric_limits<double>::quiet_NaN();
  SmallMotionChoice plain = fit_with(0.0, {}, free_a10);  // no weights: all 1
  if (meets(plain) || !options.hold_static_stiffness) return plain;
  std::optional<SmallMotionChoice> best;
  for (int k = 0;; ++k) {
    const double exponent = std::min(k * kExponentStep, options.max_run_weight_exponent);
    const std::vector<double> weights = run_weights(runs, exponent);
    const SmallMotionChoice free_fit = k == 0 ? plain : fit_with(exponent, weights, free_a10);
    if (meets(free_fit)) return free_fit;
    SmallMotionChoice held = fit_with(exponent, weights, static_stiffness_n_m);
    if (meets(held)) {
      double lo = 0.0, hi = 1.0;  // fraction of the way from k_s to the free a10
      for (int i = 0; i < kBisections; ++i) {
        const double mid = 0.5 * (lo + hi);
        const double a10 = static_stiffness_n_m + mid * (free_fit.fit.coefficients.a10() - static_stiffness_n_m);
        SmallMotionChoice c = fit_with(exponent, weights, a10);
        if (meets(c)) {
          lo = mid;
          held = std::move(c);
        } else {
          hi = mid;
        }
      }
      return held;
    }
    if (!best || std::abs(held.ratio - 1.0) < std::abs(best->ratio - 1.0)) best = held;
    if (exponent >= options.max_run_weight_exponent) return *best;
  }
}

}  // namespace

std::vector<RunDamping> run_damping(const TowlineFit& fit) {
  std::vector<RunDamping> out;
  for (const HarmonicRun& run : fit.runs()) {
    const std::size_t n = run.samples.size();
    if (run.amplitude_m <= 0.0 || n == 0) continue;
    const double dt_s = 2.0 * std::numbers::pi / run.omega_rad_s / static_cast<double>(n);
    double cable_j = 0.0, polynomial_j = 0.0;  // energy dissipated over the cycle
    for (const TensionSample& p : run.samples) {
      cable_j += p.tau_n * p.xi_dot_m_s * dt_s;
      polynomial_j += fit.dynamic_tension_n(p.xi_m, p.xi_dot_m_s, AboveBreakingModel::kPolynomial) * p.xi_dot_m_s * dt_s;
    }
    const double norm = std::numbers::pi * run.omega_rad_s * run.amplitude_m * run.amplitude_m;
    out.push_back({run.omega_rad_s, run.amplitude_m, cable_j / norm, polynomial_j / norm, run.slack_fraction});
  }
  return out;
}

double small_motion_ratio(const PolynomialCoefficients& c, double static_stiffness_n_m) {
  return first_harmonic_n(c, kSmallMotionAmplitudeM, 2.0 * std::numbers::pi / kSmallMotionPeriodS) /
         (static_stiffness_n_m * kSmallMotionAmplitudeM);
}

std::shared_ptr<const TowlineFit> build_towline_fit(const model::Towline& towline,
                                                    const TowPoints& points, double mean_tension_n,
                                                    const TowlineFitOptions& options) {
  options.validate();
  model::validate(towline);
  const double breaking_n = towline.breaking_strength_n();
  require_input(mean_tension_n > 0.0 && mean_tension_n < breaking_n, "mean towline tension [N]",
                mean_tension_n, "must be > 0 and below the breaking strength " + format_value(breaking_n) + " N");
  Catenary cat = Catenary::solve(towline, points, mean_tension_n, options.catenary);
  const std::vector<Excitation> set = excitation_set(options.excitation);

  // Spatial resolution: probe runs at N and 2N elements until they agree;
  // the coarser N is used, so the change is an estimate of its error.
  const std::vector<std::size_t> probes = probe_indices(set);
  DynamicsOptions dyn = options.dynamics;
  int n = options.min_elements;
  auto model = std::make_unique<ShallowSagModel>(cat, n);
  std::vector<HarmonicRun> probe_runs = run_set(*model, set, probes, dyn, options.num_threads);
  double space_change = 0.0;
  int left_out = 0;
  PeriodicFallback<int> space_fallback;
  for (int iteration = 1;; ++iteration) {
    if (2 * n > options.max_elements) {
      if (!space_fallback.found) {
        throw NumericalError("shallow-sag spatial resolution search: no convergence up to " +
                             std::to_string(n) + " elements (iteration " + std::to_string(iteration) +
                             ", residual RMS change " + format_value(space_change) + ")");
      }
      n = space_fallback.resolution;
      model = std::make_unique<ShallowSagModel>(cat, n);
      probe_runs = run_set(*model, set, probes, dyn, options.num_threads);
      space_change = space_fallback.change;
      left_out = space_fallback.left_out;
      break;
    }
    auto finer = std::make_unique<ShallowSagModel>(cat, 2 * n);
    std::vector<HarmonicRun> finer_runs = run_set(*finer, set, probes, dyn, options.num_threads);
    const ProbeChange c = probe_change(*model, probe_runs, dyn, *finer, finer_runs, dyn, set, probes,
                                       options.num_threads);
    space_change = c.all;
    if (space_change <= options.resolution_tolerance) break;
    space_fallback.consider(c, n, probes.size(), options.resolution_tolerance);
    n *= 2;
    model = std::move(finer);
    probe_runs = std::move(finer_runs);
  }

  // Time resolution (implicit integrator): halve dt until the probes agree;
  // again the coarser step is used. The explicit integrator's step is set by
  // stability and needs no search.
  double time_change = 0.0;
  if (dyn.integrator == Integrator::kImplicitTrapezoidal) {
    PeriodicFallback<DynamicsOptions> time_fallback;
    for (int iteration = 1;; ++iteration) {
      DynamicsOptions half = dyn;
      half.steps_per_period *= 2;
      half.steps_per_line_period *= 2;
      if (half.steps_per_period > options.max_steps_per_period) {
        if (!time_fallback.found) {
          throw NumericalError("shallow-sag time resolution search: no convergence up to " +
                               std::to_string(dyn.steps_per_period) + " steps per period (iteration " +
                               std::to_string(iteration) + ", residual RMS change " +
                               format_value(time_change) + ")");
        }
        dyn = time_fallback.resolution;
        probe_runs = run_set(*model, set, probes, dyn, options.num_threads);
        time_change = time_fallback.change;
        left_out = std::max(left_out, time_fallback.left_out);
        break;
      }
      std::vector<HarmonicRun> half_runs = run_set(*model, set, probes, half, options.num_threads);
      const ProbeChange c = probe_change(*model, probe_runs, dyn, *model, half_runs, half, set, probes,
                                         options.num_threads);
      time_change = c.all;
      if (time_change <= options.resolution_tolerance) break;
      time_fallback.consider(c, dyn, probes.size(), options.resolution_tolerance);
      dyn = half;
      probe_runs = std::move(half_runs);
    }
  }

  // All runs at the accepted resolution; the probes are reused.
  std::vector<std::size_t> rest;
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (std::find(probes.begin(), probes.end(), i) == probes.end()) rest.push_back(i);
  }
  std::vector<HarmonicRun> rest_runs = run_set(*model, set, rest, dyn, options.num_threads);
  std::vector<HarmonicRun> runs(set.size());
  for (std::size_t k = 0; k < probes.size(); ++k) runs[probes[k]] = std::move(probe_runs[k]);
  for (std::size_t k = 0; k < rest.size(); ++k) runs[rest[k]] = std::move(rest_runs[k]);

  std::vector<TensionSample> samples;
  FitSummary s;
  s.min_dt_s = std::numeric_limits<double>::infinity();
  for (const auto& r : runs) {
    samples.insert(samples.end(), r.samples.begin(), r.samples.end());
    s.runs_not_periodic += r.periodic ? 0 : 1;
    s.min_dt_s = std::min(s.min_dt_s, r.min_dt_s);
    s.max_dt_s = std::max(s.max_dt_s, r.max_dt_s);
  }
  const SmallMotionChoice chosen =
      fit_small_motion(samples, runs, cat.static_stiffness_n_m(), breaking_n - mean_tension_n,
                       model->tension_floor_n(), options);
  const PolynomialFit& fit = chosen.fit;

  // EQ-TOWLINE-13: static extension at which H reaches breaking strength.
  const Catenary at_break = Catenary::solve(towline, points, breaking_n, options.catenary);

  s.mean_tension_n = mean_tension_n;
  s.breaking_strength_n = breaking_n;
  s.unstretched_length_m = cat.unstretched_length_m();
  s.span_m = cat.span_m();
  s.chord_m = cat.chord_m();
  s.sag_m = cat.sag_m();
  s.lowest_elevation_m = cat.lowest_elevation_m();
  s.tug_angle_rad = cat.tug_angle_rad();
  s.tow_angle_rad = cat.tow_angle_rad();
  s.tug_tension_n = cat.tug_tension_n();
  s.tow_tension_n = cat.tow_tension_n();
  s.static_stiffness_n_m = cat.static_stiffness_n_m();
  s.dynamic_static_stiffness_n_m = model->quasi_static_stiffness_n_m();
  s.straight_spring_n_m = 1.0 / cat.axial_compliance_m_n();
  s.spring_onset_extension_m = at_break.chord_m() - cat.chord_m();
  s.slack_limit_n = model->tension_floor_n();
  s.coefficients = fit.coefficients;
  s.fit_rms_error_n = fit.rms_error_n;
  s.fit_max_error_n = fit.max_error_n;
  s.rms_tension_n = fit.rms_tension_n;
  s.small_motion_ratio = chosen.ratio;
  s.run_weight_exponent = chosen.exponent;
  s.samples_used = fit.samples_used;
  s.samples_excluded = fit.samples_excluded;
  for (const TensionSample& x : samples) {
    if (x.tau_n > breaking_n - mean_tension_n) continue;
    s.fit_xi_min_m = std::min(s.fit_xi_min_m, x.xi_m);
    s.fit_xi_max_m = std::max(s.fit_xi_max_m, x.xi_m);
    s.fit_xi_dot_max_m_s = std::max(s.fit_xi_dot_max_m_s, std::abs(x.xi_dot_m_s));
  }
  s.n_elements = model->n_elements();
  s.steps_per_period = dyn.integrator == Integrator::kImplicitTrapezoidal ? dyn.steps_per_period : 0;
  s.steps_per_line_period = dyn.integrator == Integrator::kImplicitTrapezoidal ? dyn.steps_per_line_period : 0;
  s.space_resolution_change = space_change;
  s.time_resolution_change = time_change;
  s.resolution_probes_left_out = left_out;
  s.runs = static_cast<int>(runs.size());
  return std::make_shared<const TowlineFit>(std::move(cat), s, std::move(runs));
}

namespace {

void append_bits(std::string& key, double x) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  key.append(reinterpret_cast<const char*>(&bits), sizeof bits);
}

std::string cache_key(const model::Towline& towline, const TowPoints& points, double mean_tension_n,
                      const TowlineFitOptions& o) {
  std::string key;
  append_bits(key, static_cast<double>(towline.segments.size()));
  for (const auto& seg : towline.segments) {
    const auto& c = seg.component;
    for (double x : {seg.length_m, c.ea_n, c.hydrodynamic_diameter_m, c.mass_per_length_kg_m,
                     c.weight_in_water_n_m, c.breaking_strength_n, c.drag_coefficient_normal,
                     c.added_mass_coefficient}) {
      append_bits(key, x);
    }
  }
  for (double x : {points.tug_height_m, points.tow_height_m, mean_tension_n, o.catenary.closure_tolerance,
                   static_cast<double>(o.catenary.max_iterations),
                   static_cast<double>(o.dynamics.samples_per_period),
                   static_cast<double>(o.dynamics.ramp_cycles), static_cast<double>(o.dynamics.min_cycles),
                   static_cast<double>(o.dynamics.max_cycles), o.dynamics.periodicity_tolerance,
                   o.dynamics.courant_target, o.dynamics.courant_limit, o.excitation.max_amplitude_m,
                   o.excitation.max_velocity_m_s, static_cast<double>(o.min_elements),
                   static_cast<double>(o.dynamics.integrator == Integrator::kImplicitTrapezoidal),
                   static_cast<double>(o.dynamics.steps_per_period),
                   static_cast<double>(o.dynamics.steps_per_line_period), o.dynamics.newton_tolerance,
                   static_cast<double>(o.dynamics.newton_max_iterations),
                   static_cast<double>(o.max_steps_per_period),
                   static_cast<double>(o.slack_fit == SlackFit::kOneSided),
                   static_cast<double>(o.max_elements), o.resolution_tolerance,
                   static_cast<double>(o.hold_static_stiffness), o.max_run_weight_exponent,
                   o.small_motion_tolerance}) {
    append_bits(key, x);
  }
  append_bits(key, static_cast<double>(o.excitation.frequencies_rad_s.size()));
  for (double x : o.excitation.frequencies_rad_s) append_bits(key, x);
  append_bits(key, static_cast<double>(o.excitation.amplitude_fractions.size()));
  for (double x : o.excitation.amplitude_fractions) append_bits(key, x);
  // num_threads is left out: results do not depend on it.
  return key;
}

}  // namespace

std::shared_ptr<const TowlineFit> TowlineFitCache::get(const model::Towline& towline,
                                                       const TowPoints& points, double mean_tension_n,
                                                       const TowlineFitOptions& options) {
  const std::string key = cache_key(towline, points, mean_tension_n, options);
  std::promise<std::shared_ptr<const TowlineFit>> promise;
  Future future;
  bool owner = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = entries_.find(key);
    if (it != entries_.end()) {
      future = it->second;
    } else {
      future = promise.get_future().share();
      entries_.emplace(key, future);
      ++builds_;
      owner = true;
    }
  }
  if (owner) {
    try {
      promise.set_value(build_towline_fit(towline, points, mean_tension_n, options));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return future.get();
}

std::size_t TowlineFitCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

std::size_t TowlineFitCache::builds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return builds_;
}

void TowlineFitCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.clear();
}

TowlineFitCache& global_fit_cache() {
  static TowlineFitCache cache;
  return cache;
}

}  // namespace towdb::towline
