// Analytic tests of the surge integrator (generator/simulation/surge.hpp).
//   surge-1  linear line, harmonic force on the tug: the steady dynamic tension
//            amplitude equals the closed-form 2-DOF frequency response.
//   surge-2  step-size convergence: halving the forcing interval changes the
//            maximum by less than the RK4 error bound.
//   surge-3  a slack-prone bilinear line: slack time and snatch events counted.
//   surge-4  integrate_days (lock step) equals integrate_day on each day alone,
//            bit for bit, also when the days need different substep counts,
//            with the baseline vectors and with AVX2's (where the processor
//            has it).
//   surge-5  a tension peak halfway between two steps (EQ-SURGE-5): the
//            samples read it low by 1 - cos(w h / 2); the maximum does not.
//   surge-6  EQ-SURGE-6 (non-surge tension linear, added): equals EQ-SURGE-4
//            for a linear line; with immovable vessels on a cubic line the
//            tension is k_ns xi_ns exactly, clamped at -T.
//   surge-7  the extension statistics read the tension law's argument at the
//            forcing samples: with immovable vessels it is xi_ns, sample for
//            sample (and 0 under EQ-SURGE-6, whose law sees the surge part);
//            on a linear spring without dashpot it is the sampled tension / k.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "simulation/surge.hpp"
#include "test_support.hpp"

namespace towdb::simulation {
namespace {

// A linear spring-dashpot line, slack below -T.
// (Tension laws are templates on the number type: the integrator's lock-step
// path evaluates them on vector lanes, surge.hpp.)
struct LinearLine {
  static constexpr bool kForcedInline = true;  // its templates are TOWDB_SURGE_INLINE
  double k = 0.0, c = 0.0, mean = 0.0;
  template <typename T>
  TOWDB_SURGE_INLINE T tension(T xi, T xi_dot) const {
    return lanes::max(lanes::splat<T>(-mean), k * xi + c * xi_dot);
  }
  template <typename T>
  TOWDB_SURGE_INLINE T stiffness(T, T) const {
    return lanes::splat<T>(k);
  }
  template <typename T>
  TOWDB_SURGE_INLINE T damping(T, T) const {
    return lanes::splat<T>(c);
  }
  double mean_tension_n() const { return mean; }
};

SurgeParameters tug_and_tow() {
  SurgeParameters p;
  p.tug_mass_kg = 2.5e6;  // about a T-ATF 166 with surge added mass
  p.tow_mass_kg = 1.0e7;  // a frigate-sized tow
  p.tug_damping_n_s_m = 6.0e4;
  p.tow_damping_n_s_m = 1.5e5;
  p.cos_alpha_tug = 0.95;
  p.cos_alpha_tow = 0.98;
  return p;
}

DayForcing harmonic_tug_force(double amplitude_n, double omega_rad_s, double dt_s, std::size_t n) {
  DayForcing f;
  f.dt_s = dt_s;
  for (std::size_t i = 0; i < n; ++i) {
    f.tug_force_n.push_back(amplitude_n * std::cos(omega_rad_s * static_cast<double>(i) * dt_s));
  }
  f.tow_force_n.assign(n, 0.0);
  f.xi_ns_m.assign(n, 0.0);
  f.xi_ns_dot_m_s.assign(n, 0.0);
  return f;
}

// Closed-form amplitude of tau for EQ-SURGE-1..4 with a linear line:
// [-w^2 M + i w (B + c s s^T) + k s s^T] X = F e1, s = (c1, -c2), tau = (k + i w c) s.X.
std::complex<double> linear_tension(const SurgeParameters& p, const LinearLine& line, double force_n, double w) {
  using C = std::complex<double>;
  const double s1 = p.cos_alpha_tug, s2 = -p.cos_alpha_tow;
  const C kc(line.k, w * line.c);
  const C a11 = -w * w * p.tug_mass_kg + C(0, w * p.tug_damping_n_s_m) + kc * s1 * s1;
  const C a22 = -w * w * p.tow_mass_kg + C(0, w * p.tow_damping_n_s_m) + kc * s2 * s2;
  const C a12 = kc * s1 * s2;
  const C det = a11 * a22 - a12 * a12;
  const C x1 = a22 * force_n / det, x7 = -a12 * force_n / det;
  return kc * (s1 * x1 + s2 * x7);
}

double linear_tension_amplitude(const SurgeParameters& p, const LinearLine& line, double force_n, double w) {
  return std::abs(linear_tension(p, line, force_n, w));
}

TEST(SurgeIntegrator, LinearHarmonicResponseMatchesClosedForm) {  // surge-1, EVIDENCE-OF: EQ-SURGE-1..4
  const SurgeParameters p = tug_and_tow();
  const LinearLine line{4.0e5, 2.0e4, 1.0e9};  // a wire-like 400 kN/m, never slack
  const double w = 2.0 * kPi / 20.0;           // 20 s period, 50 periods in the record
  const DayForcing f = harmonic_tug_force(1.0e5, w, 0.25, 4000);
  IntegratorOptions o;
  o.warmup_s = 3000.0;  // the slowest mode decays as exp(-(B1+B7)/(M1+M7) t): e^-40 after 3000 s
  const DayStatistics s = integrate_day(p, f, line, o);
  const double expected = linear_tension_amplitude(p, line, 1.0e5, w);
  // The minimum is sampled every h <= 0.25 s of a 20 s period: it misses the trough by at most
  // 1 - cos(pi/80) = 0.08 %. (The maximum is read between steps, EQ-SURGE-5.)
  constexpr double kPeakSamplingRelTol = 1.5e-3;
  EXPECT_REL_CLOSE(s.max_tension_n, expected, kPeakSamplingRelTol);
  EXPECT_REL_CLOSE(-s.min_tension_n, expected, kPeakSamplingRelTol);
  EXPECT_EQ(s.snatch_events, 0);
  EXPECT_EQ(s.slack_time_s, 0.0);
}

TEST(SurgeIntegrator, ResonanceNearTheRelativeModeIsResolved) {  // surge-1 at resonance
  const SurgeParameters p = tug_and_tow();
  const LinearLine line{4.0e5, 2.0e4, 1.0e9};
  // Relative-mode natural frequency sqrt(k (c1^2/M1 + c2^2/M7)) = 0.419 rad/s; force near it.
  const double w_n = std::sqrt(line.k * (0.95 * 0.95 / 2.5e6 + 0.98 * 0.98 / 1.0e7));
  const double period = 2.0 * kPi / w_n;
  const double dt = period / 40.0;
  const DayForcing f = harmonic_tug_force(1.0e5, 2.0 * kPi / (40.0 * dt), dt, 40 * 60);
  IntegratorOptions o;
  o.warmup_s = 4000.0;
  const DayStatistics s = integrate_day(p, f, line, o);
  const double expected = linear_tension_amplitude(p, line, 1.0e5, 2.0 * kPi / (40.0 * dt));
  constexpr double kResonantRelTol = 3e-3;  // peak sampling (0.3 %) at 40 samples per period
  EXPECT_REL_CLOSE(s.max_tension_n, expected, kResonantRelTol);
  EXPECT_GT(expected, 3.0 * 1.0e5);  // it really is resonant: dynamic amplification
}

// A cubic-stiffening line (snap-like), slack below -2e5 N.
struct CubicLine {
  static constexpr bool kForcedInline = true;  // its templates are TOWDB_SURGE_INLINE
  double cubic_n_m3 = 1.0e5;
  template <typename T>
  TOWDB_SURGE_INLINE T tension(T xi, T xi_dot) const {
    return lanes::max(lanes::splat<T>(-2.0e5), 3.0e5 * xi + cubic_n_m3 * xi * xi * xi + 1.0e4 * xi_dot);
  }
  template <typename T>
  TOWDB_SURGE_INLINE T stiffness(T xi, T) const {
    return 3.0e5 + 3.0 * cubic_n_m3 * xi * xi;
  }
  template <typename T>
  TOWDB_SURGE_INLINE T damping(T, T) const {
    return lanes::splat<T>(1.0e4);
  }
  double mean_tension_n() const { return 2.0e5; }
};

// The same line without kForcedInline: it never runs on the AVX2 path.
struct UnmarkedCubicLine {
  CubicLine line;
  template <typename T>
  TOWDB_SURGE_INLINE T tension(T xi, T xi_dot) const {
    return line.tension(xi, xi_dot);
  }
  template <typename T>
  TOWDB_SURGE_INLINE T stiffness(T xi, T xi_dot) const {
    return line.stiffness(xi, xi_dot);
  }
  template <typename T>
  TOWDB_SURGE_INLINE T damping(T xi, T xi_dot) const {
    return line.damping(xi, xi_dot);
  }
  double mean_tension_n() const { return line.mean_tension_n(); }
};

TEST(SurgeIntegrator, ConvergesWithForcingInterval) {  // surge-2
  // The cubic line driven by two harmonics.
  const SurgeParameters p = tug_and_tow();
  auto run = [&](double dt, std::vector<double>* trace) {
    const std::size_t n = static_cast<std::size_t>(std::llround(1200.0 / dt));
    DayForcing f = harmonic_tug_force(3.0e4, 2.0 * kPi / 30.0, dt, n);
    for (std::size_t i = 0; i < n; ++i) {
      f.xi_ns_m[i] = 0.3 * std::sin(2.0 * kPi / 10.0 * static_cast<double>(i) * dt);
      f.xi_ns_dot_m_s[i] = 0.3 * 2.0 * kPi / 10.0 * std::cos(2.0 * kPi / 10.0 * static_cast<double>(i) * dt);
    }
    IntegratorOptions o;
    o.warmup_s = 2400.0;
    return integrate_day(p, f, CubicLine{}, o, trace);
  };
  std::vector<double> coarse, fine, finest;
  run(0.5, &coarse);
  run(0.25, &fine);
  const DayStatistics s = run(0.125, &finest);
  // Compare tau at the common times t = k 0.5 s: trace[k] = tau(k dt).
  double d_coarse = 0.0, d_fine = 0.0;
  for (std::size_t k = 0; k < coarse.size(); ++k) {
    d_coarse = std::max(d_coarse, std::abs(coarse[k] - finest[4 * k]));
    d_fine = std::max(d_fine, std::abs(fine[2 * k] - finest[4 * k]));
  }
  // Fourth-order convergence would shrink the error 16-fold per halving; ask for 4-fold.
  EXPECT_LT(d_fine, 0.25 * d_coarse);
  constexpr double kConvergedRelTol = 1e-3;  // of the day's largest tension
  EXPECT_LT(d_fine, kConvergedRelTol * s.max_tension_n);
}

TEST(SurgeIntegrator, SlackLineCountsSlackTimeAndSnatches) {  // surge-3
  // Immovable vessels (huge masses): xi = xi_ns exactly, tau = max(-T, k xi).
  SurgeParameters p = tug_and_tow();
  p.tug_mass_kg = p.tow_mass_kg = 1e18;
  const LinearLine line{4.0e5, 0.0, 5.0e4};
  const double dt = 0.05;
  const std::size_t n = 20000;  // 1000 s, 50 periods of 20 s
  DayForcing f = harmonic_tug_force(0.0, 1.0, dt, n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    f.xi_ns_m[i] = 1.0 * std::sin(2.0 * kPi / 20.0 * t);
    f.xi_ns_dot_m_s[i] = 1.0 * 2.0 * kPi / 20.0 * std::cos(2.0 * kPi / 20.0 * t);
  }
  IntegratorOptions o;
  o.warmup_s = 100.0;
  const DayStatistics s = integrate_day(p, f, line, o);
  EXPECT_NEAR(s.min_tension_n, -5.0e4, 1e-6);  // clamped at -T
  EXPECT_REL_CLOSE(s.max_tension_n, 4.0e5, 1e-4);
  EXPECT_EQ(s.snatch_events, 50);  // one slack-to-taut transition per cycle
  // Slack while sin(w t) < -T/k = -0.125: a fraction 1/2 - asin(0.125)/pi = 0.46009 of the time.
  const double expected_slack_s = 1000.0 * (0.5 - std::asin(0.125) / kPi);
  constexpr double kSlackTimeAbsTol_s = 50 * 2 * 0.05;  // one substep of error at each of 100 crossings
  EXPECT_ABS_CLOSE(s.slack_time_s, expected_slack_s, kSlackTimeAbsTol_s);
}

TEST(SurgeIntegrator, LockStepDaysEqualSingleDaysBitForBit) {  // surge-4
  // A stiffer cubic line: the substep count grows with the extension, so
  // days with different forcing amplitudes need substeps on different
  // intervals (the lock-step path falls back to day-by-day there).
  const CubicLine line{1.0e6};
  const SurgeParameters p = tug_and_tow();
  const double dt = 0.5;
  const std::size_t n = 2000;
  std::array<DayForcing, 4> f;
  for (std::size_t l = 0; l < f.size(); ++l) {
    const double scale = 0.2 + 0.6 * static_cast<double>(l);  // the largest days need substeps
    f[l] = harmonic_tug_force(3.0e4 * scale, 2.0 * kPi / 30.0, dt, n);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) * dt;
      const double w = 2.0 * kPi / (9.0 + static_cast<double>(l));  // each day its own period
      f[l].xi_ns_m[i] = scale * std::sin(w * t);
      f[l].xi_ns_dot_m_s[i] = scale * w * std::cos(w * t);
    }
  }
  IntegratorOptions o;
  o.warmup_s = 600.0;
  std::array<std::vector<double>, 4> lockstep_trace, single_trace;
  LockstepForcing<4> lockstep;
  lockstep.dt_s = dt;
  lockstep.resize(n);
  for (std::size_t l = 0; l < f.size(); ++l) lockstep.set_day(l, f[l]);
  std::vector<LaneIsa> paths{LaneIsa::kBaseline};
  if (fastest_lane_isa() != LaneIsa::kBaseline) paths.push_back(fastest_lane_isa());
  std::array<DayStatistics, 4> together;
  long substeps_min = std::numeric_limits<long>::max(), substeps_max = 0;
  for (const LaneIsa isa : paths) {
    SCOPED_TRACE(lane_isa_name(isa));
    together = integrate_days_fastest<CubicLine>(
        p, lockstep, line, o, {&lockstep_trace[0], &lockstep_trace[1], &lockstep_trace[2], &lockstep_trace[3]},
        isa);
    for (std::size_t l = 0; l < f.size(); ++l) {
      const DayStatistics alone = integrate_day(p, f[l], line, o, &single_trace[l]);
      const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };  // also tells -0 from +0
      EXPECT_EQ(bits(together[l].max_tension_n), bits(alone.max_tension_n)) << "day " << l;
      EXPECT_EQ(bits(together[l].min_tension_n), bits(alone.min_tension_n)) << "day " << l;
      EXPECT_EQ(bits(together[l].slack_time_s), bits(alone.slack_time_s)) << "day " << l;
      EXPECT_EQ(together[l].snatch_events, alone.snatch_events) << "day " << l;
      EXPECT_EQ(together[l].substeps, alone.substeps) << "day " << l;
      EXPECT_EQ(together[l].samples, alone.samples) << "day " << l;
      EXPECT_EQ(bits(together[l].tension_sum_n), bits(alone.tension_sum_n)) << "day " << l;
      EXPECT_EQ(bits(together[l].tension_sum_sq_n2), bits(alone.tension_sum_sq_n2)) << "day " << l;
      EXPECT_EQ(bits(together[l].extension_min_m), bits(alone.extension_min_m)) << "day " << l;
      EXPECT_EQ(bits(together[l].extension_max_m), bits(alone.extension_max_m)) << "day " << l;
      EXPECT_EQ(bits(together[l].extension_sum_m), bits(alone.extension_sum_m)) << "day " << l;
      EXPECT_EQ(bits(together[l].extension_sum_sq_m2), bits(alone.extension_sum_sq_m2)) << "day " << l;
      ASSERT_EQ(lockstep_trace[l].size(), single_trace[l].size());
      for (std::size_t i = 0; i < single_trace[l].size(); ++i) {
        ASSERT_EQ(bits(lockstep_trace[l][i]), bits(single_trace[l][i])) << "day " << l << " sample " << i;
      }
      substeps_min = std::min(substeps_min, alone.substeps);
      substeps_max = std::max(substeps_max, alone.substeps);
    }
  }
  if (paths.size() == 1) std::printf("surge-4: this processor has no AVX2; only the baseline vectors were compared\n");
  // The paths taken: AVX2 only for a law that declares its templates forced
  // inline; the unmarked law gets the baseline vectors, with the same bits.
  EXPECT_EQ(lane_isa_for<CubicLine>(LaneIsa::kAvx2), fastest_lane_isa());
  EXPECT_EQ(lane_isa_for<CubicLine>(LaneIsa::kBaseline), LaneIsa::kBaseline);
  EXPECT_EQ(lane_isa_for<UnmarkedCubicLine>(LaneIsa::kAvx2), LaneIsa::kBaseline);
  const auto unmarked = integrate_days_fastest(p, lockstep, UnmarkedCubicLine{line}, o, {}, LaneIsa::kAvx2);
  for (std::size_t l = 0; l < f.size(); ++l) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(unmarked[l].max_tension_n),
              std::bit_cast<std::uint64_t>(together[l].max_tension_n))
        << "day " << l;
  }
  // The premise: the days really took different paths (one step per interval
  // for the smallest, substeps for the largest, with and without slack).
  EXPECT_EQ(substeps_min, static_cast<long>(n + 1200));  // + 600 s of warm-up
  EXPECT_GT(substeps_max, substeps_min);
  EXPECT_EQ(together[0].slack_time_s, 0.0);
  EXPECT_GT(together[3].slack_time_s, 0.0);
}

TEST(SurgeIntegrator, PeakBetweenStepsIsRead) {  // surge-5, EVIDENCE-OF: EQ-SURGE-5
  // A soft line (relative mode 0.13 rad/s: one RK4 step per 2.5 s sample,
  // omega h = 0.33 < max_omega_h) and a tug force of period 8 dt = 20 s,
  // phased so that every tension crest falls halfway between two samples.
  const SurgeParameters p = tug_and_tow();
  const LinearLine line{4.0e4, 2.0e3, 1.0e9};
  const double dt = 2.5, w = 2.0 * kPi / (8.0 * dt);
  const std::complex<double> tension = linear_tension(p, line, 1.0e5, w);
  const double psi = -std::arg(tension) - w * 0.5 * dt;  // crest at t = dt/2 (mod dt)
  const std::size_t n = 8 * 50;
  DayForcing f = harmonic_tug_force(0.0, w, dt, n);
  for (std::size_t i = 0; i < n; ++i) f.tug_force_n[i] = 1.0e5 * std::cos(w * static_cast<double>(i) * dt + psi);
  IntegratorOptions o;
  o.warmup_s = 3000.0;  // the slowest mode decays as exp(-(B1+B7)/(M1+M7) t): e^-50 after 3000 s
  std::vector<double> trace;
  const DayStatistics s = integrate_day(p, f, line, o, &trace);
  ASSERT_EQ(s.substeps, static_cast<long>(n + 1200));  // the premise: one step per sample
  const double amplitude = std::abs(tension);
  const double sampled = *std::max_element(trace.begin(), trace.end());
  // Both read the integrated response, which is low by the forcing's
  // Catmull-Rom midpoint ((9 cos(wh/2) - cos(3wh/2)) / 8 = 0.9915 of the
  // crest at w h = 0.79) and RK4's own amplitude error.
  constexpr double kIntegrationRelTol = 1e-2;
  EXPECT_REL_CLOSE(s.max_tension_n, amplitude, kIntegrationRelTol);
  // The samples straddle the crests and read cos(w dt / 2) = 0.924 of the
  // maximum; the dense-output midpoint is within (w h)^4 / 384 = 0.1 % of it.
  constexpr double kDenseOutputRelTol = 2e-3;
  EXPECT_REL_CLOSE(sampled / s.max_tension_n, std::cos(0.5 * w * dt), kDenseOutputRelTol);
  EXPECT_LT(sampled, 0.93 * amplitude);  // the premise: sampling alone misses 7 %

  // The gate (kPeakGateFraction): with a mean tension of 1e5 N the troughs lie
  // more than 20 % of T + max below the maximum and are not refined; the
  // crests still are, so the maximum is the same to the bit. (No tension, not
  // even an RK4 stage's in the start-up transient, reaches the slack limit -T:
  // the trajectory is the one with T = 1e9 N, bit for bit, as the traces show.
  // At T = 3e4 N the warm-up reaches it, and the last bits differ.)
  std::vector<double> gated_trace;
  const DayStatistics gated = integrate_day(p, f, LinearLine{4.0e4, 2.0e3, 1.0e5}, o, &gated_trace);
  ASSERT_EQ(gated_trace, trace);
  EXPECT_LT(gated.min_tension_n - s.max_tension_n,
            -detail::kPeakGateFraction * (s.max_tension_n + 1.0e5));  // troughs skipped
  EXPECT_EQ(std::bit_cast<std::uint64_t>(gated.max_tension_n), std::bit_cast<std::uint64_t>(s.max_tension_n));
}

TEST(SurgeIntegrator, LinearNonSurgeTensionEqualsTheWholeExtensionOnALinearLine) {  // surge-6, EQ-SURGE-6
  // For tau = k xi + c xi' the superposition P(xi_s) + k xi_ns + c xi_ns' is
  // P(xi_s + xi_ns): the two readings agree to rounding on any forcing.
  constexpr double kRoundingRelTol = 1e-9;
  const LinearLine line{4.0e5, 2.0e4, 1.0e9};  // never slack
  SurgeParameters p = tug_and_tow();
  const double dt = 0.25;
  const std::size_t n = 4000;
  DayForcing f = harmonic_tug_force(1.0e5, 2.0 * kPi / 20.0, dt, n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt, w = 2.0 * kPi / 8.0;
    f.xi_ns_m[i] = 0.3 * std::sin(w * t);
    f.xi_ns_dot_m_s[i] = 0.3 * w * std::cos(w * t);
  }
  IntegratorOptions o;
  o.warmup_s = 3000.0;
  std::vector<double> whole_trace, split_trace;
  const DayStatistics whole = integrate_day(p, f, line, o, &whole_trace);
  p.linear_non_surge_tension = true;
  p.non_surge_stiffness_n_m = line.k;
  p.non_surge_damping_n_s_m = line.c;
  const DayStatistics split = integrate_day(p, f, line, o, &split_trace);
  EXPECT_REL_CLOSE(split.max_tension_n, whole.max_tension_n, kRoundingRelTol);
  EXPECT_REL_CLOSE(split.min_tension_n, whole.min_tension_n, kRoundingRelTol);
  ASSERT_EQ(split_trace.size(), whole_trace.size());
  for (std::size_t i = 0; i < n; i += 97) {
    EXPECT_ABS_CLOSE(split_trace[i], whole_trace[i], kRoundingRelTol * whole.max_tension_n) << "sample " << i;
  }
}

TEST(SurgeIntegrator, LinearNonSurgeTensionBypassesTheNonlinearLaw) {  // surge-6, EQ-SURGE-6
  // Immovable vessels: xi_s = 0, so P(xi_s) = 0 and tau = max(-T, k_ns xi_ns)
  // exactly, where EQ-SURGE-4 gives the cubic line's P(xi_ns).
  SurgeParameters p = tug_and_tow();
  p.tug_mass_kg = p.tow_mass_kg = 1e18;
  const CubicLine line{1.0e6};  // P(1 m) = 3e5 + 1e6 = 1.3e6 N; slack at -2e5 N
  const double dt = 0.05;
  const std::size_t n = 20000;
  DayForcing f = harmonic_tug_force(0.0, 1.0, dt, n);
  const double w = 2.0 * kPi / 20.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    f.xi_ns_m[i] = std::sin(w * t);
    f.xi_ns_dot_m_s[i] = w * std::cos(w * t);
  }
  IntegratorOptions o;
  o.warmup_s = 100.0;
  const DayStatistics whole = integrate_day(p, f, line, o);
  EXPECT_GT(whole.max_tension_n, 1.2e6);  // the cubic's stiffening (plus its 1e4 xi' term, out of phase)
  p.linear_non_surge_tension = true;
  p.non_surge_stiffness_n_m = 4.0e5;
  const DayStatistics split = integrate_day(p, f, line, o);
  EXPECT_REL_CLOSE(split.max_tension_n, 4.0e5, 1e-4);  // peaks read between steps (EQ-SURGE-5)
  EXPECT_NEAR(split.min_tension_n, -2.0e5, 1e-6);       // clamped at -T
  EXPECT_EQ(split.snatch_events, 50);                   // one slack-to-taut transition per 20 s cycle
}

TEST(SurgeIntegrator, ExtensionStatisticsReadTheLawsArgument) {  // surge-7, EQ-SURGE-3
  // Immovable vessels: xi = x1 cos(a1) - x7 cos(a2) + xi_ns with x1, x7 of
  // order F t^2 / M = 6e5 N (1100 s)^2 / 1e30 kg ~ 1e-18 m, far below the
  // metres of xi_ns.
  SurgeParameters p = tug_and_tow();
  p.tug_mass_kg = p.tow_mass_kg = 1e30;
  constexpr double kImmovableAbsTolM = 1e-12;
  const LinearLine line{4.0e5, 0.0, 1.0e9};
  const double dt = 0.5;
  const std::size_t n = 2000;
  DayForcing f = harmonic_tug_force(0.0, 1.0, dt, n);
  const double w = 2.0 * kPi / 13.0;
  double lo = 0.0, hi = 0.0, sum = 0.0, sum_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    f.xi_ns_m[i] = 1.5 * std::sin(w * t) + 0.25;
    f.xi_ns_dot_m_s[i] = 1.5 * w * std::cos(w * t);
    lo = i == 0 ? f.xi_ns_m[i] : std::min(lo, f.xi_ns_m[i]);
    hi = i == 0 ? f.xi_ns_m[i] : std::max(hi, f.xi_ns_m[i]);
    sum += f.xi_ns_m[i];
    sum_sq += f.xi_ns_m[i] * f.xi_ns_m[i];
  }
  IntegratorOptions o;
  o.warmup_s = 100.0;
  const DayStatistics s = integrate_day(p, f, line, o);
  ASSERT_EQ(s.samples, static_cast<long>(n));
  EXPECT_NEAR(s.extension_min_m, lo, kImmovableAbsTolM);
  EXPECT_NEAR(s.extension_max_m, hi, kImmovableAbsTolM);
  EXPECT_NEAR(s.extension_sum_m, sum, n * kImmovableAbsTolM);
  EXPECT_NEAR(s.extension_sum_sq_m2, sum_sq, n * 4.0 * kImmovableAbsTolM);  // 2 |xi| dxi, |xi| < 2 m
  // EQ-SURGE-6: the law sees the surge part of the extension, which is 0 here.
  p.linear_non_surge_tension = true;
  p.non_surge_stiffness_n_m = 4.0e5;
  const DayStatistics split = integrate_day(p, f, line, o);
  EXPECT_NEAR(split.extension_min_m, 0.0, kImmovableAbsTolM);
  EXPECT_NEAR(split.extension_max_m, 0.0, kImmovableAbsTolM);

  // Moving vessels on a spring without dashpot: tau = k xi at every sample,
  // so the sampled tension over k is the recorded extension.
  const SurgeParameters q = tug_and_tow();
  const DayForcing g = harmonic_tug_force(1.0e5, 2.0 * kPi / 20.0, 0.25, 4000);
  std::vector<double> trace;
  o.warmup_s = 3000.0;
  const DayStatistics m = integrate_day(q, g, line, o, &trace);
  const double k = line.k;
  constexpr double kRoundingRelTol = 1e-12;  // k xi + 0 xi' against xi: one rounding
  EXPECT_REL_CLOSE(m.extension_max_m, *std::max_element(trace.begin(), trace.end()) / k, kRoundingRelTol);
  EXPECT_REL_CLOSE(m.extension_min_m, *std::min_element(trace.begin(), trace.end()) / k, kRoundingRelTol);
  EXPECT_GT(m.extension_max_m, 0.1);  // the premise: the line really moved (tau amplitude / k ~ decimetres)
}

}  // namespace
}  // namespace towdb::simulation
