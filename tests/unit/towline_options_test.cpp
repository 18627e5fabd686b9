// Options validation and edge cases of towdb::towline: every bad value is an
// InputError naming the field; the cache computes each fit once.
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/units.hpp"
#include "test_support.hpp"
#include "towline/towline.hpp"
#include "towline_test_lines.hpp"

namespace towdb::towline {
namespace {

using test::expect_input_error;

TEST(TowlineOptions, DefaultsAreValid) {
  EXPECT_NO_THROW(CatenaryOptions{}.validate());
  EXPECT_NO_THROW(DynamicsOptions{}.validate());
  EXPECT_NO_THROW(ExcitationOptions{}.validate());
  EXPECT_NO_THROW(TowlineFitOptions{}.validate());
}

TEST(TowlineOptions, BadValuesNameTheirField) {
  expect_input_error([] { CatenaryOptions o; o.closure_tolerance = 0.0; o.validate(); }, "closure_tolerance");
  expect_input_error([] { CatenaryOptions o; o.max_iterations = 1; o.validate(); }, "max_iterations");
  expect_input_error([] { DynamicsOptions o; o.samples_per_period = 4; o.validate(); }, "samples_per_period");
  expect_input_error([] { DynamicsOptions o; o.max_cycles = 1; o.validate(); }, "max_cycles");
  expect_input_error([] { DynamicsOptions o; o.periodicity_tolerance = std::nan(""); o.validate(); },
                     "periodicity_tolerance");
  expect_input_error([] { DynamicsOptions o; o.courant_limit = 2.5; o.validate(); }, "courant_limit");
  expect_input_error([] { DynamicsOptions o; o.steps_per_period = 2; o.validate(); }, "steps_per_period");
  expect_input_error([] { DynamicsOptions o; o.newton_tolerance = 1.0; o.validate(); }, "newton_tolerance");
  expect_input_error([] { ExcitationOptions o; o.frequencies_rad_s = {0.5}; o.validate(); }, "frequencies_rad_s");
  expect_input_error([] { ExcitationOptions o; o.amplitude_fractions = {0.5, 1.5}; o.validate(); },
                     "amplitude_fractions");
  expect_input_error([] { ExcitationOptions o; o.max_velocity_m_s = -1.0; o.validate(); }, "max_velocity_m_s");
  expect_input_error([] { TowlineFitOptions o; o.max_elements = o.min_elements; o.validate(); }, "max_elements");
  expect_input_error([] { TowlineFitOptions o; o.resolution_tolerance = 0.9; o.validate(); },
                     "resolution_tolerance");
}

TEST(TowlineOptions, BadPhysicalInputsAreRejected) {
  const model::Towline line = test::thesis_towline("wire", 1000.0);
  expect_input_error([&] { Catenary::solve(line, test::thesis_tow_points(), 0.0); }, "mean) tension");
  expect_input_error([&] { Catenary::solve(line, {0.0, 400.0}, 1e5); }, "height difference");
  model::Towline empty;
  expect_input_error([&] { Catenary::solve(empty, test::thesis_tow_points(), 1e5); }, "no segments");
  expect_input_error(
      [&] { build_towline_fit(line, test::thesis_tow_points(), units::lbf_to_n(400000.0)); },
      "mean towline tension");
  const Catenary cat = Catenary::solve(line, test::thesis_tow_points(), 1e5);
  expect_input_error([&] { ShallowSagModel(cat, 3); }, "element count");
  const ShallowSagModel model(cat, 16);
  expect_input_error([&] { model.run_harmonic(1.0, 0.0); }, "frequency");
  expect_input_error([&] { model.run_harmonic(-1.0, 0.5); }, "amplitude");
}

TEST(TowlineOptions, FitNeedsNineUsableSamples) {
  std::vector<TensionSample> few(8, TensionSample{1.0, 1.0, 1.0, false});
  expect_input_error([&] { fit_polynomial(few, 10.0); }, "samples below breaking strength");
  // Samples on one sinusoid's zero crossing only cannot determine 9 terms.
  std::vector<TensionSample> degenerate(20, TensionSample{0.0, 1.0, 5.0, false});
  EXPECT_THROW(fit_polynomial(degenerate, 10.0), InputError);
}

TEST(TowlineOptions, SmallMotionFitInputsAreChecked) {
  std::vector<TensionSample> samples;
  for (int k = 0; k < 40; ++k) samples.push_back({std::sin(0.3 * k), std::cos(0.7 * k), 1.0 * k, false});
  const double inf = std::numeric_limits<double>::infinity();
  SmallMotionFit wrong_count;
  wrong_count.weights.assign(samples.size() - 1, 1.0);
  expect_input_error([&] { fit_polynomial(samples, inf, -inf, SlackFit::kTwoSided, wrong_count); },
                     "weights count");
  SmallMotionFit negative;
  negative.weights.assign(samples.size(), 1.0);
  negative.weights[3] = -1.0;
  expect_input_error([&] { fit_polynomial(samples, inf, -inf, SlackFit::kTwoSided, negative); }, "weight");
  SmallMotionFit infinite;
  infinite.fixed_a10_n_m = inf;
  expect_input_error([&] { fit_polynomial(samples, inf, -inf, SlackFit::kTwoSided, infinite); }, "fixed a10");
  TowlineFitOptions options;
  options.max_run_weight_exponent = 1.5;
  expect_input_error([&] { options.validate(); }, "towline_fit.max_run_weight_exponent");
  options = {};
  options.small_motion_tolerance = 0.0;
  expect_input_error([&] { options.validate(); }, "towline_fit.small_motion_tolerance");
}

// The cache computes each (towline, points, tension, options) fit once, also
// when several threads ask at the same moment, and returns the same object.
TEST(TowlineOptions, CacheComputesEachFitOnce) {
  TowlineFitCache cache;
  TowlineFitOptions o;
  o.excitation.frequencies_rad_s = {0.1, 0.8};
  o.excitation.amplitude_fractions = {0.2, 0.6, 1.0};
  const model::Towline line = test::thesis_towline("nylon", 800.0);
  std::vector<std::shared_ptr<const TowlineFit>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < got.size(); ++i) {
    threads.emplace_back([&, i] { got[i] = cache.get(line, test::thesis_tow_points(), 2e5, o); });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(cache.builds(), 1u);
  for (const auto& g : got) EXPECT_EQ(g.get(), got[0].get());
  // The thread count is not part of the key; names are not either.
  TowlineFitOptions o2 = o;
  o2.num_threads = 1;
  model::Towline renamed = line;
  renamed.segments[0].component.name = "other name";
  EXPECT_EQ(cache.get(renamed, test::thesis_tow_points(), 2e5, o2).get(), got[0].get());
  EXPECT_EQ(cache.builds(), 1u);
  // A different tension is a different fit.
  EXPECT_NE(cache.get(line, test::thesis_tow_points(), 2.1e5, o).get(), got[0].get());
  EXPECT_EQ(cache.builds(), 2u);
  // Failures are cached and rethrown.
  EXPECT_THROW(cache.get(line, test::thesis_tow_points(), -1.0, o), InputError);
  EXPECT_THROW(cache.get(line, test::thesis_tow_points(), -1.0, o), InputError);
  EXPECT_EQ(cache.builds(), 3u);
  cache.clear();
  EXPECT_EQ(cache.size(), 0u);
}

}  // namespace
}  // namespace towdb::towline
