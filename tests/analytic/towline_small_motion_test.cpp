// The quasi-static limit of the fitted towline (EQ-TOWLINE-16/17): for a
// small, slow extension xi = A sin(2 pi t / T) a towline answers with its
// static stiffness, tau ~ k_s A (Irvine 1981 ch. 2: dH/dX of the elastic
// catenary, EQ-TOWLINE-4). Checked on the four lines of the project issue
// that found the thesis's fit answering with up to 2.7 k_s A: the T-ATF 166's
// wire rigged to an FFG 7 (ships/), at A = 1 ft, T = 100 s.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "test_support.hpp"
#include "towline/towline.hpp"

namespace towdb::towline {
namespace {

// The issue's criterion: the first harmonic within 10 % of k_s A. The line's
// own shallow-sag runs at 0.03-0.07 rad/s give 0.93-0.96 k_s A.
constexpr double kSmallMotionRelTol = 0.10;

struct IssueLine {
  double length_ft;
  double mean_lbf;
  double thesis_fit_ratio;  // measured with the thesis's fit (issue table)
};

std::shared_ptr<const TowlineFit> fit_line(const IssueLine& c, const TowlineFitOptions& options) {
  const io::ShipCatalog catalog = io::ShipCatalog::load(test::source_dir() / "ships");
  const model::Vessel& tug = catalog.vessel("T-ATF 166").vessel;
  const model::Vessel& tow = catalog.vessel("FFG 7").vessel;
  const model::Towline line = catalog.towline(tug, model::LineKind::kWire, units::ft_to_m(c.length_ft));
  return build_towline_fit(line, TowPoints{tug.tow_point.z_m, tow.tow_point.z_m}, units::lbf_to_n(c.mean_lbf),
                           options);
}

// EVIDENCE-OF: EQ-TOWLINE-16
// EVIDENCE-OF: EQ-TOWLINE-17
TEST(TowlineSmallMotion, FirstHarmonicIsTheStaticStiffness) {
  const std::vector<IssueLine> lines = {
      {2000.0, 15000.0, 2.7}, {2000.0, 50000.0, 1.6}, {1000.0, 15000.0, 1.3}, {2000.0, 100000.0, 1.07}};
  TowlineFitOptions thesis;
  thesis.hold_static_stiffness = false;
  thesis.max_run_weight_exponent = 0.0;
  for (const IssueLine& c : lines) {
    const auto fit = fit_line(c, TowlineFitOptions{});
    const FitSummary& s = fit->summary();
    // The fit's own constraint (EQ-TOWLINE-16), tighter than the issue's 10 %.
    EXPECT_LE(std::abs(s.small_motion_ratio - 1.0), TowlineFitOptions{}.small_motion_tolerance);
    const double direct = first_harmonic_n(s.coefficients, kSmallMotionAmplitudeM,
                                           2.0 * std::acos(-1.0) / kSmallMotionPeriodS) /
                          (s.static_stiffness_n_m * kSmallMotionAmplitudeM);
    EXPECT_DOUBLE_EQ(s.small_motion_ratio, direct);
    EXPECT_NEAR(s.small_motion_ratio, 1.0, kSmallMotionRelTol) << c.length_ft << " ft at " << c.mean_lbf << " lbf";
    // The thesis's fit reproduces the issue's measurement (so this test can fail).
    const double before = fit_line(c, thesis)->summary().small_motion_ratio;
    EXPECT_NEAR(before, c.thesis_fit_ratio, 0.05 * c.thesis_fit_ratio) << c.length_ft << " ft at " << c.mean_lbf;
  }
}

}  // namespace
}  // namespace towdb::towline
