// Options validation and input edge cases of the seakeeping module.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "seakeeping/seakeeping.hpp"
#include "seakeeping_hulls.hpp"
#include "test_support.hpp"

namespace towdb::seakeeping {
namespace {

using test::expect_input_error;

TEST(SeakeepingOptions, SectionOptionsRejectBadValues) {
  SectionOptions o;
  EXPECT_NO_THROW(o.validate());
  o.max_terms = o.min_terms;
  expect_input_error([&] { o.validate(); }, "SectionOptions.max_terms");
  o = SectionOptions{};
  o.convergence_tolerance = 0.0;
  expect_input_error([&] { o.validate(); }, "SectionOptions.convergence_tolerance");
  o = SectionOptions{};
  o.quadrature_points = 2;
  expect_input_error([&] { o.validate(); }, "SectionOptions.quadrature_points");
  o = SectionOptions{};
  o.lewis.min_half_beam_draft_ratio = 0.0;
  expect_input_error([&] { o.validate(); }, "LewisOptions.min_half_beam_draft_ratio");
}

TEST(SeakeepingOptions, ResponseAndAddedResistanceOptionsRejectBadValues) {
  ResponseOptions r;
  EXPECT_NO_THROW(r.validate());
  r.min_encounter_frequency_nondim = 0.0;
  expect_input_error([&] { r.validate(); }, "min_encounter_frequency_nondim");
  AddedResistanceOptions a;
  EXPECT_NO_THROW(a.validate());
  // The default step is the thesis's 1 ft/s.
  EXPECT_DOUBLE_EQ(a.speed_step_m_s, 0.3048);
  a.omega_max_rad_s = a.omega_min_rad_s;
  expect_input_error([&] { a.validate(); }, "omega_max_rad_s");
  a = AddedResistanceOptions{};
  a.omega_count = 2;
  expect_input_error([&] { a.validate(); }, "omega_count");
}

TEST(SeakeepingOptions, LewisFormRejectsNonPhysicalSections) {
  expect_input_error([] { lewis_form(0.0, 1.0, 0.8); }, "beam_m");
  expect_input_error([] { lewis_form(1.0, -1.0, 0.8); }, "draft_m");
  expect_input_error([] { lewis_form(1.0, 1.0, 1.2); }, "area_coefficient");
}

TEST(SeakeepingOptions, ExtremeProportionsAreClampedAndFlagged) {
  // EVIDENCE-OF: EQ-LEWIS-5
  const LewisForm thin = lewis_form(0.02, 1.0, 0.7);  // B/(2T) = 0.01 < 0.05
  EXPECT_TRUE(thin.proportions_adjusted);
  EXPECT_NEAR(thin.draft_m, 1.0, 1e-12);
  EXPECT_NEAR(thin.half_beam_m, 0.05, 1e-12);
  const LewisForm flat = lewis_form(40.0, 1.0, 0.9);  // B/(2T) = 20 > 15
  EXPECT_TRUE(flat.proportions_adjusted);
  EXPECT_NEAR(flat.draft_m, 20.0 / 15.0, 1e-12);
  EXPECT_FALSE(lewis_form(10.0, 4.0, 0.9).proportions_adjusted);
}

TEST(SeakeepingOptions, DegenerateSectionGivesZeroCoefficients) {
  const SectionSolution s = solve_lewis_section(0.0, 2.0, 0.0, 1.0);
  EXPECT_TRUE(s.degenerate);
  EXPECT_EQ(s.coefficients.a33, 0.0);
  EXPECT_EQ(s.coefficients.b22, 0.0);
  EXPECT_TRUE(s.nodes.empty());
  expect_input_error([] { solve_lewis_section(2.0, 1.0, 0.8, 0.0); }, "omega_rad_s");
}

TEST(SeakeepingOptions, ComputeResponseRejectsBadInputs) {
  const model::Vessel v = test::wigley_vessel();
  expect_input_error([&] { compute_response(v, -1.0, kPi, {2.0}); }, "speed_m_s");
  expect_input_error([&] { compute_response(v, 1.0, std::nan(""), {2.0}); }, "heading_rad");
  expect_input_error([&] { compute_response(v, 1.0, kPi, {-2.0}); }, "omega_rad_s");
  model::Vessel bad = v;
  std::swap(bad.hull.stations[3], bad.hull.stations[4]);
  expect_input_error([&] { compute_response(bad, 1.0, kPi, {2.0}); }, "x_m");
  model::Vessel few = v;
  few.hull.stations.resize(2);
  expect_input_error([&] { compute_response(few, 1.0, kPi, {2.0}); }, "stations");
}

TEST(SeakeepingOptions, MassAndRestoringMatricesAreConsistent) {
  // EVIDENCE-OF: EQ-STRIP-5
  // EVIDENCE-OF: EQ-STRIP-6
  const model::Vessel v = test::wigley_vessel();
  const Matrix6d m = rigid_body_mass_matrix(v.hull);
  const double zg = v.hull.kg_m - v.hull.draft_m;
  EXPECT_DOUBLE_EQ(m(kSway, kRoll), -v.hull.displacement_kg * zg);
  EXPECT_DOUBLE_EQ(m(kSurge, kPitch), v.hull.displacement_kg * zg);
  EXPECT_TRUE(m.isApprox(m.transpose(), 1e-14));
  const Matrix6d c = hydrostatic_restoring_matrix(v.hull);
  // Waterplane of the Wigley hull: B L int (1-xi^2)(1+0.2 xi^2) dxi / 2 =
  // B L (52/75); the 41-station trapezoid sum is within 0.2%.
  constexpr double kTrapezoidRelTol = 2e-3;
  EXPECT_REL_CLOSE(c(kHeave, kHeave) / (kRhoSeawater_kg_m3 * kGravity_m_s2),
                   v.hull.beam_m * v.hull.length_pp_m * 52.0 / 75.0, kTrapezoidRelTol);
  EXPECT_DOUBLE_EQ(c(kRoll, kRoll), v.hull.displacement_kg * kGravity_m_s2 * v.hull.gm_m);
  EXPECT_NEAR(c(kHeave, kPitch), 0.0, 1e-9 * c(kHeave, kHeave));  // fore-aft symmetric
}

}  // namespace
}  // namespace towdb::seakeeping
