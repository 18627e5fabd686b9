// Analytic tests of the station-table generator (generator/model/hull_form.hpp).
// Test plan:
//   hf-1  box barge: every station has B, T and sigma = 1 (EQ-HULLFORM-7)
//   hf-2  the trapezoid volume, LCB and waterplane area of the generated table
//         reproduce C_b L B T, the LCB and C_wp L B (EQ-HULLFORM-4, -5)
//   hf-3  sigma in (0, 1] wherever B > 0, sigma <= C_m, and B = T = sigma = 0
//         only at pointed ends, over a grid of hull forms (EQ-HULLFORM-6)
//   hf-4  continuous limit: on a fine grid the fitted exponents approach the
//         closed forms C_h = n/(n+1) and the half-moment C_h/(2(2-C_h)) (EQ-HULLFORM-3)
//   hf-5  C_wp = C_p gives b = a, so sigma = C_m at every interior station (EQ-HULLFORM-5, -6)
//   hf-6  station positions run from -L/2 to +L/2 in equal steps (EQ-HULLFORM-1)
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "model/hull_form.hpp"
#include "test_support.hpp"

namespace towdb::model {
namespace {

// The fit solves for the trapezoid sums themselves with a 1e-12 bisection
// tolerance; 1e-9 relative leaves room for round-off in the sums of 21-1001 terms.
constexpr double kFittedIntegralRelTol = 1e-9;
// Station positions are computed as (2i - (N-1))/(N-1) * L/2: exact to round-off.
constexpr double kPositionAbsTolM = 1e-12;

HullFormParticulars particulars(double length_ft, double beam_ft, double draft_ft, double cb, double cm,
                                double lcb_ft, double cwp = 0.0) {
  HullFormParticulars p;
  p.length_pp_m = units::ft_to_m(length_ft);
  p.beam_m = units::ft_to_m(beam_ft);
  p.draft_m = units::ft_to_m(draft_ft);
  p.block_coefficient = cb;
  p.midship_coefficient = cm;
  p.lcb_m = units::ft_to_m(lcb_ft);
  p.waterplane_coefficient = cwp;
  return p;
}

// The seven towdb vessels' particulars as in ships/*.toml (C_m, LCB estimated there).
std::vector<HullFormParticulars> fleet() {
  return {
      particulars(204.0, 42.0, 15.0, 0.6155, 0.90, 1.0),      // T-ATF 166
      particulars(240.0, 50.0, 15.5, 0.6176, 0.90, 0.0),      // ARS 50
      particulars(778.0, 106.0, 26.0, 0.6517, 0.98, -7.8),    // LHA 1
      particulars(536.0, 81.0, 26.0, 0.6183, 0.97, -5.4),     // AE 26
      particulars(529.0, 55.0, 21.5, 0.5371, 0.82, -13.2),    // CG 47
      particulars(408.0, 45.0, 14.8, 0.5281, 0.80, -10.2),    // FFG 7
      particulars(151.3, 49.3, 3.4, 0.8971, 0.98, 0.0),       // YRBM
  };
}

// hf-1
TEST(HullForm, BoxBargeHasFullRectangularSections) {
  // EVIDENCE-OF: EQ-HULLFORM-7
  for (double cwp : {1.0, 0.0}) {  // given, and estimated as (1 + 2 C_b)/3 = 1
    const HullFormParticulars p = particulars(100.0, 40.0, 5.0, 1.0, 1.0, 0.0, cwp);
    const HullForm form = generate_hull_form(p);
    ASSERT_EQ(form.stations.size(), 21u);
    EXPECT_TRUE(form.is_box);
    for (const Station& s : form.stations) {
      EXPECT_EQ(s.beam_m, p.beam_m);
      EXPECT_EQ(s.draft_m, p.draft_m);
      EXPECT_EQ(s.area_coefficient, 1.0);
    }
    // A box's trapezoid volume is exact: L B T.
    EXPECT_REL_CLOSE(station_volume_m3(form.stations), p.length_pp_m * p.beam_m * p.draft_m,
                     kFittedIntegralRelTol);
  }
}

// hf-2
TEST(HullForm, VolumeLcbAndWaterplaneAreReproduced) {
  // EVIDENCE-OF: EQ-HULLFORM-4
  // EVIDENCE-OF: EQ-HULLFORM-5
  for (const HullFormParticulars& p : fleet()) {
    const HullForm form = generate_hull_form(p);
    const double lbt = p.length_pp_m * p.beam_m * p.draft_m;
    EXPECT_REL_CLOSE(station_volume_m3(form.stations), p.block_coefficient * lbt, kFittedIntegralRelTol);
    EXPECT_ABS_CLOSE(station_lcb_m(form.stations), p.lcb_m, kFittedIntegralRelTol * p.length_pp_m);
    EXPECT_REL_CLOSE(station_waterplane_area_m2(form.stations),
                     form.waterplane_coefficient * p.length_pp_m * p.beam_m, kFittedIntegralRelTol);
    // Default C_wp = (1 + 2 C_b)/3 (Papanikolaou 2014 eq. 2.83) unless below C_p.
    EXPECT_DOUBLE_EQ(form.waterplane_coefficient,
                     std::max((1.0 + 2.0 * p.block_coefficient) / 3.0, p.prismatic_coefficient()));
  }
  // A given C_wp and an even station count are honoured too.
  HullFormOptions options;
  options.station_count = 30;
  const HullFormParticulars p = particulars(400.0, 50.0, 16.0, 0.55, 0.85, 6.0, 0.74);
  const HullForm form = generate_hull_form(p, options);
  ASSERT_EQ(form.stations.size(), 30u);
  EXPECT_REL_CLOSE(station_volume_m3(form.stations), 0.55 * p.length_pp_m * p.beam_m * p.draft_m,
                   kFittedIntegralRelTol);
  EXPECT_ABS_CLOSE(station_lcb_m(form.stations), p.lcb_m, kFittedIntegralRelTol * p.length_pp_m);
  EXPECT_REL_CLOSE(station_waterplane_area_m2(form.stations), 0.74 * p.length_pp_m * p.beam_m,
                   kFittedIntegralRelTol);
}

// hf-3
TEST(HullForm, AreaCoefficientStaysInUnitInterval) {
  // EVIDENCE-OF: EQ-HULLFORM-6
  int checked = 0;
  for (int n : {5, 11, 21, 41}) {
    HullFormOptions options;
    options.station_count = n;
    for (double cb : {0.40, 0.50, 0.60, 0.70, 0.80}) {
      for (double cm : {0.80, 0.90, 0.98}) {
        // A pointed-end half holds at most 1 - 1/(N-1) of its box (0.75 for N = 5):
        // skip forms the method rejects (the unit tests check that rejection).
        const double fullest = std::max(cb / cm, (1.0 + 2.0 * cb) / 3.0);
        if (fullest > 1.0 - 1.0 / (n - 1) - 0.05) continue;
        for (double lcb_fraction : {-0.02, 0.0, 0.02}) {
          const HullFormParticulars p = particulars(300.0, 40.0, 12.0, cb, cm, lcb_fraction * 300.0);
          const HullForm form = generate_hull_form(p, options);
          ASSERT_EQ(form.stations.size(), static_cast<std::size_t>(n));
          for (std::size_t i = 0; i < form.stations.size(); ++i) {
            const Station& s = form.stations[i];
            const bool end = (i == 0 || i + 1 == form.stations.size());
            if (s.beam_m > 0.0) {
              EXPECT_GT(s.area_coefficient, 0.0) << "cb " << cb << " cm " << cm << " station " << i;
              EXPECT_LE(s.area_coefficient, cm * (1.0 + 1e-12)) << "cb " << cb << " station " << i;
              EXPECT_EQ(s.draft_m, p.draft_m);
            } else {
              EXPECT_TRUE(end) << "zero beam inside the hull at station " << i;
              EXPECT_EQ(s.draft_m, 0.0);
              EXPECT_EQ(s.area_coefficient, 0.0);
            }
            EXPECT_LE(s.beam_m, p.beam_m);
          }
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 100);
}

// hf-4
TEST(HullForm, FineGridApproachesClosedFormExponents) {
  // EVIDENCE-OF: EQ-HULLFORM-3
  HullFormOptions options;
  options.station_count = 1001;
  // The trapezoid sum of 1 - xi^n on 500 intervals per half differs from
  // n/(n+1) by about n dxi^2/12 = 1e-6; the exponent then moves by
  // (n+1)^2 * 1e-6 < 2e-5: 1e-3 relative is ample and still fails for any
  // error in the closed forms.
  constexpr double kExponentRelTol = 1e-3;
  {
    // Symmetric: C_p = 0.75 -> each half C_h = 0.75 -> n = C_h/(1 - C_h) = 3.
    const HullForm form = generate_hull_form(particulars(200.0, 30.0, 10.0, 0.75, 1.0, 0.0), options);
    EXPECT_REL_CLOSE(form.area_exponent_fore, 3.0, kExponentRelTol);
    EXPECT_REL_CLOSE(form.area_exponent_aft, 3.0, kExponentRelTol);
  }
  {
    // n_f = 3 (C_f = 3/4), n_a = 1 (C_a = 1/2): C_p = 5/8 and
    // 2 LCB/L = [0.75/2.5 - 0.5/3] / (0.75 + 0.5) = 0.106667, LCB = 0.053333 L.
    const double length_ft = 300.0;
    const double lcb_ft = 0.5 * length_ft * (0.75 / 2.5 - 0.5 / 3.0) / 1.25;
    const HullForm form =
        generate_hull_form(particulars(length_ft, 40.0, 12.0, 0.625, 1.0, lcb_ft), options);
    EXPECT_REL_CLOSE(form.area_exponent_fore, 3.0, kExponentRelTol);
    EXPECT_REL_CLOSE(form.area_exponent_aft, 1.0, kExponentRelTol);
  }
}

// hf-5
TEST(HullForm, WaterplaneEqualToPrismaticGivesConstantSigma) {
  // EVIDENCE-OF: EQ-HULLFORM-5
  // EVIDENCE-OF: EQ-HULLFORM-6
  // r = (1 - C_wp)/(1 - C_p) = 1 makes each waterline half as full as its
  // area half, so p_h = n_h, b = a and sigma = C_m a / b = C_m.
  constexpr double kSigmaAbsTol = 1e-9;  // b and a agree to the 1e-12 bisection tolerance
  const double cb = 0.56;
  const double cm = 0.8;
  const HullFormParticulars p = particulars(350.0, 42.0, 14.0, cb, cm, -5.0, cb / cm);
  const HullForm form = generate_hull_form(p);
  for (std::size_t i = 1; i + 1 < form.stations.size(); ++i) {
    EXPECT_ABS_CLOSE(form.stations[i].area_coefficient, cm, kSigmaAbsTol) << "station " << i;
  }
}

// hf-6
TEST(HullForm, StationsAreEquallySpacedFromAftToForwardPerpendicular) {
  // EVIDENCE-OF: EQ-HULLFORM-1
  const HullFormParticulars p = particulars(204.0, 42.0, 15.0, 0.6155, 0.90, 1.0);
  const HullForm form = generate_hull_form(p);
  const double half = 0.5 * p.length_pp_m;
  for (std::size_t i = 0; i < form.stations.size(); ++i) {
    EXPECT_ABS_CLOSE(form.stations[i].x_m, -half + static_cast<double>(i) * p.length_pp_m / 20.0,
                     kPositionAbsTolM);
  }
  EXPECT_EQ(form.stations[10].x_m, 0.0);  // odd N: a station at midships with sigma = C_m
  EXPECT_ABS_CLOSE(form.stations[10].area_coefficient, 0.90, 1e-15);
}

}  // namespace
}  // namespace towdb::model
