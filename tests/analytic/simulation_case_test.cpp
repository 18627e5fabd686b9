// Tests of one whole towing case (generator/simulation/case_runner.hpp).
//   case-1  linear limit: with a linear towline and no second-order forces the
//           simulated tension variance equals the frequency-domain prediction
//           (issue "Long-time towing simulation", verification: within 3 %).
//           Deterministic amplitudes and one component per encounter bin make
//           the variance of a periodic linear record exact (Parseval), so one
//           day suffices; what remains is integration and interpolation error.
//   case-2  determinism: bit-identical daily maxima for 1 and 2 threads, and a
//           different seed gives different days.
//   case-3  the Gumbel statistics of the case are the method-of-moments fit of
//           its own daily maxima (thesis eq. 4.5-4.6).
//   case-4  the straight-spring option above breaking strength (EQ-TOWLINE-13)
//           in the lock-step lanes: the days of a case where the line passes
//           the breaking strength equal each day simulated alone, and the
//           lanes of the fastest vectors (AVX2 where the processor has it)
//           equal the baseline's.
//   case-5  with CaseOptions::tow_drift_at_tow (a diagnostic; the thesis
//           shares one envelope, and then the lag is 0) the tow's slowly
//           varying surge force is built from the wave envelope at the tow,
//           G astern of the tug (thesis eq. 3-21: the
//           tow's wave elevation is the tug's times exp(i k G cos mu)), so in
//           head seas the wave groups, hence the second-order forces, reach
//           the tow one group-travel time G / (c_g + U) after the tug
//           (Newman 1974: the slowly varying force follows the local envelope).
//   case-6  the linear heading profile (EQ-CASE-3) is the linear prediction's
//           standard deviation at each heading, bit for bit; it has the
//           beam-sea minimum the simulated tension has (docs/audit.md:
//           T-ATF / FFG 7, 1,041 ft wire, 74,086 lbf, 7.96 kt, 27.71 kt:
//           131 / 38.5 / 70 kips simulated at 76 / 84 / 90 deg); a sea of two
//           systems is refused.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "simulation/case_runner.hpp"
#include "test_support.hpp"

namespace towdb::simulation {
namespace {

const io::ShipCatalog& catalog() {
  static const io::ShipCatalog cat = io::ShipCatalog::load(test::source_dir() / "ships");
  return cat;
}

CaseInputs frigate_case(double heading_deg, int days) {
  CaseInputs in;
  in.tug = &catalog().vessel("T-ATF").vessel;
  in.tow = &catalog().vessel("FFG7").vessel;
  in.towline = catalog().towline(*in.tug, model::LineKind::kWire, units::ft_to_m(2000.0));
  in.speed_m_s = units::kt_to_m_s(9.0);
  in.sea = sea::single_system(sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(20.0)),
                              units::deg_to_rad(heading_deg));
  in.mean_tension_n = units::lbf_to_n(50000.0);
  in.days = days;
  in.seed = 7;
  return in;
}

CaseOptions quick_options() {
  CaseOptions o;
  o.response_frequencies = 24;  // the test compares the chain with itself: a coarse grid is enough
  o.bootstrap_replicates = 200;
  return o;
}

TEST(SimulationCase, LinearLimitMatchesFrequencyDomain) {  // case-1, EVIDENCE-OF: EQ-SURGE-1..4
  for (double heading : {0.0, 180.0}) {
    CaseInputs in = frigate_case(heading, 3);
    CaseOptions o = quick_options();
    o.tension_law = TensionLaw::kLinear;
    o.second_order_forces = false;
    o.num_threads = 2;
    const CaseResult r = run_case(in, o);
    double simulated = 0.0;
    for (const auto& d : r.days) simulated += d.tension_variance_n2;
    simulated /= static_cast<double>(r.days.size());
    const double predicted = linear_tension_variance_n2(in, o);
    constexpr double kLinearLimitRelTol = 0.03;  // the criterion
    EXPECT_REL_CLOSE(simulated, predicted, kLinearLimitRelTol) << "heading " << heading;
    // Every day has the same variance (phases only): a check of the record synthesis too.
    for (const auto& d : r.days) EXPECT_REL_CLOSE(d.tension_variance_n2, predicted, kLinearLimitRelTol);
  }
}

TEST(SimulationCase, BitIdenticalForAnyThreadCount) {  // case-2
  const CaseInputs in = frigate_case(0.0, 6);
  CaseOptions one = quick_options(), two = quick_options();
  one.num_threads = 1;
  two.num_threads = 2;
  const CaseResult a = run_case(in, one), b = run_case(in, two);
  ASSERT_EQ(a.days.size(), b.days.size());
  for (std::size_t i = 0; i < a.days.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.days[i].max_dynamic_tension_n),
              std::bit_cast<std::uint64_t>(b.days[i].max_dynamic_tension_n))
        << "day " << i;
  }
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.statistics.dynamic_999_n),
            std::bit_cast<std::uint64_t>(b.statistics.dynamic_999_n));
  // run_case integrates days 0-3 in lock step and days 4-5 one at a time; each
  // equals the day simulated alone (surge.hpp integrate_days).
  const auto model = prepare_case(in, one);
  for (std::uint64_t d : {0u, 3u, 5u}) {
    const DayStatistics alone = simulate_day(*model, day_forcing(*model, in.seed, d), one.integrator);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.days[d].max_dynamic_tension_n),
              std::bit_cast<std::uint64_t>(alone.max_tension_n))
        << "day " << d;
    EXPECT_EQ(a.days[d].slack_time_s, alone.slack_time_s) << "day " << d;
  }
  CaseInputs other = in;
  other.seed = 8;
  const CaseResult c = run_case(other, one);
  EXPECT_NE(a.days[0].max_dynamic_tension_n, c.days[0].max_dynamic_tension_n);
}

TEST(SimulationCase, StatisticsAreTheMomentsFitOfTheDays) {  // case-3
  const CaseResult r = run_case(frigate_case(0.0, 8), quick_options());
  double mean = 0.0;
  for (const auto& d : r.days) mean += d.max_dynamic_tension_n;
  mean /= static_cast<double>(r.days.size());
  double var = 0.0;
  for (const auto& d : r.days) var += (d.max_dynamic_tension_n - mean) * (d.max_dynamic_tension_n - mean);
  var /= static_cast<double>(r.days.size() - 1);
  // alpha = pi / (sigma sqrt 6), u = mu - gamma / alpha, x_F = u - ln(-ln F) / alpha.
  const double alpha = kPi / std::sqrt(6.0 * var);
  const double u = mean - kEulerGamma / alpha;
  constexpr double kRoundOffRelTol = 1e-12;
  EXPECT_REL_CLOSE(r.statistics.gumbel_alpha_per_n, alpha, kRoundOffRelTol);
  EXPECT_REL_CLOSE(r.statistics.gumbel_u_n, u, kRoundOffRelTol);
  EXPECT_REL_CLOSE(r.statistics.dynamic_999_n, u - std::log(-std::log(0.999)) / alpha, kRoundOffRelTol);
  EXPECT_LE(r.statistics.ci_low_n, r.statistics.dynamic_999_n);
  EXPECT_GE(r.statistics.ci_high_n, r.statistics.dynamic_999_n);
  EXPECT_TRUE(std::isnan(r.statistics.empirical_999_n));  // 8 days < 5 / (1 - 0.999)
  // The extension summary pools the days (each has the same number of samples):
  // the whole record's mean and variance from the days' means and variances.
  double lo = r.days[0].extension_min_m, hi = r.days[0].extension_max_m, m1 = 0.0, m2 = 0.0;
  int outside = 0;
  for (const auto& d : r.days) {
    lo = std::min(lo, d.extension_min_m);
    hi = std::max(hi, d.extension_max_m);
    m1 += d.extension_mean_m;
    m2 += d.extension_variance_m2 + d.extension_mean_m * d.extension_mean_m;
    outside += d.extension_min_m < r.towline.fit_xi_min_m || d.extension_max_m > r.towline.fit_xi_max_m;
  }
  m1 /= static_cast<double>(r.days.size());
  m2 /= static_cast<double>(r.days.size());
  EXPECT_EQ(r.extension.min_m, lo);
  EXPECT_EQ(r.extension.max_m, hi);
  EXPECT_REL_CLOSE(r.extension.mean_m, m1, kRoundOffRelTol);
  EXPECT_REL_CLOSE(r.extension.sd_m, std::sqrt(m2 - m1 * m1), 1e-9);  // a difference of squares
  EXPECT_EQ(r.extension.days_outside_fit, outside);
  EXPECT_LT(r.extension.min_m, r.extension.mean_m);
  EXPECT_GT(r.extension.max_m, r.extension.mean_m);
}

TEST(SimulationCase, StraightSpringLanesEqualSingleDays) {  // case-4
  // 1000 ft of wire at 51,500 lbf in a 35 kt sea: the thesis's dynamic tension
  // for this line reaches several times its 360,000 lbf breaking strength.
  CaseInputs in = frigate_case(0.0, 6);
  in.towline = catalog().towline(*in.tug, model::LineKind::kWire, units::ft_to_m(1000.0));
  in.sea = sea::single_system(sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(35.0)), 0.0);
  in.mean_tension_n = units::lbf_to_n(51500.0);
  CaseOptions o = quick_options();
  o.above_breaking = towline::AboveBreakingModel::kStraightSpring;
  o.num_threads = 1;
  const CaseResult r = run_case(in, o);
  const auto model = prepare_case(in, o);
  // run_case used the fastest vectors; the baseline ones give the same bits.
  LockstepForcing<kLockstepDays> group;
  for (std::uint64_t d = 0; d < kLockstepDays; ++d) {
    const DayForcing day = day_forcing(*model, in.seed, d);
    group.dt_s = day.dt_s;
    group.resize(day.size());
    group.set_day(d, day);
  }
  const auto baseline = simulate_days(*model, group, o.integrator, LaneIsa::kBaseline);
  for (std::size_t d = 0; d < kLockstepDays; ++d) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r.days[d].max_dynamic_tension_n),
              std::bit_cast<std::uint64_t>(baseline[d].max_tension_n))
        << "day " << d << ", " << lane_isa_name(fastest_lane_isa()) << " against baseline";
  }
  int above = 0;
  for (std::uint64_t d = 0; d < r.days.size(); ++d) {  // days 0-3 in lock step, 4-5 a partial group
    const DayStatistics alone = simulate_day(*model, day_forcing(*model, in.seed, d), o.integrator);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r.days[d].max_dynamic_tension_n),
              std::bit_cast<std::uint64_t>(alone.max_tension_n))
        << "day " << d;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r.days[d].slack_time_s), std::bit_cast<std::uint64_t>(alone.slack_time_s))
        << "day " << d;
    EXPECT_EQ(r.days[d].snatch_events, alone.snatch_events) << "day " << d;
    // The day's mean tension, as run_case forms it from the sum (bit for bit).
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r.days[d].tension_mean_n),
              std::bit_cast<std::uint64_t>(alone.tension_sum_n / static_cast<double>(alone.samples)))
        << "day " << d;
    if (in.mean_tension_n + alone.max_tension_n > r.towline.breaking_strength_n) ++above;
  }
  EXPECT_GT(above, 0);  // the premise: the spring branch was taken
}

// The lag [s] at which the tug's and the tow's slowly varying forces (the
// forces with the second-order records minus those without: the first-order
// records are the same in both, same seed and day) correlate best, searched
// over +-max_lag_s; and G [m].
std::pair<double, double> drift_force_lag_s(const CaseInputs& in, bool tow_drift_at_tow, double max_lag_s) {
  CaseOptions with = quick_options(), without = quick_options();
  with.num_threads = without.num_threads = 1;
  with.tow_drift_at_tow = without.tow_drift_at_tow = tow_drift_at_tow;
  without.second_order_forces = false;
  const double g_m = run_case(in, with).separation_m;  // G, tug origin to tow origin
  const DayForcing a = day_forcing(*prepare_case(in, with), in.seed, 0);
  const DayForcing b = day_forcing(*prepare_case(in, without), in.seed, 0);
  const std::size_t n = a.size();
  std::vector<double> f2_tug(n), f2_tow(n);
  for (std::size_t i = 0; i < n; ++i) {
    f2_tug[i] = a.tug_force_n[i] - b.tug_force_n[i];
    f2_tow[i] = a.tow_force_n[i] - b.tow_force_n[i];
  }
  const auto max_lag = static_cast<std::ptrdiff_t>(max_lag_s / a.dt_s);
  std::ptrdiff_t best_lag = 0;
  double best = -1.0e300;
  for (std::ptrdiff_t lag = -max_lag; lag <= max_lag; ++lag) {  // the records are periodic
    double c = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto j = static_cast<std::size_t>((static_cast<std::ptrdiff_t>(i) + lag + static_cast<std::ptrdiff_t>(n)) %
                                              static_cast<std::ptrdiff_t>(n));
      c += f2_tug[i] * f2_tow[j];
    }
    if (c > best) {
      best = c;
      best_lag = lag;
    }
  }
  return {static_cast<double>(best_lag) * a.dt_s, g_m};
}

TEST(SimulationCase, TowDriftForceLagsTheTugsByTheGroupTravelTime) {  // case-5, EVIDENCE-OF: EQ-SEA-9
  // Head seas, T-ATF / FFG 7 on 2,000 ft of wire, 9 kt, PM 20 kt.
  const CaseInputs in = frigate_case(180.0, 3);
  // Expected delay: deep-water group velocity g / (2 w_p) at the PM peak
  // w_p = 0.877 g / U_wind (sea EQ-SEA-1), relative to a ship meeting the groups at U.
  const double w_p = 0.877 * kGravity_m_s2 / units::kt_to_m_s(20.0);
  const double g_m = drift_force_lag_s(in, false, 0.0).second;
  const double expected_s = g_m / (kGravity_m_s2 / (2.0 * w_p) + in.speed_m_s);
  // The spectrum is broad (groups disperse, and each vessel weights it by its
  // own drift operator): the peak must sit at the group delay within +-50 %,
  // and in any case not at zero (both vessels forced at once).
  constexpr double kGroupDelayRelTol = 0.5;
  const double measured_s = drift_force_lag_s(in, true, 3.0 * expected_s).first;
  EXPECT_GT(measured_s, (1.0 - kGroupDelayRelTol) * expected_s) << "expected " << expected_s << " s";
  EXPECT_LT(measured_s, (1.0 + kGroupDelayRelTol) * expected_s) << "expected " << expected_s << " s";
  // The thesis's shared envelope (default): both vessels at once.
  EXPECT_EQ(drift_force_lag_s(in, false, 3.0 * expected_s).first, 0.0);
}

TEST(SimulationCase, LinearHeadingProfileHasTheBeamSeaMinimum) {  // case-6, EVIDENCE-OF: EQ-CASE-3
  CaseInputs in = frigate_case(0.0, 3);
  in.towline = catalog().towline(*in.tug, model::LineKind::kWire, units::ft_to_m(1041.0));
  in.speed_m_s = units::kt_to_m_s(7.96);
  in.sea = sea::single_system(sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(27.71)), 0.0);
  in.mean_tension_n = units::lbf_to_n(74086.0);
  const CaseOptions o;
  const std::vector<double> headings = {76.0, 84.0, 90.0};
  const std::vector<double> sigma = linear_tension_sigma_by_heading_n(in, o, headings);
  ASSERT_EQ(sigma.size(), headings.size());
  for (std::size_t j = 0; j < headings.size(); ++j) {
    CaseInputs at = in;
    at.sea.systems[0].heading_rad = units::deg_to_rad(headings[j]);
    EXPECT_EQ(sigma[j], std::sqrt(linear_tension_variance_n2(at, o))) << headings[j];
  }
  // The simulated ratios are 38.5 / 131 = 0.29 and 38.5 / 70 = 0.55; this chain's linear sigma is
  // 22.8 / 6.5 / 11.4 kips, ratios 0.28 and 0.57.
  EXPECT_LT(sigma[1], 0.4 * sigma[0]);
  EXPECT_LT(sigma[1], 0.7 * sigma[2]);
  CaseInputs swell = in;
  swell.sea = sea::wind_sea_and_swell(sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(20.0)), 0.0,
                                      sea::Spectrum::bretschneider_peak_period(2.0, 12.0), 1.0);
  test::expect_input_error([&] { linear_tension_sigma_by_heading_n(swell, o, headings); }, "wave systems");
}

}  // namespace
}  // namespace towdb::simulation
