// Options validation and edge cases of the sea module: every bad input throws
// towdb::InputError naming the field.
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "sea/sea.hpp"
#include "test_support.hpp"

namespace towdb::sea {
namespace {

using test::expect_input_error;

const Spectrum& test_spectrum() {
  static const Spectrum s = Spectrum::pierson_moskowitz(12.0);
  return s;
}

TEST(SeaOptions, SpectrumFactoriesRejectBadParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_input_error([] { Spectrum::pierson_moskowitz(0.0); }, "wind_speed_m_s");
  expect_input_error([&] { Spectrum::pierson_moskowitz(nan); }, "wind_speed_m_s");
  expect_input_error([] { Spectrum::bretschneider_mean_period(-1.0, 8.0); }, "significant_height_m");
  expect_input_error([] { Spectrum::bretschneider_mean_period(2.0, 0.0); }, "mean_period_s");
  expect_input_error([] { Spectrum::bretschneider_peak_period(2.0, 100.0); }, "peak_period_s");
  expect_input_error([] { Spectrum::jonswap(2.0, 8.0, 0.5); }, "gamma");
  expect_input_error([] { test_spectrum().moment(4); }, "moment order");
  expect_input_error([] { test_spectrum().tail_omega_rad_s(1.0); }, "tail fraction");
}

TEST(SeaOptions, RecordOptionsValidate) {
  RecordOptions ok;
  EXPECT_NO_THROW(ok.validate());
  auto with = [](auto change) {
    RecordOptions o;
    change(o);
    return o;
  };
  expect_input_error([&] { with([](RecordOptions& o) { o.duration_s = 0.0; }).validate(); }, "record.duration_s");
  expect_input_error([&] { with([](RecordOptions& o) { o.encounter_cutoff_rad_s = -1.0; }).validate(); },
                     "record.encounter_cutoff_rad_s");
  expect_input_error([&] { with([](RecordOptions& o) { o.tail_energy_fraction = 0.0; }).validate(); },
                     "record.tail_energy_fraction");
  expect_input_error([&] { with([](RecordOptions& o) { o.max_time_step_s = -0.1; }).validate(); },
                     "record.max_time_step_s");
  expect_input_error([&] { with([](RecordOptions& o) { o.samples = -5; }).validate(); }, "record.samples");
  expect_input_error([&] { with([](RecordOptions& o) { o.bins_per_component = 0; }).validate(); },
                     "record.bins_per_component");
}

TEST(SeaOptions, PlanRejectsBadInputs) {
  const SeaState sea = single_system(test_spectrum(), 3.0);
  expect_input_error([&] { RecordPlan(sea, -1.0); }, "record.speed_m_s");
  expect_input_error([&] { RecordPlan(SeaState{}, 1.0); }, "sea_state.systems");
  expect_input_error(
      [&] { RecordPlan(single_system(test_spectrum(), std::numeric_limits<double>::infinity()), 1.0); },
      "heading_rad");
  RecordOptions tiny_cutoff;
  tiny_cutoff.encounter_cutoff_rad_s = 1e-5;  // below one bin (7.3e-5 rad/s for a day)
  expect_input_error([&] { RecordPlan(sea, 1.0, tiny_cutoff); }, "record.encounter_cutoff_rad_s");
  RecordOptions short_record;
  short_record.encounter_cutoff_rad_s = 2.0;
  short_record.samples = 1000;  // needs >= 55004
  expect_input_error([&] { RecordPlan(sea, 1.0, short_record); }, "record.samples");
}

TEST(SeaOptions, SynthesizerRejectsMismatchedOrNonFiniteInputs) {
  RecordOptions opt;
  opt.duration_s = 600.0;
  const RecordPlan plan(single_system(test_spectrum(), 3.0), 2.0, opt);
  const std::size_t n = plan.components().size();
  using Transfer = std::vector<std::vector<std::complex<double>>>;
  expect_input_error([&] { DaySynthesizer(plan, Transfer{std::vector<std::complex<double>>(n + 1)}, {}); },
                     "linear_transfer[0] (size)");
  std::vector<double> d(n, 1.0);
  d[n / 2] = std::numeric_limits<double>::infinity();  // a signed D is allowed, a non-finite one is not
  expect_input_error([&] { DaySynthesizer(plan, {}, {d}); }, "drift_coefficient[0]");
  std::vector<std::complex<double>> h(n, 1.0);
  h[0] = {std::numeric_limits<double>::quiet_NaN(), 0.0};
  expect_input_error([&] { DaySynthesizer(plan, Transfer{h}, {}); }, "linear_transfer[0][0]");
}

}  // namespace
}  // namespace towdb::sea
