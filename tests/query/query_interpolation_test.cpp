// Interpolation, statistics and inverse queries of the query library, on
// synthetic databases whose Gumbel parameters are known analytic functions of
// the inputs (tests/query/synthetic_db.hpp). Equations: towdb/query.h.
// Test plan:
//   query-interp-1  every stored case is reproduced exactly (linear and log space)
//   query-interp-2  a multilinear function is reproduced exactly anywhere in the grid (linear space)
//   query-interp-3  an exp(multilinear) function is reproduced exactly in log space; auto picks log
//   query-interp-3b the stored interval is interpolated in the answer's space (brackets the answer)
//   query-interp-4  heading folding: h and 360 - h give identical answers
//   query-interp-5  D-day and any-probability quantiles satisfy F(x)^D = 1 - p
//   query-interp-6  thesis Appendix A check value (mean 41.06, variance 10.80 -> 57.27 kips)
//   query-interp-7  the error estimate equals the true error for a quadratic; CI scaling
//   query-interp-8  monotone in wind on monotone data; a warning where the data is not
//   query-interp-9  Navy Towing Manual checks and limits; warnings (slack, above BS, > 300 kips)
//   query-interp-10 extrapolation: refused, then exact for linear data with a warning
//   query-interp-11 incomplete grid: refused, then renormalised with a warning
//   query-interp-12 inverse queries land on the analytic crossing; "none passes"
//   query-interp-13 nearest cases are sorted by distance and start at the node queried
//   query-interp-14 leave-one-out error of a quadratic equals a h^2
//   query-interp-15 relative mean-tension axis (EQ-QUERY-9): exact for data linear in m / T_calc; the default is
//                   T_calc at the query; a factor outside the stored ones is refused in its own terms; a question
//                   the absolute axis refuses is answered; the tugs' capacity warning
//   query-interp-16 max-speed stops where the calculated mean tension reaches the tugs' 125,000 lbf
//   query-interp-17 a sea given as Hs (and Tp) on a wind-sea database: answered at the equivalent wind, said so;
//                   a Tp far from that sea's refused naming both periods (EQ-QUERY-10)
//   query-interp-18 heading profiles (EQ-QUERY-11): data equal to a smooth factor times a line's stored
//                   profile are exact between stored headings, in log and linear space; a cell with a
//                   corner without a profile is interpolated as before, never half corrected, and so is its
//                   error estimate; the estimate along a corner's mean tensions moves with the corner
//   query-interp-23 the heading profile's exponent (EQ-QUERY-11): data equal to a factor times the profile
//                   squared are exact between stored headings (k = 2 measured from the stored headings); data
//                   with a shallower or deeper shape than the profile get k clamped to 1 or 2 (the formula
//                   checked at a cell's interior point)
//   query-interp-20 speed profiles (EQ-QUERY-12): data equal to a smooth factor times a line's stored speed
//                   profile (a fold-like swing inside a 2 kt cell) are exact between stored speeds, alone and
//                   with a heading profile; the error estimate along speed then vanishes
//   query-interp-21 searches (EQ-QUERY-5): a sea given as Hs is searched at its equivalent wind; the searched
//                   field is ignored whatever it holds; extrapolation is never used; a search where no value can
//                   be evaluated is refused with the kind of its first failure (RANGE outside the stored winds)
//   query-interp-22 EQ-QUERY-7: the full chord estimate along an axis of three or more values when no node beside
//                   the cell can be evaluated at the question; the stored interval in log space at a node between
//                   its stored mean tensions
//   query-interp-19 a node's mean tensions (EQ-QUERY-6): the monotone cubic is close to a smooth function where
//                   the chord is not, never overshoots a steep rise or a local maximum, and is the chord with two
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/constants.hpp"
#include "synthetic_db.hpp"
#include "test_support.hpp"
#include "towdb/query.hpp"

namespace towdb::test {
namespace {

using query::Database;
using query::QueryError;
using query::QueryRequest;
using query::QueryResult;

// Round-off of a 16-corner weighted sum and one mean-tension interpolation:
// a few ulp per operation on values of order 100.
constexpr double kRoundOffRelTol = 1e-12;
// The thesis prints the Appendix A inputs and output with two decimals: the
// rounded mean (+-0.005), the rounded variance (+-0.005 kips^2, times
// dx/dvar = 4.94/(2 sigma) = 0.75) and the printed output (+-0.005) allow
// |x - 57.27| <= 0.0138 kips.
constexpr double kThesisPrintAbsTol_kips = 0.014;

double u_multilinear(double s, double w, double h, double l, double m) {
  return 5.0 + 1.5 * s + 2.0 * w + 0.05 * h - 0.01 * l + 0.0004 * m + 0.02 * s * w - 0.00001 * w * l +
         5e-6 * w * m;
}
double beta_multilinear(double s, double w, double h, double /*l*/, double m) {
  return 2.0 + 0.1 * w + 0.00002 * m + 0.01 * s + 0.002 * h;
}
double u_exponential(double s, double w, double h, double l, double m) {
  return 40.0 * std::exp(0.05 * s + 0.03 * w - 0.0005 * l + 0.002 * h + 5e-6 * m);
}
double beta_exponential(double /*s*/, double w, double /*h*/, double /*l*/, double m) {
  return 8.0 * std::exp(0.02 * w + 3e-6 * m);
}

class QueryTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = make_temp_dir("towdb-query"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::vector<SyntheticCase>& cases, const std::string& name = "t.towdb") {
    const auto p = dir_ / name;
    write_synthetic_db(p, cases);
    return p.string();
  }
  std::filesystem::path dir_;
};

QueryRequest request(double s, double w, double h, double l, double m) {
  QueryRequest r;
  r.tug = "T-ATF 166";
  r.tow = "LHA 1";
  r.line = "wire";
  r.values.speed_kt = s;
  r.values.wind_kt = w;
  r.values.heading_deg = h;
  r.values.length_ft = l;
  r.values.mean_tension_lbf = m;
  return r;
}

// The mean tensions every corner node of the (speed, wind) cell holds:
// [0.6 max nominal, 1.15 min nominal] (synthetic_db.hpp mean_factors).
std::pair<double, double> common_mean_range(const GridSpec& g, double s, double w) {
  auto cell = [](const std::vector<double>& axis, double q) {
    auto hi = std::upper_bound(axis.begin(), axis.end(), q);
    if (hi == axis.end()) --hi;
    return std::pair<double, double>(*(hi - 1), *hi);
  };
  const auto [s0, s1] = cell(g.speeds_kt, s);
  const auto [w0, w1] = cell(g.winds_kt, w);
  double lo = 0.0, hi = 1e300;
  for (double ss : {s0, s1}) {
    for (double ww : {w0, w1}) {
      lo = std::max(lo, 0.6 * g.nominal_mean_lbf(ss, ww));
      hi = std::min(hi, 1.15 * g.nominal_mean_lbf(ss, ww));
    }
  }
  return {lo, hi};
}

// A random query inside the grid (speed 3-9 kt, wind 20-35 kt, heading 0-180
// deg, length 800-2,000 ft) at a mean tension every corner node stores.
struct QueryPoint {
  double s, w, h, l, m;
};

QueryPoint random_point(std::mt19937& rng, const GridSpec& g) {
  std::uniform_real_distribution<double> us(3.0, 9.0), uw(20.0, 35.0), uh(0.0, 180.0), ul(800.0, 2000.0), uf(0.0, 1.0);
  const double s = us(rng), w = uw(rng), h = uh(rng), l = ul(rng);
  const auto [m0, m1] = common_mean_range(g, s, w);
  return {s, w, h, l, m0 + uf(rng) * (m1 - m0)};
}

GridSpec multilinear_grid() {
  GridSpec g;
  g.u_kips = u_multilinear;
  g.beta_kips = beta_multilinear;
  return g;
}

bool has_warning(const QueryResult& r, int kind) {
  return std::any_of(r.warnings.begin(), r.warnings.end(), [&](const auto& w) { return w.kind == kind; });
}

// query-interp-1
TEST_F(QueryTest, ReproducesEveryStoredCaseExactly) {
  // EVIDENCE-OF: EQ-QUERY-6 (weights 1 at a node; mean tension at a stored value), on the absolute
  // and on the relative (EQ-QUERY-9) mean-tension axis.
  for (bool relative : {false, true}) {
    GridSpec g = multilinear_grid();
    g.store_calculated = relative;
    const auto cases = grid_cases(g);
    const std::string path = write(cases, relative ? "relative.towdb" : "absolute.towdb");
    for (int space : {TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_SPACE_LOG}) {
      Database db(path, space);
      ASSERT_EQ(db.case_count(), static_cast<int>(cases.size()));
      for (const SyntheticCase& c : cases) {
        const QueryResult r =
            db.query(request(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf));
        EXPECT_EQ(r.values.gumbel_u_kips, c.u_kips);  // bit for bit
        EXPECT_REL_CLOSE(r.values.gumbel_alpha_per_kip, c.alpha_per_kip, 1e-15);
        EXPECT_REL_CLOSE(r.values.dynamic_999_kips, c.u_kips + reduced_variate_999() / c.alpha_per_kip, 1e-15);
        EXPECT_EQ(r.values.interpolation_error_kips, 0.0);
        EXPECT_EQ(r.values.extrapolated, 0);
      }
    }
  }
}

// query-interp-1b
TEST_F(QueryTest, CatenarySagAndDepthAreInterpolatedWithTheTensionsWeights) {
  // EVIDENCE-OF: EQ-QUERY-6 (the sag and the lowest point of the stored towline fits, weighted as
  // u and beta in linear space: exact for values multilinear in the axes and linear in the mean
  // tension; the depth is minus the stored elevation; NaN without fits or before schema 6)
  const GridSpec g = multilinear_grid();
  // Positive at every node (>= 23 ft): a stored sag below 0 is refused on open (a catenary hangs below its chord).
  auto sag = [](double s, double w, double h, double l, double m) {
    return 30.0 + 0.02 * l - 2e-4 * m + 0.1 * s + 0.01 * w * l / 1000.0 + 0.001 * h;
  };
  // Elevation of the lowest point: above the water for short taut lines, below it for long ones.
  auto elevation = [](double s, double w, double h, double l, double m) {
    return 40.0 - 0.03 * l + 1e-4 * m - 0.2 * s - 0.05 * w + 0.002 * h;
  };
  std::vector<SyntheticCase> cases = grid_cases(g);
  const std::string without = write(cases, "no-fits.towdb");
  for (SyntheticCase& c : cases) c.sag_ft = sag(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf);
  const std::string before_6 = write(cases, "fits-without-lowest-point.towdb");
  for (SyntheticCase& c : cases) {
    c.lowest_elevation_ft = elevation(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf);
  }
  Database db(write(cases, "fits.towdb"), TOWDB_QUERY_SPACE_LOG);
  int above_water = 0, below_water = 0;
  std::mt19937 rng(2026);
  for (int i = 0; i < 100; ++i) {
    const auto [s, w, h, l, m] = random_point(rng, g);
    const QueryResult r = db.query(request(s, w, h, l, m));
    EXPECT_REL_CLOSE(r.values.catenary_sag_ft, sag(s, w, h, l, m), kRoundOffRelTol) << s << " " << w << " " << h;
    const double depth = -elevation(s, w, h, l, m);
    EXPECT_NEAR(r.values.catenary_depth_ft, depth, kRoundOffRelTol * std::max(1.0, std::abs(depth)));
    (depth < 0.0 ? above_water : below_water) += 1;
  }
  EXPECT_GT(above_water, 0);  // the test covers both signs
  EXPECT_GT(below_water, 0);
  const SyntheticCase& c = cases.front();
  const QueryResult old = Database(before_6, TOWDB_QUERY_SPACE_LOG)
                              .query(request(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf));
  EXPECT_TRUE(std::isfinite(old.values.catenary_sag_ft));
  EXPECT_TRUE(std::isnan(old.values.catenary_depth_ft));
  EXPECT_TRUE(std::isnan(Database(without, TOWDB_QUERY_SPACE_LOG)
                             .query(request(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf))
                             .values.catenary_sag_ft));
}

// query-interp-2
TEST_F(QueryTest, MultilinearFunctionIsReproducedAnywhere) {
  // EVIDENCE-OF: EQ-QUERY-6 (multilinear weights are exact for multilinear data)
  const GridSpec g = multilinear_grid();
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LINEAR);
  EXPECT_EQ(db.space(), TOWDB_QUERY_SPACE_LINEAR);
  std::mt19937 rng(12345);
  for (int i = 0; i < 300; ++i) {
    const auto [s, w, h, l, m] = random_point(rng, g);
    const QueryResult r = db.query(request(s, w, h, l, m));
    const double expected = u_multilinear(s, w, h, l, m) + reduced_variate_999() * beta_multilinear(s, w, h, l, m);
    EXPECT_REL_CLOSE(r.values.dynamic_999_kips, expected, kRoundOffRelTol) << s << " " << w << " " << h << " " << l << " " << m;
    EXPECT_REL_CLOSE(r.values.gumbel_u_kips, u_multilinear(s, w, h, l, m), kRoundOffRelTol);
  }
}

// query-interp-3
TEST_F(QueryTest, ExponentialFunctionIsExactInLogSpaceAndAutoChoosesLog) {
  // EVIDENCE-OF: EQ-QUERY-6 (log space), EQ-QUERY-8 (space chosen by leave-one-out)
  GridSpec g;
  g.u_kips = u_exponential;
  g.beta_kips = beta_exponential;
  const std::string path = write(grid_cases(g));
  Database db(path);  // auto
  EXPECT_EQ(db.space(), TOWDB_QUERY_SPACE_LOG);
  const towdb_query_loo log_loo = db.leave_one_out(TOWDB_QUERY_SPACE_LOG);
  const towdb_query_loo lin_loo = db.leave_one_out(TOWDB_QUERY_SPACE_LINEAR);
  EXPECT_GT(log_loo.samples, 100);
  EXPECT_LT(log_loo.max_rel_error, 1e-12);  // exp(linear) is linear in log space
  EXPECT_GT(lin_loo.median_rel_error, 1e-4);
  std::mt19937 rng(777);
  for (int i = 0; i < 200; ++i) {
    const auto [s, w, h, l, m] = random_point(rng, g);
    const QueryResult r = db.query(request(s, w, h, l, m));
    EXPECT_EQ(r.values.interpolation_space, TOWDB_QUERY_SPACE_LOG);
    EXPECT_REL_CLOSE(r.values.gumbel_u_kips, u_exponential(s, w, h, l, m), kRoundOffRelTol);
    EXPECT_REL_CLOSE(1.0 / r.values.gumbel_alpha_per_kip, beta_exponential(s, w, h, l, m), kRoundOffRelTol);
  }
  // The same data with multilinear parameters: auto keeps linear space.
  Database lin(write(grid_cases(multilinear_grid()), "lin.towdb"));
  EXPECT_EQ(lin.space(), TOWDB_QUERY_SPACE_LINEAR);
}

// query-interp-3b
TEST_F(QueryTest, StoredIntervalIsInterpolatedInTheAnswersSpace) {
  // EVIDENCE-OF: EQ-QUERY-6 (the stored interval's bounds in the same space as u and beta).
  // Parameters that change by a factor of 7 across the grid, each case's interval +/-5 % of its
  // dynamic_999: in log space the answer is a geometric mean of the corners and the interval
  // is too, so it brackets the answer (a linear mean of the bounds lay up to 60 % above it).
  GridSpec g;
  g.u_kips = [](double s, double w, double h, double l, double m) {
    return 40.0 * std::exp(0.1 * s + 0.02 * w - 0.0015 * l + 0.004 * h + 5e-6 * m);
  };
  g.beta_kips = [](double s, double w, double h, double l, double m) {
    return 8.0 * std::exp(0.1 * s + 0.02 * w - 0.0015 * l + 0.004 * h + 5e-6 * m);
  };
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LOG);
  std::mt19937 rng(31);
  for (int i = 0; i < 200; ++i) {
    const auto [s, w, h, l, m] = random_point(rng, g);
    const towdb_query_result v = db.query(request(s, w, h, l, m)).values;
    // u and beta share their exponent: x999 is exp(multilinear), the bounds exactly 0.95 and 1.05 of it.
    EXPECT_REL_CLOSE(v.ci_low_kips, 0.95 * v.dynamic_999_kips, kRoundOffRelTol) << s << " " << l << " " << h;
    EXPECT_REL_CLOSE(v.ci_high_kips, 1.05 * v.dynamic_999_kips, kRoundOffRelTol) << s << " " << l << " " << h;
  }
  // Linear space keeps the linear mean of the bounds, as it does for u and beta.
  Database lin(write(grid_cases(multilinear_grid()), "lin.towdb"), TOWDB_QUERY_SPACE_LINEAR);
  const towdb_query_result v = lin.query(request(6.0, 25.0, 37.0, 1200.0, 60000.0)).values;
  EXPECT_REL_CLOSE(v.ci_low_kips, 0.95 * v.dynamic_999_kips, kRoundOffRelTol);
  EXPECT_REL_CLOSE(v.ci_high_kips, 1.05 * v.dynamic_999_kips, kRoundOffRelTol);
}

// query-interp-4
TEST_F(QueryTest, HeadingIsFoldedByPortStarboardSymmetry) {
  // EVIDENCE-OF: EQ-QUERY-6 (h > 180 -> 360 - h)
  const GridSpec g = multilinear_grid();
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LINEAR);
  for (double h : {0.0, 37.0, 60.0, 135.5, 180.0}) {
    const QueryResult a = db.query(request(6.0, 25.0, h, 1200.0, 60000.0));
    const QueryResult b = db.query(request(6.0, 25.0, 360.0 - h, 1200.0, 60000.0));
    EXPECT_EQ(a.values.dynamic_tension_kips, b.values.dynamic_tension_kips) << h;
  }
}

// query-interp-5
TEST_F(QueryTest, LongerTowsAndOtherProbabilitiesFollowTheGumbelLaw) {
  // EVIDENCE-OF: EQ-QUERY-2, EQ-QUERY-3, EQ-QUERY-4
  const GridSpec g = multilinear_grid();
  const auto cases = grid_cases(g);
  Database db(write(cases), TOWDB_QUERY_SPACE_LINEAR);
  const SyntheticCase& c = cases[17];
  const double beta = 1.0 / c.alpha_per_kip;
  for (double days : {1.0, 7.0, 30.0}) {
    for (double p : {0.5, 0.01, 0.001, 1e-5}) {
      QueryRequest rq = request(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf);
      rq.values.probability = p;
      rq.values.tow_days = days;
      const QueryResult r = db.query(rq);
      const double x = r.values.dynamic_tension_kips;
      // The D-day maximum's distribution F(x)^D must equal 1 - p at the answer.
      const double f_d = std::pow(std::exp(-std::exp(-(x - c.u_kips) / beta)), days);
      EXPECT_REL_CLOSE(f_d, 1.0 - p, 1e-12) << days << " " << p;
      EXPECT_REL_CLOSE(r.values.extreme_tension_lbf, c.mean_tension_lbf + 1000.0 * x, 1e-15);
    }
  }
}

// query-interp-6
TEST_F(QueryTest, ThesisAppendixACheckValue) {
  // EVIDENCE-OF: EQ-QUERY-3. EQ-STAT-3 (docs/physics.md 7) / thesis Appendix A sample
  // output: daily maxima with mean 41.06 kips and variance 10.80 kips^2 give a
  // method-of-moments Type I with x_0.999 = 57.27 kips.
  SyntheticCase c;
  const double alpha = kPi / std::sqrt(6.0 * 10.80);
  c.alpha_per_kip = alpha;
  c.u_kips = 41.06 - kEulerGamma / alpha;
  Database db(write({c}));
  const QueryResult r = db.query(request(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf));
  EXPECT_ABS_CLOSE(r.values.dynamic_tension_kips, 57.27, kThesisPrintAbsTol_kips);
}

// query-interp-7
TEST_F(QueryTest, ErrorEstimateIsExactForAQuadraticAndCiIsScaled) {
  // EVIDENCE-OF: EQ-QUERY-7. Linear interpolation of f = a (w - w0)^2 over a
  // cell of width h errs by t (1 - t) h^2 a, and the second divided difference
  // of a quadratic is exactly a, so estimate and error agree. (w0 = 27.5 kt
  // keeps the chord's rise over each cell, 50 a, small enough that the floor
  // of half the chord estimate, t (1 - t) 25 a, does not exceed it.)
  constexpr double kA = 0.05;  // kips per kt^2
  constexpr double kW0 = 27.5;
  GridSpec g;
  g.u_kips = [](double s, double w, double, double l, double) {
    return 20.0 + kA * (w - kW0) * (w - kW0) + 0.5 * s - 0.001 * l;
  };
  g.beta_kips = [](double, double, double, double, double) { return 5.0; };
  auto cases = grid_cases(g);
  for (auto& c : cases) {
    c.ci_low_kips = 100.0;
    c.ci_high_kips = 108.0;  // half-width 4 kips
  }
  Database db(write(cases), TOWDB_QUERY_SPACE_LINEAR);
  for (double w : {22.0, 25.0, 28.5, 31.0, 33.0}) {
    const double s = 5.0, l = 1500.0, m = 60000.0;
    const QueryResult r = db.query(request(s, w, 60.0, l, m));
    const double truth = 20.0 + kA * (w - kW0) * (w - kW0) + 0.5 * s - 0.001 * l + 5.0 * reduced_variate_999();
    const double actual_error = std::abs(r.values.dynamic_999_kips - truth);
    EXPECT_GT(actual_error, 0.1) << w;
    EXPECT_REL_CLOSE(r.values.interpolation_error_kips, actual_error, 1e-9) << w;
    EXPECT_REL_CLOSE(r.values.uncertainty_kips, std::hypot(actual_error, 4.0), 1e-9) << w;
  }
  // CI half-width scaled by sqrt(1 + 1.1396 K + 1.1 K^2) (Kite 1977) to (p, D).
  auto se = [](double p, double d) {
    const double k = std::sqrt(6.0) / kPi * (std::log(d) - std::log(-std::log(1.0 - p)) - kEulerGamma);
    return std::sqrt(1.0 + 1.1396 * k + 1.1 * k * k);
  };
  QueryRequest rq = request(5.0, 30.0, 60.0, 1500.0, 60000.0);  // a node: no interpolation error
  rq.values.probability = 0.01;
  rq.values.tow_days = 10.0;
  const QueryResult r = db.query(rq);
  EXPECT_EQ(r.values.interpolation_error_kips, 0.0);
  EXPECT_REL_CLOSE(r.values.uncertainty_kips, 4.0 * se(0.01, 10.0) / se(0.001, 1.0), 1e-12);

  // The floor: on linear data (no curvature) a grid axis with three or more values still reports half the
  // chord estimate, t (1 - t) |f(x_i+1) - f(x_i)| / 2 (docs/audit.md: the tension can change abruptly inside a
  // cell); along an axis with only two values, the full chord estimate.
  GridSpec lin;
  lin.lengths_ft = {1000.0, 2000.0};
  lin.u_kips = [](double, double w, double, double l, double) { return 10.0 + 2.0 * w + 0.01 * l; };
  lin.beta_kips = [](double, double, double, double, double) { return 5.0; };
  Database dl(write(grid_cases(lin), "linear.towdb"), TOWDB_QUERY_SPACE_LINEAR);
  const QueryResult rw = dl.query(request(5.0, 22.0, 60.0, 1000.0, 60000.0));  // wind: t = 0.2 of 20 -> 30 kt
  EXPECT_REL_CLOSE(rw.values.interpolation_error_kips, 0.5 * 0.2 * 0.8 * 20.0, 1e-9);
  const QueryResult rl = dl.query(request(5.0, 30.0, 60.0, 1250.0, 60000.0));  // length: t = 0.25, two values
  EXPECT_REL_CLOSE(rl.values.interpolation_error_kips, 0.25 * 0.75 * 10.0, 1e-9);
}

// query-interp-8
TEST_F(QueryTest, MoreWindNeverLowersTheAnswerOrAWarningSaysSo) {
  // EVIDENCE-OF: EQ-QUERY-6 (linear-space answer is a positive combination of
  // corner values), thesis 6.3.1 (wind speed is the most important variable).
  const GridSpec g = multilinear_grid();
  auto cases = grid_cases(g);
  {
    Database db(write(cases), TOWDB_QUERY_SPACE_LINEAR);
    double previous = 0.0;
    for (double w = 20.0; w <= 35.0; w += 0.25) {
      const QueryResult r = db.query(request(6.3, w, 75.0, 1700.0, 65000.0));
      EXPECT_GE(r.values.dynamic_tension_kips, previous) << w;
      EXPECT_FALSE(has_warning(r, TOWDB_QUERY_WARN_NOT_MONOTONE)) << w;
      previous = r.values.dynamic_tension_kips;
    }
  }
  // Lower the stored answer at one 30 kt node below its 20 kt neighbour.
  for (auto& c : cases) {
    if (c.speed_kt == 5.0 && c.wind_kt == 30.0 && c.heading_deg == 60.0 && c.length_ft == 1500.0) c.u_kips = 1.0;
  }
  Database bad(write(cases, "bad.towdb"), TOWDB_QUERY_SPACE_LINEAR);
  const QueryResult r = bad.query(request(5.0, 25.0, 60.0, 1500.0, 60000.0));
  ASSERT_TRUE(has_warning(r, TOWDB_QUERY_WARN_NOT_MONOTONE));
  const QueryResult fine = bad.query(request(5.0, 32.0, 60.0, 1500.0, 60000.0));
  EXPECT_FALSE(has_warning(fine, TOWDB_QUERY_WARN_NOT_MONOTONE));
}

// query-interp-9
TEST_F(QueryTest, NavyTowingManualChecksAndWarnings) {
  // EVIDENCE-OF: EQ-QUERY-5: extreme <= BS/1.5; mean <= BS/3 (machine) or BS/5 (brake).
  SyntheticCase c;
  c.breaking_strength_lbf = 300000.0;
  c.mean_tension_lbf = 90000.0;
  c.alpha_per_kip = 1.0 / 5.0;
  c.u_kips = 100.0 - 5.0 * reduced_variate_999();  // dynamic_999 = 100 kips
  SyntheticCase slack = c;
  slack.tow = "YRBM";
  slack.slack_fraction = 0.05;
  SyntheticCase big = c;
  big.tow = "FFG 7";
  big.u_kips = 320.0;  // > 300 kips and above breaking strength
  Database db(write({c, slack, big}));
  QueryRequest rq = request(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf);
  QueryResult r = db.query(rq);
  EXPECT_REL_CLOSE(r.values.dynamic_999_kips, 100.0, 1e-14);
  EXPECT_EQ(r.values.breaking_strength_lbf, 300000.0);
  EXPECT_EQ(r.values.extreme_limit_lbf, 200000.0);
  EXPECT_EQ(r.values.mean_limit_lbf, 100000.0);
  EXPECT_REL_CLOSE(r.values.extreme_tension_lbf, 190000.0, 1e-14);
  EXPECT_EQ(r.values.extreme_check_passed, 1);
  EXPECT_EQ(r.values.mean_check_passed, 1);
  EXPECT_TRUE(r.warnings.empty());
  rq.values.on_brake = 1;  // 90,000 > 300,000 / 5
  r = db.query(rq);
  EXPECT_EQ(r.values.mean_limit_lbf, 60000.0);
  EXPECT_EQ(r.values.mean_check_passed, 0);
  rq.values.on_brake = 0;
  rq.values.probability = 1e-4;  // x = 100 + 5 (ln(-ln 0.999) - ln(-ln 0.9999)) = 111.5 kips
  r = db.query(rq);
  EXPECT_REL_CLOSE(r.values.dynamic_tension_kips, 100.0 + 5.0 * (std::log(-std::log(0.999)) - std::log(-std::log(0.9999))), 1e-14);
  EXPECT_EQ(r.values.extreme_check_passed, 0);

  QueryRequest ry = request(c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.mean_tension_lbf);
  ry.tow = "yrbm";
  r = db.query(ry);
  EXPECT_TRUE(has_warning(r, TOWDB_QUERY_WARN_SLACK));
  EXPECT_EQ(r.values.slack_fraction, 0.05);
  ry.tow = "ffg7";
  r = db.query(ry);
  EXPECT_TRUE(has_warning(r, TOWDB_QUERY_WARN_HIGH_TENSION));
  EXPECT_TRUE(has_warning(r, TOWDB_QUERY_WARN_ABOVE_BREAKING));
  EXPECT_FALSE(has_warning(r, TOWDB_QUERY_WARN_SLACK));
}

// query-interp-10
TEST_F(QueryTest, ExtrapolationIsRefusedUnlessAskedThenLinear) {
  // EVIDENCE-OF: EQ-QUERY-6 (end-cell linear extrapolation is exact for linear data)
  const GridSpec g = multilinear_grid();
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LINEAR);
  QueryRequest rq = request(10.0, 25.0, 60.0, 1500.0, 50000.0);
  try {
    db.query(rq);
    FAIL() << "speed 10 kt is outside [3, 9]";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE);
    EXPECT_NE(std::string(e.what()).find("speed_kt = 10 is outside the stored range [3, 9]"), std::string::npos)
        << e.what();
  }
  rq.values.extrapolate = 1;
  const QueryResult r = db.query(rq);
  EXPECT_EQ(r.values.extrapolated, 1);
  EXPECT_TRUE(has_warning(r, TOWDB_QUERY_WARN_EXTRAPOLATED));
  // Mean 50,000 lbf lies below the stored mean tensions of the 9 kt nodes
  // (0.6 x 94,000 lbf) too: both extrapolations are linear, so the
  // multilinear function is exact.
  EXPECT_REL_CLOSE(r.values.dynamic_999_kips,
                   u_multilinear(10.0, 25.0, 60.0, 1500.0, 50000.0) +
                       reduced_variate_999() * beta_multilinear(10.0, 25.0, 60.0, 1500.0, 50000.0),
                   kRoundOffRelTol);
  QueryRequest low_mean = request(5.0, 25.0, 60.0, 1500.0, 10000.0);
  try {
    db.query(low_mean);
    FAIL() << "10,000 lbf is below every stored mean tension";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE);
    EXPECT_NE(std::string(e.what()).find("mean_tension_lbf = 10000 is outside the mean tensions stored at"),
              std::string::npos)
        << e.what();
  }
}

// query-interp-11
TEST_F(QueryTest, IncompleteGridIsRefusedThenRenormalised) {
  const GridSpec g = multilinear_grid();
  auto cases = grid_cases(g);
  std::erase_if(cases, [](const SyntheticCase& c) {
    return c.speed_kt == 9.0 && c.wind_kt == 35.0 && c.heading_deg == 180.0 && c.length_ft == 2000.0;
  });
  Database db(write(cases), TOWDB_QUERY_SPACE_LINEAR);
  QueryRequest rq = request(8.0, 33.0, 170.0, 1900.0, 80000.0);
  try {
    db.query(rq);
    FAIL() << "a corner node is missing";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE);
    EXPECT_NE(std::string(e.what()).find("no stored case at T-ATF 166 / LHA 1 / wire at speed 9 kt, wind 35 kt"),
              std::string::npos)
        << e.what();
  }
  rq.values.extrapolate = 1;
  const QueryResult r = db.query(rq);
  EXPECT_TRUE(has_warning(r, TOWDB_QUERY_WARN_INCOMPLETE_GRID));
  EXPECT_TRUE(std::isfinite(r.values.dynamic_tension_kips));
  // A node next to the hole is still answered exactly without extrapolation.
  const QueryResult node = db.query(request(9.0, 35.0, 120.0, 2000.0, 0.6 * g.nominal_mean_lbf(9.0, 35.0)));
  EXPECT_EQ(node.values.extrapolated, 0);
}

// The searches' analytic data (query-interp-12, 21): dynamic_999(s, l) = 250 + 10 s - 0.1 l + 5 y_999 kips
// at a mean tension of 70,000 lbf at every node.
GridSpec crossing_grid() {
  GridSpec g;
  g.nominal_mean_lbf = [](double, double) { return 70000.0; };
  g.u_kips = [](double s, double, double, double l, double) { return 250.0 + 10.0 * s - 0.1 * l; };
  g.beta_kips = [](double, double, double, double, double) { return 5.0; };
  return g;
}

// query-interp-12
TEST_F(QueryTest, InverseQueriesFindTheAnalyticCrossing) {
  // EVIDENCE-OF: EQ-QUERY-5. dynamic_999(s, l) = 250 + 10 s - 0.1 l + 5 y_999
  // (y_999 = -ln(-ln 0.999)); with mean 70,000 lbf and BS 360,000 lbf the
  // extreme check is mean + 1000 x <= 240,000 lbf, i.e. x <= 170 kips.
  Database db(write(grid_cases(crossing_grid())), TOWDB_QUERY_SPACE_LINEAR);
  const double y = reduced_variate_999();
  // Bisection to 1e-6 of the searched range (query.h).
  constexpr double kSpeedTol_kt = 1e-5, kLengthTol_ft = 1e-2;

  QueryRequest rq = request(kNoValue, 30.0, 60.0, 1800.0, 70000.0);
  auto s = db.max_speed(rq);
  ASSERT_EQ(s.search.found, 1);
  EXPECT_ABS_CLOSE(s.search.value, (170.0 - 250.0 + 0.1 * 1800.0 - 5.0 * y) / 10.0, kSpeedTol_kt);  // 6.546 kt
  EXPECT_EQ(s.search.range_low, 3.0);
  EXPECT_EQ(s.search.range_high, 9.0);
  EXPECT_EQ(s.at_value.values.extreme_check_passed, 1);

  rq = request(6.0, 30.0, 60.0, kNoValue, 70000.0);
  auto l = db.min_length(rq);
  ASSERT_EQ(l.search.found, 1);
  EXPECT_ABS_CLOSE(l.search.value, (250.0 + 60.0 + 5.0 * y - 170.0) / 0.1, kLengthTol_ft);  // 1745 ft

  // On the brake the mean limit is BS/5 = 72,000 lbf: 78,000 lbf fails at every speed.
  rq = request(kNoValue, 30.0, 60.0, 1800.0, 78000.0);
  rq.values.on_brake = 1;  // 78,000 > 360,000 / 5
  s = db.max_speed(rq);
  EXPECT_EQ(s.search.found, 0);
  EXPECT_TRUE(std::isnan(s.search.value));
}

// query-interp-13
TEST_F(QueryTest, NearestCasesStartAtTheQueriedNode) {
  const GridSpec g = multilinear_grid();
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LINEAR);
  const double m = g.nominal_mean_lbf(5.0, 30.0);
  const QueryResult r = db.query(request(5.1, 30.0, 60.0, 1500.0, m * 1.02));
  ASSERT_EQ(r.nearest.size(), 4u);
  EXPECT_EQ(r.nearest[0].speed_kt, 5.0);
  EXPECT_EQ(r.nearest[0].wind_kt, 30.0);
  EXPECT_EQ(r.nearest[0].length_ft, 1500.0);
  for (std::size_t i = 1; i < r.nearest.size(); ++i) EXPECT_LE(r.nearest[i - 1].distance, r.nearest[i].distance);
  const auto& c = r.nearest[0];
  EXPECT_REL_CLOSE(c.dynamic_999_kips,
                   u_multilinear(5.0, 30.0, 60.0, 1500.0, c.mean_tension_lbf) +
                       reduced_variate_999() * beta_multilinear(5.0, 30.0, 60.0, 1500.0, c.mean_tension_lbf),
                   1e-14);
}

// query-interp-14
TEST_F(QueryTest, LeaveOneOutOfAQuadraticIsAHSquared) {
  // EVIDENCE-OF: EQ-QUERY-8. Predicting f(w) = a w^2 at w from w - h and w + h
  // errs by exactly a h^2; all other axes are linear (zero error).
  constexpr double kA = 0.05;
  GridSpec g;
  g.winds_kt = {20.0, 30.0, 40.0};
  g.u_kips = [](double s, double w, double, double, double) { return 20.0 + kA * w * w + s; };
  g.beta_kips = [](double, double, double, double, double) { return 5.0; };
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LINEAR);
  const towdb_query_loo sea = db.leave_one_out(TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_AXIS_SEA);
  ASSERT_GT(sea.samples, 0);
  EXPECT_REL_CLOSE(sea.median_abs_error_kips, kA * 100.0, 1e-9);
  const towdb_query_loo speed = db.leave_one_out(TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_AXIS_SPEED);
  ASSERT_GT(speed.samples, 0);
  EXPECT_LT(speed.max_rel_error, 1e-13);
  // Relative errors a h^2 / x lie between those at the smallest and largest x.
  const double y = reduced_variate_999();
  EXPECT_GE(sea.max_rel_error, kA * 100.0 / (20.0 + kA * 900.0 + 9.0 + 5.0 * y) * (1 - 1e-12));
  EXPECT_LE(sea.max_rel_error, kA * 100.0 / (20.0 + kA * 900.0 + 3.0 + 5.0 * y) * (1 + 1e-12));
}

// query-interp-15
TEST_F(QueryTest, RelativeMeanTensionAxisIsExactForDataLinearInTheFactor) {
  // EVIDENCE-OF: EQ-QUERY-9. T_calc(s, w) = 30,000 + 6,000 s + 500 w (synthetic_db.hpp), stored with every
  // case; u and beta are multilinear in (s, w, h, l) and linear in f = m / T_calc, so interpolation along f
  // at each node and multilinearly across nodes is exact, with f = m / T_calc(q) and T_calc(q) the
  // geometric mean of the corners' T_calc with the cell's weights.
  GridSpec g = multilinear_grid();
  g.store_calculated = true;
  const auto factor_of = [&g](double s, double w, double m) { return m / g.nominal_mean_lbf(s, w); };
  g.u_kips = [&](double s, double w, double h, double l, double m) {
    return u_multilinear(s, w, h, l, 0.0) + 30.0 * factor_of(s, w, m);
  };
  g.beta_kips = [&](double s, double w, double h, double l, double m) {
    return beta_multilinear(s, w, h, l, 0.0) + 2.0 * factor_of(s, w, m);
  };
  const auto cases = grid_cases(g);
  const std::string relative_path = write(cases, "relative.towdb");
  Database db(relative_path, TOWDB_QUERY_SPACE_LINEAR);
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> us(3.0, 9.0), uw(20.0, 35.0), uh(0.0, 180.0), ul(800.0, 2000.0),
      uf(0.6, 1.15);
  auto calc_at = [&g](double s, double w) {
    // Multilinear weights of the (speed, wind) cell, geometric mean of T_calc.
    auto cell = [](const std::vector<double>& axis, double q) {
      auto hi = std::upper_bound(axis.begin(), axis.end(), q);
      if (hi == axis.end()) --hi;
      const double x0 = *(hi - 1), x1 = *hi;
      return std::tuple<double, double, double>(x0, x1, (q - x0) / (x1 - x0));
    };
    const auto [s0, s1, ts] = cell(g.speeds_kt, s);
    const auto [w0, w1, tw] = cell(g.winds_kt, w);
    return std::exp((1 - ts) * (1 - tw) * std::log(g.nominal_mean_lbf(s0, w0)) +
                    ts * (1 - tw) * std::log(g.nominal_mean_lbf(s1, w0)) +
                    (1 - ts) * tw * std::log(g.nominal_mean_lbf(s0, w1)) + ts * tw * std::log(g.nominal_mean_lbf(s1, w1)));
  };
  for (int i = 0; i < 200; ++i) {
    const double s = us(rng), w = uw(rng), h = uh(rng), l = ul(rng), f = uf(rng);
    const double t_calc = calc_at(s, w);
    // Given mean tension.
    QueryResult r = db.query(request(s, w, h, l, f * t_calc));
    const double u = u_multilinear(s, w, h, l, 0.0) + 30.0 * f;
    const double beta = beta_multilinear(s, w, h, l, 0.0) + 2.0 * f;
    EXPECT_REL_CLOSE(r.values.dynamic_999_kips, u + reduced_variate_999() * beta, kRoundOffRelTol) << i;
    EXPECT_REL_CLOSE(r.values.mean_tension_factor, f, kRoundOffRelTol);
    EXPECT_REL_CLOSE(r.values.calculated_mean_tension_lbf, t_calc, kRoundOffRelTol);
    EXPECT_EQ(r.values.extrapolated, 0);
    // Default: the calculated mean tension at the query (f = 1).
    r = db.query(request(s, w, h, l, kNoValue));
    EXPECT_EQ(r.values.mean_tension_factor, 1.0);
    EXPECT_REL_CLOSE(r.values.mean_tension_lbf, t_calc, kRoundOffRelTol);
    EXPECT_REL_CLOSE(r.values.dynamic_999_kips,
                     u_multilinear(s, w, h, l, 0.0) + 30.0 + reduced_variate_999() * (beta_multilinear(s, w, h, l, 0.0) + 2.0),
                     kRoundOffRelTol);
  }

  // At 4 kt, 20 kt wind, factor 1.12: the 3 kt node's highest stored tension is 1.15 x 49,000 = 56,350 lbf,
  // below 1.12 x T_calc(4 kt) ~ 60,400 lbf, so the absolute axis refuses what the relative axis answers.
  const double m = 1.12 * calc_at(4.0, 20.0);
  EXPECT_NO_THROW(db.query(request(4.0, 20.0, 90.0, 1000.0, m)));
  std::vector<SyntheticCase> absolute = cases;
  for (SyntheticCase& c : absolute) c.calculated_mean_tension_lbf = kNoValue;
  Database db_abs(write(absolute, "absolute.towdb"), TOWDB_QUERY_SPACE_LINEAR);
  try {
    db_abs.query(request(4.0, 20.0, 90.0, 1000.0, m));
    ADD_FAILURE() << "the absolute axis should refuse " << m << " lbf";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE);
  }
  EXPECT_TRUE(std::isnan(db_abs.query(request(4.0, 20.0, 90.0, 1000.0, 50000.0)).values.mean_tension_factor));

  // A factor outside the stored 0.6 - 1.15 is refused in its own terms, then extrapolated on request.
  try {
    db.query(request(4.0, 20.0, 90.0, 1000.0, 1.3 * calc_at(4.0, 20.0)));
    ADD_FAILURE() << "factor 1.3 should be refused";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE);
    EXPECT_NE(std::string(e.what()).find("1.3 x the calculated mean tension"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.6 to 1.15 x its calculated value"), std::string::npos) << e.what();
  }
  QueryRequest ex = request(4.0, 20.0, 90.0, 1000.0, 1.3 * calc_at(4.0, 20.0));
  ex.values.extrapolate = 1;
  const QueryResult rx = db.query(ex);
  EXPECT_REL_CLOSE(rx.values.dynamic_999_kips,
                   u_multilinear(4.0, 20.0, 90.0, 1000.0, 0.0) + 30.0 * 1.3 +
                       reduced_variate_999() * (beta_multilinear(4.0, 20.0, 90.0, 1000.0, 0.0) + 2.0 * 1.3),
                   kRoundOffRelTol);
  EXPECT_EQ(rx.values.extrapolated, 1);

  // Above the tugs' 125,000 lbf (thesis ch. 5): answered, with a warning. T_calc(9 kt, 35 kt) = 101,500 lbf,
  // so 140,000 lbf is factor 1.38 (extrapolated).
  QueryRequest above = request(9.0, 35.0, 0.0, 2000.0, 140000.0);
  above.values.extrapolate = 1;
  EXPECT_TRUE(has_warning(db.query(above), TOWDB_QUERY_WARN_ABOVE_CAPACITY));
  EXPECT_FALSE(has_warning(db.query(request(9.0, 35.0, 0.0, 2000.0, 100000.0)), TOWDB_QUERY_WARN_ABOVE_CAPACITY));

  // Leave-one-out reads the neighbours at the node's own factor: exact for this data along speed.
  const towdb_query_loo speed = db.leave_one_out(TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_AXIS_SPEED);
  ASSERT_GT(speed.samples, 0);
  EXPECT_LT(speed.max_rel_error, 1e-12);
}

// query-interp-16
TEST_F(QueryTest, MaxSpeedStopsAtTheTugsCapacity) {
  // EVIDENCE-OF: thesis ch. 5 (125,000 lbf, "beyond the capacity of the tugs"), EQ-QUERY-9. T_calc = 20,000 s
  // lbf at every node; the Towing Manual checks pass below 166,667 lbf (dynamic ~ 27 kips, BS 500,000 lbf, so
  // the mean limit BS/3 lies above the tugs' capacity). With the
  // calculated default mean tension, T_calc(q) = 100,000 x 1.4^t across the 5-7 kt cell (geometric), which
  // reaches 125,000 lbf at t = ln 1.25 / ln 1.4: s = 5 + 2 t = 6.3265 kt.
  GridSpec g;
  g.store_calculated = true;
  g.breaking_strength_lbf = 500000.0;
  g.nominal_mean_lbf = [](double s, double) { return 20000.0 * s; };
  g.u_kips = [](double, double, double, double, double) { return 20.0; };
  g.beta_kips = [](double, double, double, double, double) { return 1.0; };
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LINEAR);
  QueryRequest rq = request(kNoValue, 30.0, 90.0, 1500.0, kNoValue);
  const auto r = db.max_speed(rq);
  ASSERT_EQ(r.search.found, 1);
  EXPECT_NEAR(r.search.value, 5.0 + 2.0 * std::log(1.25) / std::log(1.4), 1e-4);
  EXPECT_LE(r.at_value.values.mean_tension_lbf, 125000.0);
  EXPECT_TRUE(has_warning(r.at_value, TOWDB_QUERY_WARN_ABOVE_CAPACITY));
  // A given mean tension the tugs cannot hold: no speed passes, and the warning says why.
  rq.values.mean_tension_lbf = 130000.0;
  const auto none = db.max_speed(rq);
  EXPECT_EQ(none.search.found, 0);
  EXPECT_TRUE(has_warning(none.at_value, TOWDB_QUERY_WARN_ABOVE_CAPACITY));
}

// query-interp-17
TEST_F(QueryTest, HsOnAWindSeaDatabaseIsAnsweredAtTheEquivalentWind) {
  // EVIDENCE-OF: EQ-QUERY-10 with EQ-SEA-1 (Pierson-Moskowitz, U at 19.5 m): Hs = 0.2092 U^2 / g and
  // Tp = 2 pi U / (0.877 g). U = 25 kt = 12.861 m/s gives Hs = 3.5283 m = 11.576 ft and Tp = 9.396 s.
  Database db(write(grid_cases(multilinear_grid())), TOWDB_QUERY_SPACE_LINEAR);
  const double wind_kt = 25.0;
  const double u_m_s = wind_kt * kMetersPerSecondPerKnot;
  const double hs_ft = 0.2092 * u_m_s * u_m_s / kGravity_m_s2 / kMetersPerFoot;
  const double tp_s = 2.0 * std::numbers::pi * u_m_s / (0.877 * kGravity_m_s2);
  EXPECT_NEAR(hs_ft, 11.576, 0.001);  // the hand value above
  EXPECT_NEAR(tp_s, 9.396, 0.001);

  const QueryResult by_wind = db.query(request(6.0, wind_kt, 100.0, 1200.0, 70000.0));
  EXPECT_TRUE(std::isnan(by_wind.values.equivalent_wind_kt));
  QueryRequest rq = request(6.0, kNoValue, 100.0, 1200.0, 70000.0);
  rq.values.hs_ft = hs_ft;
  for (double tp : {kNoValue, tp_s, 1.19 * tp_s, 0.81 * tp_s}) {
    rq.values.tp_s = tp;
    const QueryResult by_hs = db.query(rq);
    EXPECT_NEAR(by_hs.values.equivalent_wind_kt, wind_kt, 1e-9) << tp;
    EXPECT_REL_CLOSE(by_hs.values.dynamic_999_kips, by_wind.values.dynamic_999_kips, 1e-9);
    EXPECT_TRUE(has_warning(by_hs, TOWDB_QUERY_WARN_EQUIVALENT_WIND));
  }
  // A Tp more than 20 % from the fully developed sea's: swell or a young sea, not stored.
  for (double tp : {1.21 * tp_s, 0.79 * tp_s}) {
    rq.values.tp_s = tp;
    try {
      (void)db.query(rq);
      ADD_FAILURE() << "Tp " << tp << " s was answered";
    } catch (const QueryError& e) {
      EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE);
      const std::string what = e.what();
      EXPECT_NE(what.find("tp_s = "), std::string::npos) << what;
      EXPECT_NE(what.find("has Tp = 9.4 s"), std::string::npos) << what;
    }
  }
  // A spectrum named other than Pierson-Moskowitz is not converted: no such seas are stored.
  rq.values.tp_s = tp_s;
  rq.spectrum = "jonswap";
  EXPECT_THROW((void)db.query(rq), QueryError);
}

// query-interp-18
// A heading profile with a minimum between stored headings (the beam-sea dips
// of docs/audit.md): ln P linear between its 2.5 deg grid points, the values
// exactly representable in binary32 (the table stores sigma_kips_f32).
double profile_point(int j) {
  const double h = 2.5 * j;
  return static_cast<float>(10.0 - 8.0 * std::cos((h - 84.0) * kPi / 30.0) + 0.02 * h);
}
double profile_at(double h) {
  const double x = h / 2.5;
  const int j = std::min(static_cast<int>(x), 71);
  const double f = x - j;
  return std::exp((1.0 - f) * std::log(profile_point(j)) + f * std::log(profile_point(j + 1)));
}

// The profile P on its 73 grid points (the lines' scales cancel in ratios).
std::vector<double> profile_points() {
  std::vector<double> sigma;
  for (int j = 0; j < 73; ++j) sigma.push_back(profile_point(j));
  return sigma;
}

// A random query inside the profile test's grid (5-7 kt, 20-30 kt, 60-105 deg,
// 1,000-2,000 ft) at a mean tension every corner node stores.
QueryPoint profile_cell_point(std::mt19937& rng, const GridSpec& g) {
  std::uniform_real_distribution<double> us(5.0, 7.0), uw(20.0, 30.0), uh(60.0, 105.0), ul(1000.0, 2000.0), uf(0, 1);
  const double s = us(rng), w = uw(rng), h = uh(rng), l = ul(rng);
  const auto [m0, m1] = common_mean_range(g, s, w);
  return {s, w, h, l, m0 + uf(rng) * (m1 - m0)};
}

TEST_F(QueryTest, HeadingProfilesMakeDataProportionalToThemExactBetweenHeadings) {
  // EVIDENCE-OF: EQ-QUERY-11 (x / sigma interpolated across a heading cell; exact when x / sigma is
  // what EQ-QUERY-6 reproduces exactly: exp(multilinear) in log space, multilinear in linear space)
  GridSpec g;
  g.speeds_kt = {5.0, 7.0};
  g.winds_kt = {20.0, 30.0};
  g.headings_deg = {60.0, 75.0, 90.0, 105.0};
  g.lengths_ft = {1000.0, 2000.0};
  g.u_kips = [](double s, double w, double h, double l, double m) { return u_exponential(s, w, 0.0, l, m) * profile_at(h); };
  g.beta_kips = [](double s, double w, double h, double l, double m) { return beta_exponential(s, w, 0.0, l, m) * profile_at(h); };
  const std::string plain = write(grid_cases(g), "plain.towdb");
  const std::string with = write(grid_cases(g), "profiles.towdb");
  write_heading_profiles(with, profile_points());
  std::mt19937 rng(18);
  Database log_db(with, TOWDB_QUERY_SPACE_LOG);
  Database plain_db(plain, TOWDB_QUERY_SPACE_LOG);
  double worst_plain = 0.0;
  for (int i = 0; i < 200; ++i) {
    const auto [s, w, h, l, m] = profile_cell_point(rng, g);
    const QueryResult r = log_db.query(request(s, w, h, l, m));
    EXPECT_REL_CLOSE(r.values.gumbel_u_kips, g.u_kips(s, w, h, l, m), kRoundOffRelTol) << s << " " << w << " " << h;
    EXPECT_REL_CLOSE(1.0 / r.values.gumbel_alpha_per_kip, g.beta_kips(s, w, h, l, m), kRoundOffRelTol);
    const QueryResult p = plain_db.query(request(s, w, h, l, m));
    worst_plain = std::max(worst_plain, std::abs(p.values.gumbel_u_kips / g.u_kips(s, w, h, l, m) - 1.0));
  }
  // Without the profiles the dip at 84 deg is lost between 75 and 90 deg.
  EXPECT_GT(worst_plain, 0.3);

  // Linear space: the profile ratio times a multilinear function is exact too.
  GridSpec lin = g;
  lin.u_kips = [](double s, double w, double h, double l, double m) { return u_multilinear(s, w, 0.0, l, m) * profile_at(h); };
  lin.beta_kips = [](double s, double w, double h, double l, double m) { return beta_multilinear(s, w, 0.0, l, m) * profile_at(h); };
  const std::string lin_path = write(grid_cases(lin), "linear.towdb");
  write_heading_profiles(lin_path, profile_points());
  Database lin_db(lin_path, TOWDB_QUERY_SPACE_LINEAR);
  for (int i = 0; i < 100; ++i) {
    const auto [s, w, h, l, m] = profile_cell_point(rng, lin);
    const QueryResult r = lin_db.query(request(s, w, h, l, m));
    EXPECT_REL_CLOSE(r.values.gumbel_u_kips, lin.u_kips(s, w, h, l, m), kRoundOffRelTol) << s << " " << w << " " << h;
  }

  // One case without a profile: its cells are interpolated as without profiles (never half
  // corrected); the stored nodes stay exact.
  const std::string holed = write(grid_cases(g), "holed.towdb");
  write_heading_profiles(holed, profile_points(), 1);  // case 1: 5 kt, 20 kt, 60 deg, 1,000 ft, its first mean tension
  Database holed_db(holed, TOWDB_QUERY_SPACE_LOG);
  const double m = grid_cases(g).front().mean_tension_lbf;
  const QueryResult a = holed_db.query(request(5.0, 20.0, 70.0, 1000.0, m));
  const QueryResult b = plain_db.query(request(5.0, 20.0, 70.0, 1000.0, m));
  EXPECT_EQ(a.values.gumbel_u_kips, b.values.gumbel_u_kips);
  const QueryResult c = holed_db.query(request(5.0, 20.0, 80.0, 1000.0, m));
  EXPECT_REL_CLOSE(c.values.gumbel_u_kips, g.u_kips(5.0, 20.0, 80.0, 1000.0, m), kRoundOffRelTol);
  const QueryResult node = log_db.query(request(5.0, 20.0, 75.0, 1000.0, m));
  EXPECT_EQ(node.values.gumbel_u_kips, g.u_kips(5.0, 20.0, 75.0, 1000.0, m));

  // EQ-QUERY-7 along heading with profiles: the pinned evaluations moved to the query's heading
  // all give the answer (x / sigma does not change with heading here), so only heading being
  // free leaves no interpolation error; without profiles the dip is a large one.
  const QueryResult free_heading = log_db.query(request(5.0, 20.0, 84.4, 1000.0, m));
  EXPECT_LT(free_heading.values.interpolation_error_kips, 1e-9 * free_heading.values.dynamic_999_kips);
  const QueryResult plain_heading = plain_db.query(request(5.0, 20.0, 84.4, 1000.0, m));
  EXPECT_GT(plain_heading.values.interpolation_error_kips, 0.1 * plain_heading.values.dynamic_999_kips);

  // EQ-QUERY-7 with a corner without a profile: the question is interpolated as without profiles, and so is
  // every pinned evaluation of its estimate (a pinned half of the cell whose corners all have profiles is
  // not moved while the other half is not): the estimate is the one without profiles.
  // 50,000 lbf: between the 5 kt node's first two mean tensions (42,000 lbf, the case without a profile, and
  // at least 59,500) and inside the 7 kt node's 49,200-94,300.
  const QueryResult holed_cell = holed_db.query(request(6.0, 20.0, 70.0, 1000.0, 50000.0));
  const QueryResult plain_cell = plain_db.query(request(6.0, 20.0, 70.0, 1000.0, 50000.0));
  EXPECT_REL_CLOSE(holed_cell.values.interpolation_error_kips, plain_cell.values.interpolation_error_kips,
                   kRoundOffRelTol);

  // EQ-QUERY-7 along a corner's mean tensions, in linear space: the corner's values moved along the profile
  // scale by sigma(h_q) / sigma(h_c), and so does their estimate. Data P(h) L(s, w, l, m), L linear in m:
  // only the mean tensions of the corners with two stored ones contribute (the chord estimate, P(h_c) e_L
  // each), so between the heading nodes 75 and 90 deg the estimate is P(h_q) ((1 - t) e_75 / P(75) +
  // t e_90 / P(90)), e_x the estimate at heading x.
  int nonzero = 0;
  for (double ws : {20.0, 30.0}) {
    for (double ls : {1000.0, 2000.0}) {
      const auto [m0, m1] = common_mean_range(lin, 5.0, ws);
      const double mq = m0 + 0.37 * (m1 - m0);
      const double e75 = lin_db.query(request(5.0, ws, 75.0, ls, mq)).values.interpolation_error_kips;
      const double e90 = lin_db.query(request(5.0, ws, 90.0, ls, mq)).values.interpolation_error_kips;
      // Round-off of exactly linear data (about 1e-14 kips): no estimate to scale.
      const double noise_kips = 1e-9 * lin_db.query(request(5.0, ws, 75.0, ls, mq)).values.dynamic_999_kips;
      const bool estimated = std::max(e75, e90) > noise_kips;
      nonzero += estimated ? 1 : 0;
      for (double hq : {78.0, 84.4, 88.0}) {
        const double t = (hq - 75.0) / 15.0;
        const double expected = profile_at(hq) * ((1.0 - t) * e75 / profile_at(75.0) + t * e90 / profile_at(90.0));
        const QueryResult r = lin_db.query(request(5.0, ws, hq, ls, mq));
        if (estimated) {
          EXPECT_REL_CLOSE(r.values.interpolation_error_kips, expected, 1e-9) << ws << " " << ls << " " << hq;
        } else {
          EXPECT_LT(r.values.interpolation_error_kips, noise_kips) << ws << " " << ls << " " << hq;
        }
      }
    }
  }
  EXPECT_GT(nonzero, 0);  // some corner has two stored mean tensions: the check is not 0 = 0
}

// query-interp-23
// Data x = L(s, w, l, m) P(h)^p on the profile test's grid with the stored profile P.
GridSpec powered_profile_grid(double p) {
  GridSpec g;
  g.speeds_kt = {5.0, 7.0};
  g.winds_kt = {20.0, 30.0};
  g.headings_deg = {60.0, 75.0, 90.0, 105.0};
  g.lengths_ft = {1000.0, 2000.0};
  g.u_kips = [p](double s, double w, double h, double l, double m) {
    return u_exponential(s, w, 0.0, l, m) * std::pow(profile_at(h), p);
  };
  g.beta_kips = [p](double s, double w, double h, double l, double m) {
    return beta_exponential(s, w, 0.0, l, m) * std::pow(profile_at(h), p);
  };
  return g;
}

// Its cases at the factors every node stores (0.6 and 1.15, synthetic_db.hpp mean_factors), so that every
// line (speed, wind, length, mean tension) has all four headings to measure its exponent on, as a sweep's
// lines do.
std::vector<SyntheticCase> every_heading(const GridSpec& g) {
  std::vector<SyntheticCase> out;
  for (const SyntheticCase& c : grid_cases(g)) {
    const double f = c.mean_tension_lbf / g.nominal_mean_lbf(c.speed_kt, c.wind_kt);
    if (std::abs(f - 0.6) < 1e-12 || std::abs(f - 1.15) < 1e-12) out.push_back(c);
  }
  return out;
}

TEST_F(QueryTest, HeadingProfileExponentIsMeasuredOnTheStoredHeadings) {
  // EVIDENCE-OF: EQ-QUERY-11 (x / sigma^k interpolated across a heading cell, k the slope of the stored
  // tensions' departures from their chords against the profile's, clamped to [1, 2])
  const GridSpec squared = powered_profile_grid(2.0);
  const std::string path = write(every_heading(squared), "squared.towdb");
  write_heading_profiles(path, profile_points());
  Database db(path, TOWDB_QUERY_SPACE_LOG);
  std::mt19937 rng(23);
  for (int i = 0; i < 200; ++i) {
    const auto [s, w, h, l, m] = profile_cell_point(rng, squared);
    const QueryResult r = db.query(request(s, w, h, l, m));
    EXPECT_REL_CLOSE(r.values.gumbel_u_kips, squared.u_kips(s, w, h, l, m), kRoundOffRelTol) << s << " " << w << " " << h;
    EXPECT_REL_CLOSE(1.0 / r.values.gumbel_alpha_per_kip, squared.beta_kips(s, w, h, l, m), kRoundOffRelTol);
  }

  // Outside the bounds: P^0.5 is answered with k = 1, P^3 with k = 2. At a node of every axis but heading
  // (and a stored mean tension) the answer is the chord of ln u between 75 and 90 deg plus k times the
  // profile's departure from its own chord.
  for (const auto& [p, k] : {std::pair{0.5, 1.0}, std::pair{3.0, 2.0}}) {
    const GridSpec g = powered_profile_grid(p);
    const std::vector<SyntheticCase> cases = every_heading(g);
    const std::string name = "power-" + std::to_string(p) + ".towdb";
    write_heading_profiles(write(cases, name), profile_points());
    Database clamped((dir_ / name).string(), TOWDB_QUERY_SPACE_LOG);
    const double m = cases.front().mean_tension_lbf;  // stored at (5 kt, 20 kt, 60 deg, 1,000 ft) and every heading
    for (double hq : {78.0, 84.4, 88.0}) {
      const double t = (hq - 75.0) / 15.0;
      const double chord_u = (1.0 - t) * std::log(g.u_kips(5.0, 20.0, 75.0, 1000.0, m)) +
                             t * std::log(g.u_kips(5.0, 20.0, 90.0, 1000.0, m));
      const double chord_p = (1.0 - t) * std::log(profile_at(75.0)) + t * std::log(profile_at(90.0));
      const double expected = std::exp(chord_u + k * (std::log(profile_at(hq)) - chord_p));
      const QueryResult r = clamped.query(request(5.0, 20.0, hq, 1000.0, m));
      EXPECT_REL_CLOSE(r.values.gumbel_u_kips, expected, kRoundOffRelTol) << p << " " << hq;
    }
  }
}

// query-interp-20
// A speed profile with a swing inside the 5-7 kt cell (the encounter fold of
// docs/audit.md): 9 points every 0.25 kt, the values as stored (binary16).
std::vector<double> speed_profile_points() {
  std::vector<double> sigma;
  for (int j = 0; j < 9; ++j) sigma.push_back(10.0 - 8.0 * std::cos((5.0 + 0.25 * j - 6.1) * kPi / 0.6));
  std::string packed;
  EXPECT_TRUE(store::pack_float16(sigma, &packed));
  return store::unpack_float16(packed, sigma.size(), "test");
}
double speed_profile_at(double v) {
  static const std::vector<double> p = speed_profile_points();
  const double x = (v - 5.0) / 0.25;
  const int j = std::min(static_cast<int>(x), 7);
  const double f = x - j;
  return std::exp((1.0 - f) * std::log(p[j]) + f * std::log(p[j + 1]));
}

TEST_F(QueryTest, SpeedProfilesMakeDataProportionalToThemExactBetweenSpeeds) {
  // EVIDENCE-OF: EQ-QUERY-12 (x / sigma interpolated across a speed cell; with EQ-QUERY-11 the two
  // shifts add, exact for a product of a heading and a speed factor)
  GridSpec g;
  g.speeds_kt = {5.0, 7.0};
  g.winds_kt = {20.0, 30.0};
  g.headings_deg = {60.0, 75.0, 90.0, 105.0};
  g.lengths_ft = {1000.0, 2000.0};
  g.u_kips = [](double s, double w, double, double l, double m) {
    return u_exponential(0.0, w, 0.0, l, m) * speed_profile_at(s);
  };
  g.beta_kips = [](double s, double w, double, double l, double m) {
    return beta_exponential(0.0, w, 0.0, l, m) * speed_profile_at(s);
  };
  const std::string plain = write(grid_cases(g), "plain.towdb");
  const std::string with = write(grid_cases(g), "speed.towdb");
  write_speed_profiles(with, speed_profile_points(), 5.0, 0.25);
  std::mt19937 rng(20);
  Database db(with, TOWDB_QUERY_SPACE_LOG);
  Database plain_db(plain, TOWDB_QUERY_SPACE_LOG);
  double worst_plain = 0.0;
  for (int i = 0; i < 200; ++i) {
    const auto [s, w, h, l, m] = profile_cell_point(rng, g);
    const QueryResult r = db.query(request(s, w, h, l, m));
    EXPECT_REL_CLOSE(r.values.gumbel_u_kips, g.u_kips(s, w, h, l, m), kRoundOffRelTol) << s << " " << w << " " << h;
    EXPECT_REL_CLOSE(1.0 / r.values.gumbel_alpha_per_kip, g.beta_kips(s, w, h, l, m), kRoundOffRelTol);
    const QueryResult p = plain_db.query(request(s, w, h, l, m));
    worst_plain = std::max(worst_plain, std::abs(p.values.gumbel_u_kips / g.u_kips(s, w, h, l, m) - 1.0));
  }
  EXPECT_GT(worst_plain, 0.3);  // without the profile the swing is lost between 5 and 7 kt
  // EQ-QUERY-7 along speed: x / sigma does not change with speed, so the relative error estimate
  // is that of the same data without the speed factor (what is left is the mean tension's).
  GridSpec flat = g;
  flat.u_kips = [](double, double w, double, double l, double m) { return u_exponential(0.0, w, 0.0, l, m); };
  flat.beta_kips = [](double, double w, double, double l, double m) { return beta_exponential(0.0, w, 0.0, l, m); };
  Database flat_db(write(grid_cases(flat), "flat.towdb"), TOWDB_QUERY_SPACE_LOG);
  const double m = common_mean_range(g, 6.1, 20.0).first;
  const QueryResult at_speed = db.query(request(6.1, 20.0, 60.0, 1000.0, m));
  const QueryResult at_flat = flat_db.query(request(6.1, 20.0, 60.0, 1000.0, m));
  EXPECT_REL_CLOSE(at_speed.values.interpolation_error_kips / at_speed.values.dynamic_999_kips,
                   at_flat.values.interpolation_error_kips / at_flat.values.dynamic_999_kips, 1e-9);
  const QueryResult plain_speed = plain_db.query(request(6.1, 20.0, 60.0, 1000.0, m));
  EXPECT_GT(plain_speed.values.interpolation_error_kips, 0.1 * plain_speed.values.dynamic_999_kips);

  // Both profiles: a heading factor times a speed factor, exact between headings and speeds.
  GridSpec both = g;
  both.u_kips = [](double s, double w, double h, double l, double mean) {
    return u_exponential(0.0, w, 0.0, l, mean) * speed_profile_at(s) * profile_at(h);
  };
  both.beta_kips = [](double s, double w, double h, double l, double mean) {
    return beta_exponential(0.0, w, 0.0, l, mean) * speed_profile_at(s) * profile_at(h);
  };
  const std::string both_path = write(grid_cases(both), "both.towdb");
  write_speed_profiles(both_path, speed_profile_points(), 5.0, 0.25);
  write_heading_profiles(both_path, profile_points());
  Database both_db(both_path, TOWDB_QUERY_SPACE_LOG);
  for (int i = 0; i < 100; ++i) {
    const auto [s, w, h, l, m2] = profile_cell_point(rng, both);
    const QueryResult r = both_db.query(request(s, w, h, l, m2));
    EXPECT_REL_CLOSE(r.values.gumbel_u_kips, both.u_kips(s, w, h, l, m2), kRoundOffRelTol) << s << " " << h;
  }
}

// query-interp-21
TEST_F(QueryTest, SearchesResolveTheSeaIgnoreTheirFieldAndNeverExtrapolate) {
  // EVIDENCE-OF: query.h towdb_query_max_speed ("request->speed_kt ignored ... Extrapolation is never used by a
  // search") with EQ-QUERY-10 (a sea given as Hs answered at the equivalent wind). Same analytic data as
  // query-interp-12: the crossing at (170 - 250 + 0.1 l - 5 y_999) / 10 kt.
  Database db(write(grid_cases(crossing_grid())), TOWDB_QUERY_SPACE_LINEAR);
  const auto by_wind = db.max_speed(request(kNoValue, 30.0, 60.0, 1800.0, 70000.0));
  ASSERT_EQ(by_wind.search.found, 1);

  // Hs of the fully developed 30 kt sea (EQ-SEA-1, as query-interp-17): the same speed.
  const double u_m_s = 30.0 * kMetersPerSecondPerKnot;
  QueryRequest rq = request(kNoValue, kNoValue, 60.0, 1800.0, 70000.0);
  rq.values.hs_ft = 0.2092 * u_m_s * u_m_s / kGravity_m_s2 / kMetersPerFoot;
  const auto by_hs = db.max_speed(rq);
  ASSERT_EQ(by_hs.search.found, 1);
  EXPECT_REL_CLOSE(by_hs.search.value, by_wind.search.value, 1e-9);
  EXPECT_NEAR(by_hs.at_value.values.equivalent_wind_kt, 30.0, 1e-9);

  // The searched field is ignored whatever it holds: 0 (a zero-initialised C request) or a negative length.
  const auto zero_speed = db.max_speed(request(0.0, 30.0, 60.0, 1800.0, 70000.0));
  EXPECT_EQ(zero_speed.search.value, by_wind.search.value);
  const auto negative_length = db.min_length(request(6.0, 30.0, 60.0, -1.0, 70000.0));
  const auto nan_length = db.min_length(request(6.0, 30.0, 60.0, kNoValue, 70000.0));
  ASSERT_EQ(nan_length.search.found, 1);
  EXPECT_EQ(negative_length.search.value, nan_length.search.value);

  // Extrapolation is never used: asked for, the search answers as without it; beyond the stored winds (35 kt)
  // no speed can be evaluated, and the refusal is a RANGE one, as the query's own would be.
  QueryRequest extrapolating = request(kNoValue, 30.0, 60.0, 1800.0, 70000.0);
  extrapolating.values.extrapolate = 1;
  EXPECT_EQ(db.max_speed(extrapolating).search.value, by_wind.search.value);
  extrapolating.values.wind_kt = 37.0;
  try {
    (void)db.max_speed(extrapolating);
    ADD_FAILURE() << "a search beyond the stored winds was answered";
  } catch (const QueryError& e) {
    EXPECT_EQ(e.code(), TOWDB_QUERY_RANGE) << e.what();
    EXPECT_NE(std::string(e.what()).find("no speed_kt in the stored range 3 to 9"), std::string::npos) << e.what();
  }
}

// query-interp-22
TEST_F(QueryTest, ErrorEstimateWithoutNeighboursAndTheIntervalAtANode) {
  // EVIDENCE-OF: EQ-QUERY-7 (with no curvature to measure, the chord estimate t (1 - t) |f(x_i+1) - f(x_i)|
  // in full). Speeds 3, 5, 7, 9 kt; the node mean tensions span [0.6, 1.15] x (30,000 + 6,000 s + 500 w) lbf,
  // so 90,000 lbf at 30 kt is stored around 7 and 9 kt (52,200-100,050 and 59,400-113,850 lbf) but not at 5 kt
  // (45,000-86,250): along speed, the cell 7-9 kt has no evaluable neighbour. u = 10 + 2 s: at 8 kt the chord's
  // estimate is 0.5 x 0.5 x |u(9) - u(7)| = 1 kip; every other axis is at a node, and u does not depend on m.
  GridSpec g;
  g.u_kips = [](double s, double, double, double, double) { return 10.0 + 2.0 * s; };
  g.beta_kips = [](double, double, double, double, double) { return 5.0; };
  Database db(write(grid_cases(g)), TOWDB_QUERY_SPACE_LINEAR);
  const QueryResult r = db.query(request(8.0, 30.0, 60.0, 1500.0, 90000.0));
  EXPECT_REL_CLOSE(r.values.interpolation_error_kips, 0.25 * 4.0, 1e-9);
  // With the neighbour evaluable (80,000 lbf is stored at 5 kt too) the floor of half the chord applies.
  const QueryResult inside = db.query(request(8.0, 30.0, 60.0, 1500.0, 80000.0));
  EXPECT_REL_CLOSE(inside.values.interpolation_error_kips, 0.5 * 0.25 * 4.0, 1e-9);

  // EQ-QUERY-6: the stored interval in the answer's space, also at a grid node between its stored mean
  // tensions. u and beta share their exponent, each case's interval is +/-5 % of its dynamic_999: in log space
  // the interval is exactly 0.95 and 1.05 of the answer (a linear chord of the bounds is not).
  GridSpec e;
  e.u_kips = [](double s, double w, double, double, double m) { return 40.0 * std::exp(0.1 * s + 0.02 * w + 2e-5 * m); };
  e.beta_kips = [](double s, double w, double, double, double m) { return 8.0 * std::exp(0.1 * s + 0.02 * w + 2e-5 * m); };
  const auto cases = grid_cases(e);
  Database log_db(write(cases, "exp.towdb"), TOWDB_QUERY_SPACE_LOG);
  int checked = 0;
  for (double s : e.speeds_kt) {
    const double nominal = e.nominal_mean_lbf(s, 30.0);
    for (double f : {0.7, 0.9, 1.1}) {
      const QueryResult v = log_db.query(request(s, 30.0, 60.0, 1500.0, f * nominal));
      EXPECT_REL_CLOSE(v.values.ci_low_kips, 0.95 * v.values.dynamic_999_kips, kRoundOffRelTol) << s << " " << f;
      EXPECT_REL_CLOSE(v.values.ci_high_kips, 1.05 * v.values.dynamic_999_kips, kRoundOffRelTol) << s << " " << f;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 12);
}

// query-interp-19
// One grid node (5 kt, 20 kt, 0 deg, 2,000 ft) with the mean tensions given and
// u = u(m), beta = 5 kips.
std::vector<SyntheticCase> one_node(const std::vector<double>& means_lbf, const std::function<double(double)>& u) {
  std::vector<SyntheticCase> out;
  for (double m : means_lbf) {
    SyntheticCase c;
    c.mean_tension_lbf = m;
    c.u_kips = u(m);
    c.alpha_per_kip = 0.2;
    out.push_back(c);
  }
  return out;
}

TEST_F(QueryTest, MeanTensionsOfANodeAreJoinedByAMonotoneCubic) {
  // EVIDENCE-OF: EQ-QUERY-6 (Fritsch & Carlson 1980 monotone cubic Hermite interpolation in m)
  const std::vector<double> means = {20000.0, 40000.0, 60000.0, 80000.0};
  auto u_at = [](Database& db, double m) { return db.query(request(5.0, 20.0, 0.0, 2000.0, m)).values.gumbel_u_kips; };

  // A quadratic, u = c m^2 (m in kips, c = 0.01): the slopes at 40 and 60 kips are the harmonic means of the
  // neighbouring secants, 2 / (1/60 + 1/100) c = 75 c and 2 / (1/100 + 1/140) c = 116.67 c, so mid-way
  // u = 2,600 c + (20 / 8) (75 - 116.67) c = 2,495.83 c against 2,500 c: 4 % of the chord's error of 100 c.
  constexpr double kC = 0.01;
  auto quad = [](double m) { return kC * (m / 1000.0) * (m / 1000.0); };
  Database qdb(write(one_node(means, quad), "quadratic.towdb"), TOWDB_QUERY_SPACE_LINEAR);
  EXPECT_REL_CLOSE(u_at(qdb, 50000.0), (2600.0 + 2.5 * (75.0 - 2.0 / (1.0 / 100 + 1.0 / 140))) * kC, kRoundOffRelTol);
  EXPECT_LT(std::abs(u_at(qdb, 50000.0) - quad(50000.0)), 0.05 * 100.0 * kC);
  for (double m : means) EXPECT_EQ(u_at(qdb, m), quad(m));  // through every stored value

  // A steep rise between 40 and 60 kips (slack giving way to snatch): monotone everywhere, inside each
  // interval's two values, in both spaces; and a local maximum at 40 kips is never exceeded.
  const std::vector<double> steep = {10.0, 11.0, 200.0, 210.0};
  auto steep_u = [&](double m) { return steep[static_cast<std::size_t>(std::lround(m / 20000.0)) - 1]; };
  const std::string steep_path = write(one_node(means, steep_u), "steep.towdb");
  for (int space : {TOWDB_QUERY_SPACE_LINEAR, TOWDB_QUERY_SPACE_LOG}) {
    Database db(steep_path, space);
    double previous = 0.0;
    for (double m = 20000.0; m <= 80000.0; m += 500.0) {
      const double u = u_at(db, m);
      const int i = std::min(2, static_cast<int>((m - 20000.0) / 20000.0));
      EXPECT_GE(u, steep[i] * (1.0 - kRoundOffRelTol)) << space << " " << m;
      EXPECT_LE(u, steep[i + 1] * (1.0 + kRoundOffRelTol)) << space << " " << m;
      EXPECT_GE(u, previous * (1.0 - kRoundOffRelTol)) << space << " " << m;
      previous = u;
    }
  }
  const std::vector<double> peak = {10.0, 50.0, 20.0, 30.0};
  auto peak_u = [&](double m) { return peak[static_cast<std::size_t>(std::lround(m / 20000.0)) - 1]; };
  Database pdb(write(one_node(means, peak_u), "peak.towdb"), TOWDB_QUERY_SPACE_LINEAR);
  for (double m = 20000.0; m <= 80000.0; m += 500.0) EXPECT_LE(u_at(pdb, m), 50.0 * (1.0 + kRoundOffRelTol)) << m;
  EXPECT_GT(u_at(pdb, 30000.0), 30.0);  // the cubic, not the chord (30 at mid-interval), on the rising side

  // Two stored mean tensions: the chord.
  Database two(write(one_node({40000.0, 60000.0}, quad), "two.towdb"), TOWDB_QUERY_SPACE_LINEAR);
  EXPECT_REL_CLOSE(u_at(two, 45000.0), 0.75 * quad(40000.0) + 0.25 * quad(60000.0), kRoundOffRelTol);
}

}  // namespace
}  // namespace towdb::test
