// Loading, interpolation (EQ-QUERY-6, -7) and leave-one-out (EQ-QUERY-8).
// Equations and conventions: query/include/towdb/query.h.
#include "engine.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <tuple>
#include <utility>

#include "common/constants.hpp"
#include "store/database.hpp"
#include "store/packed_days.hpp"

namespace towdb::query {

// ---------------------------------------------------------------------------
// Data held in memory: one Group per (tug, tow, line, sea family).

struct CaseRec {
  std::int64_t id = 0;
  double speed_kt = kNaN, wind_kt = kNaN, hs_ft = kNaN, tp_s = kNaN, heading_deg = kNaN;
  double length_ft = kNaN, mean_lbf = kNaN;
  double calc_lbf = kNaN;  // EQ-QUERY-9 T_calc of the case (NaN when not stored)
  int days = 0;
  double u_kips = kNaN, beta_kips = kNaN, dynamic_999_kips = kNaN;
  std::int64_t profile_id = 0;        // EQ-QUERY-11: heading_profiles row of its line (0: none)
  std::int64_t speed_profile_id = 0;  // EQ-QUERY-12: speed_profiles row of its line (0: none)
};

// EQ-QUERY-11/12: a line's linear profile along heading [deg] or speed [kt],
// ln sigma on a uniform grid.
struct LinearProfile {
  double first = 0.0, step = 1.0;
  std::vector<double> ln_sigma;
  double exponent = 1.0;  // EQ-QUERY-11's k (heading profiles; 1 along speed)

  // ln sigma at a heading or speed, linear between grid points, the end
  // values beyond the grid.
  double ln_at(double v) const {
    const double x = (v - first) / step;
    const double last = static_cast<double>(ln_sigma.size() - 1);
    if (!(x > 0.0)) return ln_sigma.front();
    if (x >= last) return ln_sigma.back();
    const auto i = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(i);
    return (1.0 - f) * ln_sigma[i] + f * ln_sigma[i + 1];
  }
};

// One stored mean tension at one grid node (duplicates merged by averaging).
struct MeanPoint {
  double mean_lbf = kNaN;
  double u_kips = 0.0, beta_kips = 0.0;
  double ln_u = 0.0, ln_beta = 0.0;  // precomputed for log space (NaN when u <= 0)
  double slack = 0.0, ci_level = 0.0, ci_low_kips = 0.0, ci_high_kips = 0.0;
  double ln_ci_low = 0.0, ln_ci_high = 0.0;  // for log space (NaN when a bound is <= 0)
  double bs_lbf = 0.0;
  double sag_ft = kNaN;  // static catenary's largest sag below the chord (NaN: no fit stored)
  double lowest_ft = kNaN;  // its lowest point above the waterline (NaN: not stored)
  bool above_bs = false;
  int profile = -1;  // EQ-QUERY-11: index into Group::profiles, -1 when its cases have none (or differ)
  int speed_profile = -1;  // EQ-QUERY-12: index into Group::speed_profiles, likewise
  std::vector<int> cases;  // indices into Group::cases
};

struct Node {
  std::array<int, kGridAxes> index{};
  std::vector<MeanPoint> points;  // ascending mean tension
  double calc_lbf = kNaN;         // EQ-QUERY-9 T_calc of the node (NaN: not stored for all its cases)
  double ln_calc = kNaN;
};

struct Group {
  std::string tug, tow, line, family;
  std::string tug_key, tow_key;  // normalised names (lower case, letters and digits)
  bool wind_sea = true;
  bool relative = false;  // EQ-QUERY-9: every node stores T_calc, mean tension interpolated as m / T_calc
  std::array<std::vector<double>, kGridAxes> axis;
  std::array<std::size_t, kGridAxes> stride{};
  std::vector<int> node_at;  // flat grid index -> node, -1 where no case is stored
  std::vector<Node> nodes;
  std::vector<CaseRec> cases;
  std::vector<LinearProfile> profiles;        // EQ-QUERY-11: the heading profiles its mean points use
  std::vector<LinearProfile> speed_profiles;  // EQ-QUERY-12: the speed profiles its mean points use

  int node_index(const std::array<int, kGridAxes>& idx) const {
    std::size_t flat = 0;
    for (int a = 0; a < kGridAxes; ++a) flat += static_cast<std::size_t>(idx[a]) * stride[a];
    return node_at[flat];
  }
  std::string name() const { return tug + " / " + tow + " / " + line + (wind_sea ? "" : " / " + family); }
  std::string describe(const std::array<int, kGridAxes>& idx) const {
    std::string s = name() + " at speed " + format_value(axis[kSpeed][idx[kSpeed]]) + " kt, " +
                    (wind_sea ? "wind " : "Hs ") + format_value(axis[kSea][idx[kSea]]) +
                    (wind_sea ? " kt" : " ft");
    if (!wind_sea) s += ", Tp " + format_value(axis[kPeriod][idx[kPeriod]]) + " s";
    return s + ", heading " + format_value(axis[kHeading][idx[kHeading]]) + " deg, length " +
           format_value(axis[kLength][idx[kLength]]) + " ft";
  }
};

namespace {

const char* const kAxisField[kGridAxes] = {"speed_kt", "sea", "tp_s", "heading_deg", "length_ft"};
const char* const kAxisUnit[kGridAxes] = {"kt", "", "s", "deg", "ft"};

// Two stored coordinates are the same grid value when they agree to this
// relative precision (values come from sweep files written with few digits).
constexpr double kSameValueRelTol = 1e-9;

bool same_value(double a, double b) {
  return std::abs(a - b) <= kSameValueRelTol * std::max({1.0, std::abs(a), std::abs(b)});
}

double fold_heading_deg(double h) { return h > 180.0 ? 360.0 - h : h; }

std::string normalise_name(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (std::isalnum(static_cast<unsigned char>(c))) out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// Exact normalised match, else a unique normalised prefix; InputError otherwise.
std::string match_name(const std::string& query, const std::vector<std::string>& known, const std::string& what) {
  const std::string q = normalise_name(query);
  std::vector<std::string> prefix;
  for (const auto& k : known) {
    const std::string nk = normalise_name(k);
    if (nk == q) return k;
    if (!q.empty() && nk.compare(0, q.size(), q) == 0) prefix.push_back(k);
  }
  if (prefix.size() == 1) return prefix.front();
  if (prefix.size() > 1) {
    throw InputError(what + " '" + query + "' is ambiguous; it matches: " + join(prefix));
  }
  throw InputError(what + " '" + query + "' is not in the database; known: " + join(known));
}

std::vector<double> unique_sorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v) {
    if (out.empty() || !same_value(out.back(), x)) out.push_back(x);
  }
  return out;
}

int find_value(const std::vector<double>& axis, double v) {
  const auto it = std::lower_bound(axis.begin(), axis.end(), v - kSameValueRelTol * std::max(1.0, std::abs(v)));
  TOWDB_ASSERT(it != axis.end() && same_value(*it, v));
  return static_cast<int>(it - axis.begin());
}

// EQ-QUERY-9: a node's T_calc is that of its cases (the geometric mean where
// merged duplicates differ); the group is on the relative axis when every
// node has one.
void assign_calculated(Group& g) {
  g.relative = !g.nodes.empty();
  for (Node& node : g.nodes) {
    double sum_ln = 0.0;
    int n = 0;
    bool all = true;
    for (const MeanPoint& p : node.points) {
      for (int ci : p.cases) {
        const double c = g.cases[ci].calc_lbf;
        if (!(c > 0.0 && std::isfinite(c))) {
          all = false;
        } else {
          sum_ln += std::log(c);
          ++n;
        }
      }
    }
    if (all && n > 0) {
      node.ln_calc = sum_ln / n;
      node.calc_lbf = n == 1 ? g.cases[node.points.front().cases.front()].calc_lbf : std::exp(node.ln_calc);
    } else {
      g.relative = false;
    }
  }
}

// -ln(-ln(1 - p)): the Gumbel frequency term of EQ-QUERY-3.
double gumbel_reduced_variate(double probability) { return -std::log(-std::log1p(-probability)); }

// The database's planning probability (schema/README.md: dynamic_999_kips).
constexpr double kPlanningProbability = 0.001;

double to_space(double v, Space s) { return s == Space::kLog ? std::log(v) : v; }
double from_space(double g, Space s) { return s == Space::kLog ? std::exp(g) : g; }
double u_in(const MeanPoint& p, Space s) { return s == Space::kLog ? p.ln_u : p.u_kips; }
double beta_in(const MeanPoint& p, Space s) { return s == Space::kLog ? p.ln_beta : p.beta_kips; }
double ci_low_in(const MeanPoint& p, Space s) { return s == Space::kLog ? p.ln_ci_low : p.ci_low_kips; }
double ci_high_in(const MeanPoint& p, Space s) { return s == Space::kLog ? p.ln_ci_high : p.ci_high_kips; }

// EQ-QUERY-6: a node's value of f at mean tension m inside [m_i0, m_i0+1],
// by the monotone piecewise-cubic Hermite interpolant of its k >= 3 stored
// mean tensions (Fritsch & Carlson 1980, SIAM J. Numer. Anal. 17(2); the
// slopes of Fritsch & Butland 1984, SIAM J. Sci. Stat. Comput. 5(2)): at an
// interior point the weighted harmonic mean of the two secants, zero where
// they differ in sign (a local extremum stays at the stored point); at an end
// the end interval's secant. The interpolant passes through every stored
// value, never leaves the range of an interval's two values where the data
// are monotone, and is exact for f linear in m. NaN when a value it uses is
// not finite (the caller then keeps the chord).
class MonotoneCubicInMean {
 public:
  // The interval [m_i0, m_i0+1] of the node's points and the query's m: the
  // Hermite basis and the slopes' weights, shared by every quantity.
  MonotoneCubicInMean(const std::vector<MeanPoint>& pts, int i0, double m)
      : pts_(pts), k_(static_cast<int>(pts.size())), i0_(i0) {
    h_ = x(i0 + 1) - x(i0);
    const double t = (m - x(i0)) / h_, t2 = t * t, t3 = t2 * t;
    h00_ = 2.0 * t3 - 3.0 * t2 + 1.0;
    h10_ = (t3 - 2.0 * t2 + t) * h_;
    h01_ = 3.0 * t2 - 2.0 * t3;
    h11_ = (t3 - t2) * h_;
  }

  // The interpolated value of f(i) (the quantity at stored point i).
  template <class F>
  double operator()(const F& f) const {
    const int i1 = i0_ + 1;
    return h00_ * f(i0_) + h10_ * slope(i0_, f) + h01_ * f(i1) + h11_ * slope(i1, f);
  }

 private:
  double x(int i) const { return pts_[i].mean_lbf; }
  template <class F>
  double secant(int i, const F& f) const {
    return (f(i + 1) - f(i)) / (x(i + 1) - x(i));
  }
  template <class F>
  double slope(int i, const F& f) const {
    if (i == 0) return secant(0, f);
    if (i == k_ - 1) return secant(k_ - 2, f);
    const double dl = secant(i - 1, f), dr = secant(i, f);
    if (std::isnan(dl * dr)) return kNaN;
    if (dl * dr <= 0.0) return 0.0;
    const double hl = x(i) - x(i - 1), hr = x(i + 1) - x(i);
    const double wl = 2.0 * hr + hl, wr = hr + 2.0 * hl;
    return (wl + wr) / (wl / dl + wr / dr);
  }

  const std::vector<MeanPoint>& pts_;
  int k_, i0_;
  double h_, h00_, h10_, h01_, h11_;
};

// ---------------------------------------------------------------------------
// EQ-QUERY-6: brackets and evaluation.

struct Bracket {
  int i0 = 0, i1 = 0;  // i0 == i1: pinned to one stored value (t = 0)
  double t = 0.0;
  bool outside = false;
};
using Brackets = std::array<Bracket, kGridAxes>;

Bracket make_bracket(const std::vector<double>& axis, double q, bool extrapolate, const std::string& field,
                     const std::string& unit, const std::string& group) {
  const int n = static_cast<int>(axis.size());
  Bracket b;
  if (q < axis.front() && !same_value(q, axis.front())) {
    b.outside = true;
  } else if (q > axis.back() && !same_value(q, axis.back())) {
    b.outside = true;
  }
  if (b.outside) {
    if (!extrapolate) {
      throw OutOfRangeError(field + " = " + format_value(q) + " is outside the stored range [" +
                            format_value(axis.front()) + ", " + format_value(axis.back()) + "]" +
                            (unit.empty() ? "" : " " + unit) + " of " + group +
                            "; pass extrapolate (--extrapolate) to extrapolate");
    }
    if (n == 1) return b;  // constant: a single stored value
    const int i0 = q < axis.front() ? 0 : n - 2;
    b.i0 = i0;
    b.i1 = i0 + 1;
    b.t = (q - axis[i0]) / (axis[i0 + 1] - axis[i0]);
    return b;
  }
  for (int i = 0; i < n; ++i) {
    if (same_value(q, axis[i])) {
      b.i0 = b.i1 = i;
      return b;
    }
  }
  const int i1 = static_cast<int>(std::upper_bound(axis.begin(), axis.end(), q) - axis.begin());
  b.i0 = i1 - 1;
  b.i1 = i1;
  b.t = (q - axis[b.i0]) / (axis[b.i1] - axis[b.i0]);
  return b;
}

// Parameters of one grid node at a mean tension (EQ-QUERY-6: the chord between two stored
// mean tensions, the monotone cubic with three or more; in the space).
// No default member initialisers: a cell holds up to 32 of these, and
// node_value() value-initialises the one it fills.
struct NodeValue {
  double g_u, g_beta;  // in the interpolation space
  double g_ci_low, g_ci_high;  // the stored interval's bounds, in the same space
  double u, beta;      // kips
  double slack, ci_level, ci_low, ci_high, sag_ft, lowest_ft;
  double bs_min, bs_max, mean_lbf;
  bool above_bs, mean_extrapolated;
  int p0, p1;
  double t;
};

NodeValue node_value(const Group& g, const Node& node, double mean_lbf, Space s, bool extrapolate) {
  const auto& pts = node.points;
  const int k = static_cast<int>(pts.size());
  NodeValue v{};
  if (std::isnan(mean_lbf)) {
    v.p0 = v.p1 = k - 1;
  } else {
    const bool below = mean_lbf < pts.front().mean_lbf && !same_value(mean_lbf, pts.front().mean_lbf);
    const bool above = mean_lbf > pts.back().mean_lbf && !same_value(mean_lbf, pts.back().mean_lbf);
    if (below || above) {
      if (!extrapolate) {
        std::string stored;
        for (const auto& p : pts) stored += (stored.empty() ? "" : ", ") + format_value(p.mean_lbf);
        throw OutOfRangeError("mean_tension_lbf = " + format_value(mean_lbf) +
                              " is outside the mean tensions stored at " + g.describe(node.index) + " (" +
                              stored + " lbf); pass extrapolate (--extrapolate) to extrapolate");
      }
      v.mean_extrapolated = true;
      if (k == 1) {
        v.p0 = v.p1 = 0;
      } else {
        v.p0 = below ? 0 : k - 2;
        v.p1 = v.p0 + 1;
        v.t = (mean_lbf - pts[v.p0].mean_lbf) / (pts[v.p1].mean_lbf - pts[v.p0].mean_lbf);
      }
    } else {
      int hit = -1;
      for (int i = 0; i < k; ++i) {
        if (same_value(mean_lbf, pts[i].mean_lbf)) hit = i;
      }
      if (hit >= 0) {
        v.p0 = v.p1 = hit;
      } else {
        int i1 = 1;
        while (pts[i1].mean_lbf < mean_lbf) ++i1;
        v.p0 = i1 - 1;
        v.p1 = i1;
        v.t = (mean_lbf - pts[v.p0].mean_lbf) / (pts[v.p1].mean_lbf - pts[v.p0].mean_lbf);
      }
    }
  }
  const MeanPoint& a = pts[v.p0];
  const MeanPoint& b = pts[v.p1];
  v.mean_lbf = std::isnan(mean_lbf) ? a.mean_lbf : mean_lbf;
  v.bs_min = std::min(a.bs_lbf, b.bs_lbf);
  v.bs_max = std::max(a.bs_lbf, b.bs_lbf);
  v.above_bs = a.above_bs || b.above_bs;
  if (v.p0 == v.p1) {
    v.u = a.u_kips;
    v.beta = a.beta_kips;
    v.g_u = u_in(a, s);
    v.g_beta = beta_in(a, s);
    v.slack = a.slack;
    v.sag_ft = a.sag_ft;
    v.lowest_ft = a.lowest_ft;
    v.ci_level = a.ci_level;
    v.ci_low = a.ci_low_kips;
    v.ci_high = a.ci_high_kips;
    v.g_ci_low = s == Space::kLog ? a.ln_ci_low : a.ci_low_kips;
    v.g_ci_high = s == Space::kLog ? a.ln_ci_high : a.ci_high_kips;
    return v;
  }
  const double t = v.t;
  auto lerp = [t](double x0, double x1) { return (1.0 - t) * x0 + t * x1; };
  v.g_u = lerp(u_in(a, s), u_in(b, s));
  v.g_beta = lerp(beta_in(a, s), beta_in(b, s));
  // v.u and v.beta are filled lazily (node_u / node_beta): exp is costly.
  v.u = v.beta = kNaN;
  v.slack = lerp(a.slack, b.slack);
  v.sag_ft = lerp(a.sag_ft, b.sag_ft);
  v.lowest_ft = lerp(a.lowest_ft, b.lowest_ft);
  v.ci_level = a.ci_level;
  v.ci_low = lerp(a.ci_low_kips, b.ci_low_kips);
  v.ci_high = lerp(a.ci_high_kips, b.ci_high_kips);
  v.g_ci_low = s == Space::kLog ? lerp(a.ln_ci_low, b.ln_ci_low) : v.ci_low;
  v.g_ci_high = s == Space::kLog ? lerp(a.ln_ci_high, b.ln_ci_high) : v.ci_high;
  // Between stored mean tensions of a node with three or more: the monotone
  // cubic in m for u, beta and the interval's bounds (the catenary's and the
  // slack's quantities keep the chord).
  if (k >= 3 && !v.mean_extrapolated) {
    const MonotoneCubicInMean interpolant(pts, v.p0, mean_lbf);
    auto cubic = [&](double chord, auto in) {
      const double c = interpolant([&](int i) { return in(pts[i], s); });
      return std::isfinite(c) ? c : chord;
    };
    v.g_u = cubic(v.g_u, u_in);
    v.g_beta = cubic(v.g_beta, beta_in);
    v.g_ci_low = cubic(v.g_ci_low, ci_low_in);
    v.g_ci_high = cubic(v.g_ci_high, ci_high_in);
    if (s == Space::kLinear) {
      v.ci_low = v.g_ci_low;
      v.ci_high = v.g_ci_high;
    }
  }
  return v;
}

// EQ-QUERY-9: refuses a factor outside the ones stored at a node, in the
// factor's own terms (node_value would name the node's absolute tension).
void check_factor_stored(const Group& g, const Node& node, double factor, double calc_query_lbf) {
  const double lo = node.points.front().mean_lbf / node.calc_lbf;
  const double hi = node.points.back().mean_lbf / node.calc_lbf;
  if ((factor >= lo || same_value(factor, lo)) && (factor <= hi || same_value(factor, hi))) return;
  throw OutOfRangeError("mean_tension_lbf = " + format_value(std::round(factor * calc_query_lbf)) + " is " +
                        format_value(std::round(factor * 1000.0) / 1000.0) +
                        " x the calculated mean tension at the query (" + format_value(std::round(calc_query_lbf)) +
                        " lbf); " + g.describe(node.index) + " stores " + format_value(std::round(lo * 1000.0) / 1000.0) +
                        " to " + format_value(std::round(hi * 1000.0) / 1000.0) +
                        " x its calculated value; pass extrapolate (--extrapolate) to extrapolate");
}

// A node's u and beta in kips (stored values when pinned to one mean tension).
double node_u(const NodeValue& v, Space s) { return v.p0 == v.p1 ? v.u : from_space(v.g_u, s); }
double node_beta(const NodeValue& v, Space s) { return v.p0 == v.p1 ? v.beta : from_space(v.g_beta, s); }

// Up to 2^5 corners of a cell.
constexpr int kMaxCorners = 1 << kGridAxes;

struct Corner {
  int node;  // -1: missing or zero weight (set for every corner by evaluate)
  double weight;
  std::array<int, kGridAxes> idx;
  NodeValue value;
  double profile_factor;  // sigma(x_q) / sigma(x_c) of the EQ-QUERY-11/12 moves applied (1: none)
};

struct Evaluation {
  double u = 0.0, beta = 0.0, mean_lbf = 0.0, slack = 0.0, sag_ft = 0.0, lowest_ft = 0.0;
  double calc_lbf = kNaN, factor = kNaN;  // EQ-QUERY-9 (NaN when the group is absolute)
  double ci_level = 0.0, ci_low = 0.0, ci_high = 0.0;
  double bs_min = 0.0, bs_max = 0.0;
  bool above_bs = false, mean_extrapolated = false;
  bool heading_profiled = false;  // EQ-QUERY-11: the corners were moved along their heading profiles
  bool speed_profiled = false;    // EQ-QUERY-12: ... and along their speed profiles
  int missing = 0;
  std::array<int, kGridAxes> active{};
  int active_count = 0;
  std::array<Corner, kMaxCorners> corners;  // indexed by the bit mask over active axes
};

// What mean tension each corner node is read at (EQ-QUERY-9). Absolute: the
// same mean tension at every node (NaN: each node's highest). Relative: the
// factor f = mean / T_calc(query) times each node's own T_calc; a finite
// `factor` fixes f (the error estimate's pinned evaluations keep the query's).
struct MeanTarget {
  double mean_lbf = kNaN;
  double factor = kNaN;
  // EQ-QUERY-11: with the heading pinned to a stored value, move the corners
  // along their profiles to this heading (the error estimate's pinned
  // evaluations; NaN: leave them at the stored heading).
  double heading_deg = kNaN;
  double speed_kt = kNaN;  // EQ-QUERY-12: the same along speed
  // EQ-QUERY-7's pinned evaluations: false where the question's own evaluation
  // could not move along that axis (a corner without a profile), so that the
  // estimate differences values of one kind, never moved against unmoved ones.
  bool move_heading = true, move_speed = true;
};

// EQ-QUERY-11/12: moves each corner's value from its node's coordinate x_c
// on `axis` (heading or speed) to the query's x_q along its line's linear
// profile (`slot` of its mean points into `profiles`), ln x += k (ln
// sigma(x_q) - ln sigma(x_c)) with the profile's exponent k (u, beta and the
// interval scale together), so that the multilinear weights interpolate
// x / sigma^k across the cell instead of x.
// Every corner must have a profile (else nothing moves, false): a cell is
// never half corrected.
bool shift_along(const Group& g, int axis, double xq, int MeanPoint::*slot, const std::vector<LinearProfile>& profiles,
                 Space s, Evaluation* ev, int n_corners) {
  if (profiles.empty()) return false;
  for (int mask = 0; mask < n_corners; ++mask) {
    const Corner& c = ev->corners[mask];
    if (c.node < 0) continue;
    const auto& pts = g.nodes[c.node].points;
    if (pts[c.value.p0].*slot < 0 || pts[c.value.p1].*slot < 0) return false;
  }
  for (int mask = 0; mask < n_corners; ++mask) {
    Corner& c = ev->corners[mask];
    if (c.node < 0) continue;
    const auto& pts = g.nodes[c.node].points;
    const double xc = g.axis[axis][c.idx[axis]];
    NodeValue& v = c.value;
    auto shift_of = [&](int p) {
      const LinearProfile& prof = profiles[pts[p].*slot];
      return prof.exponent * (prof.ln_at(xq) - prof.ln_at(xc));
    };
    const double shift = v.p0 == v.p1 ? shift_of(v.p0) : (1.0 - v.t) * shift_of(v.p0) + v.t * shift_of(v.p1);
    const double f = std::exp(shift);
    c.profile_factor *= f;
    if (s == Space::kLog) {
      v.g_u += shift;
      v.g_beta += shift;
      v.g_ci_low += shift;
      v.g_ci_high += shift;
    } else {
      v.g_u *= f;
      v.g_beta *= f;
      v.g_ci_low *= f;
      v.g_ci_high *= f;
    }
    v.u *= f;  // NaN (filled lazily) stays NaN
    v.beta *= f;
    v.ci_low *= f;
    v.ci_high *= f;
  }
  return true;
}

// The query's coordinate on `axis` inside its cell, else (the axis pinned to
// a stored value) the error estimate's target `pinned` (NaN: none).
double cell_coordinate(const Group& g, const Brackets& br, int axis, double pinned) {
  const Bracket& b = br[axis];
  const auto& ax = g.axis[axis];
  return b.i0 != b.i1 ? (1.0 - b.t) * ax[b.i0] + b.t * ax[b.i1] : pinned;
}

void evaluate(const Group& g, const Brackets& br, const MeanTarget& target, Space s, bool extrapolate,
              Evaluation* ev) {
  ev->active_count = 0;
  for (int a = 0; a < kGridAxes; ++a) {
    if (br[a].i0 != br[a].i1) ev->active[ev->active_count++] = a;
  }
  const int n_corners = 1 << ev->active_count;
  double present_weight = 0.0;
  int present = 0;
  ev->missing = 0;
  for (int mask = 0; mask < n_corners; ++mask) {
    Corner& c = ev->corners[mask];
    c.node = -1;
    double w = 1.0;
    for (int a = 0; a < kGridAxes; ++a) c.idx[a] = br[a].i0;
    for (int j = 0; j < ev->active_count; ++j) {
      const int a = ev->active[j];
      const bool hi = (mask >> j) & 1;
      c.idx[a] = hi ? br[a].i1 : br[a].i0;
      w *= hi ? br[a].t : 1.0 - br[a].t;
    }
    c.weight = w;
    c.profile_factor = 1.0;
    if (w == 0.0) continue;
    const int node = g.node_index(c.idx);
    if (node < 0) {
      if (!extrapolate) {
        throw OutOfRangeError("no stored case at " + g.describe(c.idx) +
                              " (the case grid is incomplete there); pass extrapolate (--extrapolate) to "
                              "interpolate from the nodes that exist");
      }
      ++ev->missing;
      continue;
    }
    c.node = node;
    present_weight += w;
    ++present;
  }
  if (present == 0 || !(std::abs(present_weight) > 1e-12)) {
    throw OutOfRangeError("no stored case surrounds the query in " + g.name());
  }
  // EQ-QUERY-9: T_calc at the query, geometric (log-linear) over the corners.
  ev->calc_lbf = ev->factor = kNaN;
  if (g.relative) {
    double ln_calc = 0.0;
    int last = -1;
    for (int mask = 0; mask < n_corners; ++mask) {
      const Corner& c = ev->corners[mask];
      if (c.node < 0) continue;
      ln_calc += c.weight / present_weight * g.nodes[c.node].ln_calc;
      last = c.node;
    }
    // At a single node its own value, bit for bit (no log/exp round trip).
    ev->calc_lbf = present == 1 ? g.nodes[last].calc_lbf : std::exp(ln_calc);
    ev->factor = std::isfinite(target.factor)     ? target.factor
                 : std::isnan(target.mean_lbf) ? 1.0
                                               : target.mean_lbf / ev->calc_lbf;
  }
  for (int mask = 0; mask < n_corners; ++mask) {
    Corner& c = ev->corners[mask];
    if (c.node < 0) continue;
    const Node& node = g.nodes[c.node];
    if (g.relative && !extrapolate) check_factor_stored(g, node, ev->factor, ev->calc_lbf);
    const double m = g.relative ? ev->factor * node.calc_lbf : target.mean_lbf;
    c.value = node_value(g, node, m, s, extrapolate);
  }
  const double hq = cell_coordinate(g, br, kHeading, target.heading_deg);
  const double vq = cell_coordinate(g, br, kSpeed, target.speed_kt);
  ev->heading_profiled = target.move_heading && std::isfinite(hq) &&
                         shift_along(g, kHeading, hq, &MeanPoint::profile, g.profiles, s, ev, n_corners);
  ev->speed_profiled = target.move_speed && std::isfinite(vq) &&
                       shift_along(g, kSpeed, vq, &MeanPoint::speed_profile, g.speed_profiles, s, ev, n_corners);
  double gu = 0.0, gb = 0.0, g_lo = 0.0, g_hi = 0.0;
  ev->mean_lbf = ev->slack = ev->sag_ft = ev->lowest_ft = ev->ci_low = ev->ci_high = 0.0;
  ev->bs_min = std::numeric_limits<double>::infinity();
  ev->bs_max = 0.0;
  ev->above_bs = ev->mean_extrapolated = false;
  const Corner* single = nullptr;
  for (int mask = 0; mask < n_corners; ++mask) {
    Corner& c = ev->corners[mask];
    if (c.node < 0) continue;
    c.weight /= present_weight;  // renormalised when corners are missing (extrapolate only)
    const NodeValue& v = c.value;
    gu += c.weight * v.g_u;
    gb += c.weight * v.g_beta;
    ev->mean_lbf += c.weight * v.mean_lbf;
    ev->slack += c.weight * v.slack;
    ev->sag_ft += c.weight * v.sag_ft;
    ev->lowest_ft += c.weight * v.lowest_ft;
    ev->ci_low += c.weight * v.ci_low;
    ev->ci_high += c.weight * v.ci_high;
    g_lo += c.weight * v.g_ci_low;
    g_hi += c.weight * v.g_ci_high;
    ev->ci_level = v.ci_level;
    ev->bs_min = std::min(ev->bs_min, v.bs_min);
    ev->bs_max = std::max(ev->bs_max, v.bs_max);
    ev->above_bs = ev->above_bs || v.above_bs;
    ev->mean_extrapolated = ev->mean_extrapolated || v.mean_extrapolated;
    single = &c;
  }
  const bool at_node = present == 1 && single->weight == 1.0;
  const bool at_stored_case = at_node && single->value.p0 == single->value.p1;
  if (at_node) {
    // At a stored node: the node's values (at a stored case, bit for bit: no log/exp round trip).
    ev->u = node_u(single->value, s);
    ev->beta = node_beta(single->value, s);
    ev->mean_lbf = single->value.mean_lbf;
  } else {
    ev->u = from_space(gu, s);
    ev->beta = from_space(gb, s);
  }
  if (!at_stored_case) {
    // The stored interval in the answer's space, so that it brackets the
    // answer as the corners' intervals bracket theirs (linear where a bound
    // is not positive); also at a node between its stored mean tensions.
    const double lo = from_space(g_lo, s), hi = from_space(g_hi, s);
    if (std::isfinite(lo) && std::isfinite(hi)) {
      ev->ci_low = lo;
      ev->ci_high = hi;
    }
  }
  if (!(std::isfinite(ev->u) && std::isfinite(ev->beta) && ev->beta > 0.0)) {
    throw NumericalError("interpolation in " + g.name() + " gives Gumbel u = " + format_value(ev->u) +
                         " kips, beta = 1/alpha = " + format_value(ev->beta) +
                         " kips: not a distribution (scale must be > 0); extrapolated too far");
  }
}

double percentile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return kNaN;
  const double pos = q * static_cast<double>(sorted.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  const double f = pos - static_cast<double>(i);
  if (i + 1 >= sorted.size()) return sorted.back();
  return sorted[i] + f * (sorted[i + 1] - sorted[i]);
}

// Second divided difference f[x0, x1, x2] (EQ-QUERY-7: f''/2 for a quadratic).
double divided_difference2(double x0, double f0, double x1, double f1, double x2, double f2) {
  const double d01 = (f1 - f0) / (x1 - x0);
  const double d12 = (f2 - f1) / (x2 - x1);
  return (d12 - d01) / (x2 - x0);
}

// EQ-QUERY-7: ratio of the MoM quantile standard error at frequency factor K.
double quantile_se_factor(double reduced_variate_plus_ln_days) {
  const double k = std::numbers::sqrt3 * std::numbers::sqrt2 / kPi * (reduced_variate_plus_ln_days - kEulerGamma);
  return std::sqrt(std::max(0.0, 1.0 + 1.1396 * k + 1.1 * k * k));
}

// EQ-QUERY-7's floor on a grid axis with curvature information: at least
// this fraction of the chord estimate t (1 - t) |f(x_i1) - f(x_i0)|, because
// the tension changes abruptly between some nodes (the line goes slack in
// exactly following seas and not 30 deg off), where a second difference
// across three nodes misses the shape inside the cell. Calibrated with
// `towdb audit` on the bundled database (docs/audit.md): 0 covered 73 % of
// 30 questions (seed 1), 0.25 77 %, 0.5 90 %, 1 97 %; 0.5 then covered 87 %
// of 100 other questions (seed 2) against 78 % without the floor.
constexpr double kChordSagFloor = 0.5;

// EQ-QUERY-7: interpolation error of x(p, D) = u + beta c at the query,
// summed over the active grid axes and the mean tension. Along an axis with
// a third stored value beside the cell, t (1 - t) h^2 |f[x_k, x_i0, x_i1]|,
// the larger over the triples on either side, and at least kChordSagFloor
// times the chord estimate; with only the cell's two values, the chord
// estimate t (1 - t) |f(x_i1) - f(x_i0)| (a chord that sags by a quarter of
// the rise at mid-cell: the curvature of f ~ x^2 over the cell). In log
// space f = ln x and the estimate is scaled by x (dx = x d ln x).
// EQ-QUERY-7 along one axis of stored values x(0..n-1), the query in the
// cell [i0, i1] at fraction t; f(i) is the interpolated quantity with this
// axis pinned to index i (NaN: not available). The chord estimate
// t (1 - t) |f(i1) - f(i0)| counts in full where no third value is available
// (an axis of two values, or neighbours that cannot be evaluated at the
// question: a missing node, a mean tension outside a node's stored ones) and
// with weight chord_floor otherwise; the curvature estimate of each side that
// has a third value can only raise it.
template <class X, class F>
double axis_error(int n, int i0, int i1, double t, double chord_floor, const X& x, const F& f) {
  const double f0 = f(i0), f1 = f(i1);
  if (!(std::isfinite(f0) && std::isfinite(f1))) return 0.0;  // ln of a non-positive corner value
  const double tt = std::abs(t * (1.0 - t)), h = x(i1) - x(i0);
  const double chord = tt * std::abs(f1 - f0);
  double curvature = kNaN;  // the larger side's estimate; NaN: no third value
  if (i0 - 1 >= 0) {
    const double fl = f(i0 - 1);
    if (std::isfinite(fl)) {
      curvature = tt * h * h * std::abs(divided_difference2(x(i0 - 1), fl, x(i0), f0, x(i1), f1));
    }
  }
  if (i1 + 1 < n) {
    const double fr = f(i1 + 1);
    if (std::isfinite(fr)) {
      const double right = tt * h * h * std::abs(divided_difference2(x(i0), f0, x(i1), f1, x(i1 + 1), fr));
      curvature = std::isnan(curvature) ? right : std::max(curvature, right);
    }
  }
  return std::isnan(curvature) ? chord : std::max(chord_floor * chord, curvature);
}

double interpolation_error_kips(const Group& g, const Brackets& br, const Evaluation& ev, const MeanTarget& target,
                                Space s, bool ex, double c, double answer_kips) {
  const bool log_space = s == Space::kLog && answer_kips > 0.0;
  auto g_of = [&](double x) { return log_space ? std::log(x) : x; };
  const double scale = log_space ? answer_kips : 1.0;
  double err = 0.0;
  for (int j = 0; j < ev.active_count; ++j) {
    const int a = ev.active[j];
    const auto& ax = g.axis[a];
    // The whole cell re-evaluated with this axis pinned to stored index i.
    // Along heading or speed, when the answer used the profiles (EQ-QUERY-11,
    // 12), each pinned evaluation is moved to the query's heading or speed
    // too: the estimate then measures how x / sigma changes between the
    // stored values (a value that could not be moved is not available).
    MeanTarget at = target;
    at.move_heading = ev.heading_profiled;
    at.move_speed = ev.speed_profiled;
    const bool moved = (a == kHeading && ev.heading_profiled) || (a == kSpeed && ev.speed_profiled);
    const double xq = (1.0 - br[a].t) * ax[br[a].i0] + br[a].t * ax[br[a].i1];
    if (moved && a == kHeading) at.heading_deg = xq;
    if (moved && a == kSpeed) at.speed_kt = xq;
    auto f_at = [&](int i) {
      Brackets pinned = br;
      pinned[a] = Bracket{i, i, 0.0, false};
      Evaluation e2;
      try {
        evaluate(g, pinned, at, s, ex, &e2);
        if (moved && !(a == kHeading ? e2.heading_profiled : e2.speed_profiled)) return kNaN;
        return g_of(e2.u + e2.beta * c);
      } catch (const InputError&) {
        return kNaN;
      } catch (const NumericalError&) {
        return kNaN;
      }
    };
    err += scale * axis_error(static_cast<int>(ax.size()), br[a].i0, br[a].i1, br[a].t, kChordSagFloor,
                              [&](int i) { return ax[i]; }, f_at);
  }
  // Each corner's own mean tensions (no chord floor: it was calibrated on the grid axes; docs/audit.md),
  // moved as the corner was (EQ-QUERY-11/12): in linear space its values scale by the profile factor, in
  // log space their differences do not change.
  const int n_corners = 1 << ev.active_count;
  for (int mask = 0; mask < n_corners; ++mask) {
    const Corner& cn = ev.corners[mask];
    if (cn.node < 0 || cn.value.p0 == cn.value.p1) continue;
    const auto& pts = g.nodes[cn.node].points;
    const double e_mean = axis_error(
        static_cast<int>(pts.size()), cn.value.p0, cn.value.p1, cn.value.t, 0.0,
        [&](int i) { return pts[i].mean_lbf; }, [&](int i) { return g_of(pts[i].u_kips + pts[i].beta_kips * c); });
    err += scale * std::abs(cn.weight) * (log_space ? 1.0 : cn.profile_factor) * e_mean;
  }
  return err;
}

}  // namespace

// ---------------------------------------------------------------------------

double gumbel_quantile_kips(double u_kips, double beta_kips, double probability, double tow_days) {
  return u_kips + beta_kips * (std::log(tow_days) + gumbel_reduced_variate(probability));
}

void QueryOptions::validate() const {
  require_positive("high_tension_warning_kips", high_tension_warning_kips);
  require_in_range("slack_warning_fraction", slack_warning_fraction, 0.0, 1.0);
  require_input(std::isfinite(extreme_safety_factor) && extreme_safety_factor >= 1.0, "extreme_safety_factor",
                extreme_safety_factor, "must be a finite number >= 1");
  require_input(std::isfinite(mean_safety_factor_machine) && mean_safety_factor_machine >= 1.0,
                "mean_safety_factor_machine", mean_safety_factor_machine, "must be a finite number >= 1");
  require_input(std::isfinite(mean_safety_factor_brake) && mean_safety_factor_brake >= 1.0,
                "mean_safety_factor_brake", mean_safety_factor_brake, "must be a finite number >= 1");
  require_in_range("nearest_cases", nearest_cases, 0, 64);
  require_positive("tug_capacity_lbf", tug_capacity_lbf);
}

void Request::validate() const {
  if (tug.empty()) throw InputError("tug: a tug name is required");
  if (tow.empty()) throw InputError("tow: a tow name is required");
  if (line != "wire" && line != "fiber") {
    throw InputError("line = '" + line + "': must be 'wire' or 'fiber'");
  }
  require_positive("speed_kt", speed_kt);
  const bool has_wind = !std::isnan(wind_kt), has_hs = !std::isnan(hs_ft);
  if (has_wind == has_hs) {
    throw InputError(has_wind ? "wind_kt and hs_ft: give one sea, not both"
                              : "wind_kt: a sea is required (wind_kt, or hs_ft for a two-parameter sea)");
  }
  if (has_wind) require_positive("wind_kt", wind_kt);
  if (has_hs) require_positive("hs_ft", hs_ft);
  if (!std::isnan(tp_s)) require_positive("tp_s", tp_s);
  require_in_range("heading_deg", heading_deg, 0.0, 360.0);
  require_positive("length_ft", length_ft);
  if (!std::isnan(mean_tension_lbf)) require_positive("mean_tension_lbf", mean_tension_lbf);
  require_input(std::isfinite(probability) && probability > 0.0 && probability < 1.0, "probability", probability,
                "must be strictly between 0 and 1 (exceedance probability of the tow's maximum)");
  require_input(std::isfinite(tow_days) && tow_days >= 1.0, "tow_days", tow_days,
                "must be a finite number of days >= 1");
}

// ---------------------------------------------------------------------------
// Loading.

namespace {

// The builds' coverage notes (schema 5), grid notes first.
std::vector<CoverageNote> load_coverage_notes(store::Database& db) {
  std::vector<CoverageNote> out;
  store::Statement st = db.prepare(
      "SELECT DISTINCT tug_name, tow_name, sweep_label, note, kind = 'skipped', nominal_speed_kt, heading_deg, "
      "sea FROM coverage_notes ORDER BY kind = 'skipped', note_id");
  while (st.step()) {
    CoverageNote n;
    n.tug = st.column_text(0);
    n.tow = st.column_text(1);
    n.sweep_label = st.column_text(2);
    n.note = st.column_text(3);
    n.skipped = st.column_int(4) != 0;
    n.nominal_speed_kt = st.column_optional_double(5).value_or(kNaN);
    n.heading_deg = st.column_optional_double(6).value_or(kNaN);
    n.sea = st.is_null(7) ? "" : st.column_text(7);
    out.push_back(std::move(n));
  }
  return out;
}

}  // namespace

Engine::Engine(Engine&&) noexcept = default;
Engine& Engine::operator=(Engine&&) noexcept = default;
Engine::~Engine() = default;

namespace {

// A database that lies (issue 20 item 4): every value Engine::open reads is
// checked before use, and the first bad one is refused naming the file, the
// case, table.column, the value and what is allowed (TOWDB_QUERY_DATABASE).
// Column numbers are those of the SELECT in Engine::open.
struct StoredNumber {
  int column;
  const char* name;  // table.column
  bool nullable;
  double lo, hi;     // allowed range; bounds open where flagged
  bool lo_open, hi_open, whole;
  const char* allowed;
};

constexpr double kInf = std::numeric_limits<double>::infinity();
const StoredNumber kStoredNumbers[] = {
    {4, "cases.speed_kt", false, 0.0, kInf, true, true, false, "a finite speed > 0"},
    {6, "cases.wind_kt", true, 0.0, kInf, false, true, false, "NULL or a finite wind speed >= 0"},
    {7, "cases.hs_ft", true, 0.0, kInf, true, true, false, "NULL or a finite wave height > 0"},
    {8, "cases.tp_s", true, 0.0, kInf, true, true, false, "NULL or a finite peak period > 0"},
    {9, "cases.gamma", true, 0.0, kInf, true, true, false, "NULL or a finite peak enhancement > 0"},
    {11, "cases.heading_deg", false, 0.0, 360.0, false, false, false, "a heading in [0, 360]"},
    {12, "cases.length_ft", false, 0.0, kInf, true, true, false, "a finite length > 0"},
    {13, "cases.mean_tension_lbf", false, 0.0, kInf, true, true, false, "a finite mean tension > 0"},
    {14, "cases.days", false, 1.0, 2147483647.0, false, false, true, "a whole number of days >= 1"},
    {15, "results.gumbel_u_kips", false, -kInf, kInf, true, true, false, "a finite location"},
    {16, "results.gumbel_alpha_per_kip", false, 0.0, kInf, true, true, false,
     "a finite alpha > 0 (the Gumbel scale 1/alpha must be positive)"},
    {17, "results.dynamic_999_kips", false, -kInf, kInf, true, true, false, "a finite tension"},
    {18, "results.ci_level", false, 0.0, 1.0, true, true, false, "a confidence level in (0, 1)"},
    {19, "results.ci_low_kips", false, -kInf, kInf, true, true, false, "a finite tension"},
    {20, "results.ci_high_kips", false, -kInf, kInf, true, true, false, "a finite tension"},
    {21, "results.breaking_strength_lbf", false, 0.0, kInf, true, true, false, "a finite breaking strength > 0"},
    {22, "results.above_breaking_strength", false, 0.0, 1.0, false, false, true, "0 or 1"},
    {23, "results.slack_fraction", false, 0.0, 1.0, false, false, false, "a fraction in [0, 1]"},
    {24, "cases.calculated_mean_tension_lbf", true, 0.0, kInf, true, true, false,
     "NULL or a finite mean tension > 0"},
    {25, "towline_fits.sag_ft", true, 0.0, kInf, false, true, false, "NULL or a finite sag >= 0"},
    {26, "towline_fits.lowest_elevation_ft", true, -kInf, kInf, true, true, false, "NULL or a finite elevation"},
};

// dynamic_999 = u + beta (-ln(-ln 0.999)) (EQ-QUERY-3) as stored: the
// generator writes all three from one fit (agreement ~1e-16 on the bundled
// database); 1e-6 admits values written as text with 7 significant digits.
constexpr double kStoredQuantileRelTol = 1e-6;

[[noreturn]] void refuse_stored(const std::filesystem::path& path, std::int64_t case_id, const std::string& what) {
  throw DatabaseError(path.string() + ": case " + std::to_string(case_id) + ": " + what);
}

// Throws DatabaseError for the first value of the current row that no towdb
// build can have written.
void check_stored_row(const store::Statement& st, const std::filesystem::path& path) {
  const std::int64_t id = st.column_int(0);
  for (const StoredNumber& n : kStoredNumbers) {
    const std::string type = st.column_type_name(n.column);
    if (type == "null") {
      if (n.nullable) continue;
      refuse_stored(path, id, std::string(n.name) + " is NULL (NaN is stored as NULL); allowed: " + n.allowed);
    }
    if (type != "integer" && type != "real") {
      const std::string shown = type == "text" ? "'" + st.column_text(n.column).substr(0, 40) + "'" : "a blob";
      refuse_stored(path, id, std::string(n.name) + " = " + shown + " (" + type + "); allowed: " + n.allowed);
    }
    const double v = st.column_double(n.column);
    const bool ok = std::isfinite(v) && (n.lo_open ? v > n.lo : v >= n.lo) && (n.hi_open ? v < n.hi : v <= n.hi) &&
                    (!n.whole || v == std::floor(v));
    if (!ok) refuse_stored(path, id, std::string(n.name) + " = " + format_value(v) + "; allowed: " + n.allowed);
  }
  if (st.is_null(6) && st.is_null(7)) {
    refuse_stored(path, id, "cases.wind_kt and cases.hs_ft are both NULL; allowed: a sea with a wind speed or a wave "
                            "height");
  }
  if (!st.is_null(7) && st.is_null(8)) {
    refuse_stored(path, id, "cases.tp_s is NULL beside hs_ft = " + format_value(st.column_double(7)) +
                                "; allowed: a two-parameter sea with its peak period");
  }
  const double u = st.column_double(15), alpha = st.column_double(16), x999 = st.column_double(17);
  if (!std::isfinite(1.0 / alpha)) {
    refuse_stored(path, id, "results.gumbel_alpha_per_kip = " + format_value(alpha) + " gives the Gumbel scale 1/alpha = " +
                                format_value(1.0 / alpha) + "; allowed: an alpha whose scale 1/alpha is finite");
  }
  const double expected = u + gumbel_reduced_variate(kPlanningProbability) / alpha;  // EQ-QUERY-3
  if (!(std::abs(x999 - expected) <= kStoredQuantileRelTol * std::max(1.0, std::abs(x999)))) {
    refuse_stored(path, id, "results.dynamic_999_kips = " + format_value(x999) + " disagrees with gumbel_u_kips + " +
                                "(-ln(-ln 0.999)) / gumbel_alpha_per_kip = " + format_value(expected) +
                                " (EQ-QUERY-3); allowed: within a relative " + format_value(kStoredQuantileRelTol));
  }
  if (!(st.column_double(19) <= st.column_double(20))) {
    refuse_stored(path, id, "results.ci_low_kips = " + format_value(st.column_double(19)) + " exceeds ci_high_kips = " +
                                format_value(st.column_double(20)) + "; allowed: ci_low_kips <= ci_high_kips");
  }
}

}  // namespace

namespace {

// One finished case as Engine::open reads it: the interpolated record and the
// per-case extras that are averaged into its node's mean point.
struct Row {
  CaseRec rec;
  double folded_heading = 0.0, slack = 0.0, ci_level = 0.0, ci_low = 0.0, ci_high = 0.0, bs = 0.0;
  double sag_ft = kNaN, lowest_ft = kNaN;
  bool above = false;
};

// The finished cases of a database, checked row by row (check_stored_row),
// grouped by (tug, tow, line, sea family); rows[i] are groups[i]'s.
struct LoadedRows {
  std::vector<Group> groups;
  std::vector<std::vector<Row>> rows;
};

void read_rows(store::Database& db, const std::filesystem::path& path, LoadedRows* out) {
  std::map<std::tuple<std::string, std::string, std::string, std::string>, std::size_t> group_of;
  store::Statement st = db.prepare(
      "SELECT c.case_id, c.tug_name, c.tow_name, c.line_type, c.speed_kt, c.spectrum, c.wind_kt, c.hs_ft, "
      "c.tp_s, c.gamma, c.swell_hs_ft, c.heading_deg, c.length_ft, c.mean_tension_lbf, c.days, "
      "r.gumbel_u_kips, r.gumbel_alpha_per_kip, r.dynamic_999_kips, r.ci_level, r.ci_low_kips, r.ci_high_kips, "
      "r.breaking_strength_lbf, r.above_breaking_strength, r.slack_fraction, c.calculated_mean_tension_lbf, "
      "f.sag_ft, f.lowest_elevation_ft, c.profile_id, c.speed_profile_id FROM cases c JOIN results r ON r.case_id = c.case_id "
      "LEFT JOIN towline_fits f ON f.fit_id = c.fit_id WHERE c.status = 'done' ORDER BY c.case_id");
  while (st.step()) {
    Row r;
    r.rec.id = st.column_int(0);
    const std::string tug = st.column_text(1), tow = st.column_text(2), line = st.column_text(3);
    r.rec.speed_kt = st.column_double(4);
    std::string family = st.column_text(5);
    const auto wind = st.column_optional_double(6), hs = st.column_optional_double(7);
    const auto tp = st.column_optional_double(8), gamma = st.column_optional_double(9);
    if (!st.is_null(10) || family.find("+swell") != std::string::npos) continue;  // swell seas: not gridded
    check_stored_row(st, path);
    if (wind.has_value() == hs.has_value()) continue;                             // not one sea parameter
    r.rec.wind_kt = wind.value_or(kNaN);
    r.rec.hs_ft = hs.value_or(kNaN);
    r.rec.tp_s = hs ? tp.value_or(0.0) : kNaN;
    if (gamma) family += "(gamma=" + format_value(*gamma) + ")";
    r.rec.heading_deg = st.column_double(11);
    r.folded_heading = fold_heading_deg(r.rec.heading_deg);
    r.rec.length_ft = st.column_double(12);
    r.rec.mean_lbf = st.column_double(13);
    r.rec.days = static_cast<int>(st.column_int(14));
    r.rec.u_kips = st.column_double(15);
    const double alpha = st.column_double(16);
    r.rec.dynamic_999_kips = st.column_double(17);
    r.ci_level = st.column_double(18);
    r.ci_low = st.column_double(19);
    r.ci_high = st.column_double(20);
    r.bs = st.column_double(21);
    r.above = st.column_int(22) != 0;
    r.slack = st.column_double(23);
    r.rec.calc_lbf = st.column_optional_double(24).value_or(kNaN);
    r.sag_ft = st.column_optional_double(25).value_or(kNaN);
    r.lowest_ft = st.column_optional_double(26).value_or(kNaN);
    r.rec.profile_id = st.is_null(27) ? 0 : st.column_int(27);
    r.rec.speed_profile_id = st.is_null(28) ? 0 : st.column_int(28);
    r.rec.beta_kips = 1.0 / alpha;
    const auto key = std::make_tuple(tug, tow, line, (wind ? "wind:" : "hs:") + family);
    auto [it, inserted] = group_of.try_emplace(key, out->groups.size());
    if (inserted) {
      Group g;
      g.tug = tug;
      g.tow = tow;
      g.line = line;
      g.family = family;
      g.wind_sea = wind.has_value();
      g.tug_key = normalise_name(tug);
      g.tow_key = normalise_name(tow);
      out->groups.push_back(std::move(g));
      out->rows.emplace_back();
    }
    out->rows[it->second].push_back(r);
  }
}

// EQ-QUERY-11/12: one kind of stored profile, as read_profiles checks it.
struct ProfileTable {
  const char* sql;     // id, first, step, count, blob
  const char* table;   // for messages
  const char* id;      // the id column
  const char* coordinate, *points, *unit;  // "heading", "headings", "deg"
  const char* blob;    // the blob column
  double first_max;    // first in (0 or above, first_max]
  bool first_positive; // first > 0 (speeds) rather than >= 0 (headings)
  std::int64_t max_points;
  int bytes;  // a value: 4 binary32, 2 binary16
};

// A profile longer than a heading every 0.01 deg, or a speed every 0.001 kt
// over 100 kt, is not one a build writes.
const ProfileTable kHeadingProfiles{
    "SELECT profile_id, heading_first_deg, heading_step_deg, headings, sigma_kips_f32 FROM heading_profiles",
    "heading_profiles", "profile_id", "heading", "headings", "deg", "sigma_kips_f32", 180.0, false, 18001, 4};
const ProfileTable kSpeedProfiles{
    "SELECT speed_profile_id, speed_first_kt, speed_step_kt, speeds, sigma_kips_f16 FROM speed_profiles",
    "speed_profiles", "speed_profile_id", "speed", "speeds", "kt", "sigma_kips_f16", 100.0, true, 100001, 2};

// Every stored profile of one kind by its id, each checked.
std::map<std::int64_t, LinearProfile> read_profiles(store::Database& db, const std::filesystem::path& path,
                                                    const ProfileTable& t) {
  std::map<std::int64_t, LinearProfile> out;
  store::Statement st = db.prepare(t.sql);
  while (st.step()) {
    const std::int64_t id = st.column_int(0);
    LinearProfile p;
    p.first = st.column_double(1);
    p.step = st.column_double(2);
    const std::int64_t count = st.column_int(3);
    const std::string blob = st.column_blob(4);
    const std::string row = path.string() + ": " + t.table + " row " + std::to_string(id);
    const bool first_ok = (t.first_positive ? p.first > 0.0 : p.first >= 0.0) && p.first <= t.first_max;
    if (!(p.step > 0.0 && std::isfinite(p.step)) || !first_ok || count < 2 || count > t.max_points) {
      throw DatabaseError(row + " has first " + t.coordinate + " " + format_value(p.first) + " " + t.unit +
                          ", step " + format_value(p.step) + " " + t.unit + " and " + std::to_string(count) + " " +
                          t.points + "; allowed: first in " + (t.first_positive ? "(0, " : "[0, ") +
                          format_value(t.first_max) + "], a finite step > 0 and 2 to " +
                          std::to_string(t.max_points) + " " + t.points);
    }
    const auto n = static_cast<std::size_t>(count);
    if (blob.size() != static_cast<std::size_t>(t.bytes) * n) {
      throw DatabaseError(row + ": " + t.blob + " holds " + std::to_string(blob.size()) + " bytes; expected " +
                          std::to_string(t.bytes) + " x " + std::to_string(n) + " " + t.points);
    }
    const std::string field = std::string(t.table) + "." + t.blob + " of " + t.id + " " + std::to_string(id);
    const std::vector<double> sigma =
        t.bytes == 4 ? store::unpack_float32(blob, n, field) : store::unpack_float16(blob, n, field);
    for (double v : sigma) {
      if (!(v > 0.0 && std::isfinite(v))) {
        throw DatabaseError(path.string() + ": " + field + " holds " + format_value(v) +
                            " kips; allowed: finite and > 0");
      }
      p.ln_sigma.push_back(std::log(v));
    }
    out.emplace(id, std::move(p));
  }
  return out;
}

// EQ-QUERY-11/12: a mean point uses its cases' profile (`id` of CaseRec,
// into `slot`) when they all have the same one (merged duplicates such as h
// and 360 - h share their line's).
void assign_profiles(Group& g, const std::map<std::int64_t, LinearProfile>& stored, std::int64_t CaseRec::*id_of,
                     int MeanPoint::*slot, std::vector<LinearProfile> Group::*used) {
  std::map<std::int64_t, int> index;
  for (Node& node : g.nodes) {
    for (MeanPoint& p : node.points) {
      const std::int64_t id = g.cases[p.cases.front()].*id_of;
      const bool shared = std::all_of(p.cases.begin(), p.cases.end(),
                                      [&](int ci) { return g.cases[ci].*id_of == id; });
      const auto it = stored.find(id);
      if (id == 0 || !shared || it == stored.end()) continue;
      auto [at, inserted] = index.try_emplace(id, static_cast<int>((g.*used).size()));
      if (inserted) (g.*used).push_back(it->second);
      p.*slot = at->second;
    }
  }
}

// EQ-QUERY-11's exponent k of a heading profile, measured on the stored
// headings of its line (docs/audit.md, "The heading profile's exponent").
// Below 1 the fit would flatten the profile where the tension's shape is not
// the linear model's (the slowly varying forces, which the linear model does
// not have, add to it): pooled over 600 audit questions the 90th percentile
// was no better and the +/- covered fewer. Above 2 a line's few interior
// headings over-amplify narrow minima (worst error between 60 and 120 deg
// 22 % with 2, 27 % with 3, 30 % with 5).
constexpr double kProfileExponentMin = 1.0;
constexpr double kProfileExponentMax = 2.0;
// Sum of squared second differences of ln sigma below which a line's profile
// has no curvature at its stored headings to measure k against (k = 1).
constexpr double kProfileCurvatureFloor = 1e-4;

// EQ-QUERY-11: the exponent of every heading profile of a group, from the
// mean points that use it (one per stored heading of the line): the
// least-squares slope of d_x against d_s over the line's interior headings,
// where d is a value's departure from the chord of its two neighbouring
// headings (in ln x999 and ln sigma), clamped to [min, max].
void fit_heading_exponents(Group& g) {
  struct LinePoint {
    double heading_deg, ln_sigma, ln_x999;
  };
  std::vector<std::vector<LinePoint>> lines(g.profiles.size());
  const double c = gumbel_reduced_variate(kPlanningProbability);
  for (const Node& node : g.nodes) {
    const double h = g.axis[kHeading][node.index[kHeading]];
    for (const MeanPoint& p : node.points) {
      const double x999 = p.u_kips + p.beta_kips * c;
      if (p.profile < 0 || !(x999 > 0.0)) continue;
      lines[p.profile].push_back({h, g.profiles[p.profile].ln_at(h), std::log(x999)});
    }
  }
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::vector<LinePoint>& v = lines[k];
    std::sort(v.begin(), v.end(), [](const LinePoint& a, const LinePoint& b) { return a.heading_deg < b.heading_deg; });
    double ss = 0.0, sx = 0.0;
    for (std::size_t j = 1; j + 1 < v.size(); ++j) {
      const double t = (v[j].heading_deg - v[j - 1].heading_deg) / (v[j + 1].heading_deg - v[j - 1].heading_deg);
      const double ds = v[j].ln_sigma - ((1.0 - t) * v[j - 1].ln_sigma + t * v[j + 1].ln_sigma);
      const double dx = v[j].ln_x999 - ((1.0 - t) * v[j - 1].ln_x999 + t * v[j + 1].ln_x999);
      ss += ds * ds;
      sx += ds * dx;
    }
    if (ss > kProfileCurvatureFloor)
      g.profiles[k].exponent = std::clamp(sx / ss, kProfileExponentMin, kProfileExponentMax);
  }
}

// A group's grid: each axis the sorted distinct stored values, the nodes
// (one per stored combination) and each node's mean points with their cases.
void build_grid(Group& g, const std::vector<Row>& rs) {
  std::array<std::vector<double>, kGridAxes> raw;
  for (const Row& r : rs) {
    raw[kSpeed].push_back(r.rec.speed_kt);
    raw[kSea].push_back(g.wind_sea ? r.rec.wind_kt : r.rec.hs_ft);
    raw[kPeriod].push_back(g.wind_sea ? 0.0 : r.rec.tp_s);
    raw[kHeading].push_back(r.folded_heading);
    raw[kLength].push_back(r.rec.length_ft);
  }
  std::size_t total = 1;
  for (int a = kGridAxes - 1; a >= 0; --a) {
    g.axis[a] = unique_sorted(raw[a]);
    g.stride[a] = total;
    total *= g.axis[a].size();
  }
  g.node_at.assign(total, -1);
  for (const Row& r : rs) {
    std::array<int, kGridAxes> idx{};
    idx[kSpeed] = find_value(g.axis[kSpeed], r.rec.speed_kt);
    idx[kSea] = find_value(g.axis[kSea], g.wind_sea ? r.rec.wind_kt : r.rec.hs_ft);
    idx[kPeriod] = find_value(g.axis[kPeriod], g.wind_sea ? 0.0 : r.rec.tp_s);
    idx[kHeading] = find_value(g.axis[kHeading], r.folded_heading);
    idx[kLength] = find_value(g.axis[kLength], r.rec.length_ft);
    int node = g.node_index(idx);
    if (node < 0) {
      node = static_cast<int>(g.nodes.size());
      std::size_t flat = 0;
      for (int a = 0; a < kGridAxes; ++a) flat += static_cast<std::size_t>(idx[a]) * g.stride[a];
      g.node_at[flat] = node;
      g.nodes.push_back(Node{idx, {}});
    }
    const int case_index = static_cast<int>(g.cases.size());
    g.cases.push_back(r.rec);
    auto& pts = g.nodes[node].points;
    auto same = std::find_if(pts.begin(), pts.end(), [&](const MeanPoint& p) { return same_value(p.mean_lbf, r.rec.mean_lbf); });
    if (same == pts.end()) {
      MeanPoint p;
      p.mean_lbf = r.rec.mean_lbf;
      pts.push_back(p);
      same = pts.end() - 1;
    }
    same->cases.push_back(case_index);
  }
}

// Each mean point's parameters: the average of its cases (duplicates such as
// headings h and 360 - h merged), logs precomputed; *log_ok becomes false when
// some u <= 0. Mean points sorted by mean tension.
void merge_points(Group& g, const std::vector<Row>& rs, bool* log_ok) {
  // Merge duplicates (e.g. headings h and 360 - h): average of the parameters.
  for (Node& node : g.nodes) {
    for (MeanPoint& p : node.points) {
      const double n = static_cast<double>(p.cases.size());
      double u = 0, beta = 0, slack = 0, lo = 0, hi = 0, level = 0, bs = std::numeric_limits<double>::infinity();
      double sag = 0, lowest = 0;
      bool above = false;
      for (int ci : p.cases) {
        const CaseRec& c = g.cases[ci];
        u += c.u_kips;
        beta += c.beta_kips;
        // Per-case extras live in the Row list in the same order as g.cases.
        const Row& r = rs[ci];
        slack += r.slack;
        sag += r.sag_ft;  // NaN when any case has no stored fit
        lowest += r.lowest_ft;  // NaN also for fits stored before schema 6
        lo += r.ci_low;
        hi += r.ci_high;
        level = r.ci_level;
        bs = std::min(bs, r.bs);
        above = above || r.above;
      }
      if (p.cases.size() == 1) {
        p.u_kips = u;
        p.beta_kips = beta;
      } else {
        p.u_kips = u / n;
        p.beta_kips = beta / n;
      }
      p.slack = slack / n;
      p.sag_ft = sag / n;
      p.lowest_ft = lowest / n;
      p.ci_low_kips = lo / n;
      p.ci_high_kips = hi / n;
      p.ln_ci_low = p.ci_low_kips > 0.0 ? std::log(p.ci_low_kips) : kNaN;
      p.ln_ci_high = p.ci_high_kips > 0.0 ? std::log(p.ci_high_kips) : kNaN;
      p.ci_level = level;
      p.bs_lbf = bs;
      p.above_bs = above;
      if (!(p.u_kips > 0.0)) *log_ok = false;
      p.ln_u = std::log(p.u_kips);
      p.ln_beta = std::log(p.beta_kips);
    }
    std::sort(node.points.begin(), node.points.end(),
              [](const MeanPoint& a, const MeanPoint& b) { return a.mean_lbf < b.mean_lbf; });
  }
}

}  // namespace

Engine Engine::open(const std::filesystem::path& path, Space space, QueryOptions options) {
  options.validate();
  Engine e;
  e.options_ = options;
  LoadedRows loaded;
  std::map<std::int64_t, LinearProfile> profiles, speed_profiles;
  try {
    store::Database db = store::Database::open(path, store::Database::Mode::kReadOnly);
    read_rows(db, path, &loaded);
    profiles = read_profiles(db, path, kHeadingProfiles);
    speed_profiles = read_profiles(db, path, kSpeedProfiles);
    e.coverage_ = load_coverage_notes(db);
  } catch (const DatabaseError&) {
    throw;
  } catch (const InputError& err) {
    throw DatabaseError(err.what());
  } catch (const StorageError& err) {
    throw DatabaseError(err.what());
  }
  if (loaded.groups.empty()) {
    throw DatabaseError(path.string() + ": no finished cases (cases.status = 'done' with a results row) to query");
  }
  e.groups_ = std::move(loaded.groups);
  e.log_ok_ = true;
  for (std::size_t gi = 0; gi < e.groups_.size(); ++gi) {
    Group& g = e.groups_[gi];
    build_grid(g, loaded.rows[gi]);
    merge_points(g, loaded.rows[gi], &e.log_ok_);
    assign_profiles(g, profiles, &CaseRec::profile_id, &MeanPoint::profile, &Group::profiles);
    assign_profiles(g, speed_profiles, &CaseRec::speed_profile_id, &MeanPoint::speed_profile, &Group::speed_profiles);
    fit_heading_exponents(g);
    assign_calculated(g);
    e.case_count_ += static_cast<int>(g.cases.size());
  }

  // EQ-QUERY-6: the space is chosen by the leave-one-out test (EQ-QUERY-8).
  if (space == Space::kLog && !e.log_ok_) {
    throw InputError("space = log: some stored gumbel_u_kips <= 0, so log-space interpolation is impossible; use "
                     "linear or auto");
  }
  if (space == Space::kAuto) {
    e.space_ = Space::kLinear;
    if (e.log_ok_) {
      const LooStats lin = e.leave_one_out(Space::kLinear, kAllAxes);
      const LooStats lg = e.leave_one_out(Space::kLog, kAllAxes);
      // The 90th percentile, not the median: the planner's large errors come
      // from the few cells where the tension changes abruptly (docs/audit.md:
      // on the bundled database log space halves the audit's 90th-percentile
      // error while the leave-one-out median prefers linear).
      if (lin.samples > 0 && lg.p90_rel_error < lin.p90_rel_error) e.space_ = Space::kLog;
    }
  } else {
    e.space_ = space;
  }
  return e;
}

const Group& Engine::find_group(const Request& r) const {
  // Fast path (no allocation beyond two short keys): exact normalised names
  // and a unique group; the lists and messages are built only when needed.
  const std::string tug_key = normalise_name(r.tug), tow_key = normalise_name(r.tow);
  const bool wind_sea = !std::isnan(r.wind_kt);
  const Group* hit = nullptr;
  int hits = 0;
  for (const Group& g : groups_) {
    if (g.tug_key == tug_key && g.tow_key == tow_key && g.line == r.line && g.wind_sea == wind_sea &&
        r.spectrum.empty()) {
      hit = &g;
      ++hits;
    }
  }
  if (hits == 1) return *hit;

  std::vector<std::string> tugs;
  for (const Group& g : groups_) {
    if (std::find(tugs.begin(), tugs.end(), g.tug) == tugs.end()) tugs.push_back(g.tug);
  }
  std::sort(tugs.begin(), tugs.end());
  const std::string tug = match_name(r.tug, tugs, "tug");
  std::vector<std::string> tows;
  for (const Group& g : groups_) {
    if (g.tug == tug && std::find(tows.begin(), tows.end(), g.tow) == tows.end()) tows.push_back(g.tow);
  }
  std::sort(tows.begin(), tows.end());
  const std::string tow = match_name(r.tow, tows, "tow (towed by " + tug + ")");
  std::vector<const Group*> found;
  std::set<std::string> lines, seas;
  for (const Group& g : groups_) {
    if (g.tug != tug || g.tow != tow) continue;
    lines.insert(g.line);
    if (g.line != r.line) continue;
    seas.insert(g.wind_sea ? "wind (" + g.family + ")" : "hs (" + g.family + ")");
    if (g.wind_sea != wind_sea) continue;
    if (!r.spectrum.empty() && normalise_name(g.family).rfind(normalise_name(r.spectrum), 0) != 0) continue;
    found.push_back(&g);
  }
  if (!lines.count(r.line)) {
    throw InputError("line = '" + r.line + "': no " + r.line + " towline cases for " + tug + " towing " + tow +
                     "; stored: " + join({lines.begin(), lines.end()}));
  }
  if (found.empty()) {
    throw InputError(std::string(wind_sea ? "wind_kt" : "hs_ft") + ": no " +
                     (wind_sea ? "wind-defined (Pierson-Moskowitz)" : "Hs-defined") + " seas" +
                     (r.spectrum.empty() ? "" : " with spectrum '" + r.spectrum + "'") + " for " + tug + " / " + tow +
                     " / " + r.line + "; stored seas: " + join({seas.begin(), seas.end()}));
  }
  if (found.size() > 1) {
    std::vector<std::string> fams;
    for (const Group* g : found) fams.push_back(g->family);
    throw InputError("spectrum: several sea spectra are stored for " + tug + " / " + tow + " / " + r.line +
                     " (" + join(fams) + "); name one");
  }
  return *found.front();
}

namespace {

// An answer is returned only when it is physical: extrapolating far beyond
// the stored data (extrapolate = 1 and, e.g., wind_kt = 1e300 or length_ft =
// 2^63) can overflow the interpolated confidence interval to inf, or take the
// default mean tension (each node's highest stored one) to 0 or below, while
// the call succeeded (regression inputs: tests/fuzz/regressions/query_requests). Refused as
// TOWDB_QUERY_NUMERICAL naming the answer's field (and, by the caller, the
// request fields that were extrapolated).
void require_physical_answer(const Answer& a) {
  const std::pair<const char*, double> values[] = {
      {"dynamic_tension_kips", a.dynamic_tension_kips}, {"dynamic_999_kips", a.dynamic_999_kips},
      {"mean_tension_lbf", a.mean_tension_lbf},         {"extreme_tension_lbf", a.extreme_tension_lbf},
      {"gumbel_u_kips", a.gumbel_u_kips},               {"gumbel_alpha_per_kip", a.gumbel_alpha_per_kip},
      {"interpolation_error_kips", a.interpolation_error_kips}, {"ci_low_kips", a.ci_low_kips},
      {"ci_high_kips", a.ci_high_kips},                 {"uncertainty_kips", a.uncertainty_kips},
      {"breaking_strength_lbf", a.breaking_strength_lbf}};
  for (const auto& [name, v] : values) {
    if (!std::isfinite(v)) {
      throw NumericalError(std::string(name) + " = " + format_value(v) +
                                  ": the answer is not finite (extrapolated too far from the stored data); "
                                  "allowed: a question nearer the stored range");
    }
  }
  const std::pair<const char*, double> positive[] = {{"mean_tension_lbf", a.mean_tension_lbf},
                                                     {"gumbel_alpha_per_kip", a.gumbel_alpha_per_kip},
                                                     {"breaking_strength_lbf", a.breaking_strength_lbf}};
  for (const auto& [name, v] : positive) {
    if (!(v > 0.0)) {
      throw NumericalError(std::string(name) + " = " + format_value(v) +
                                  ": not physical (extrapolated too far from the stored data); allowed: > 0, at a "
                                  "question nearer the stored range");
    }
  }
}

}  // namespace

// ---------------------------------------------------------------------------
// EQ-QUERY-10: a sea given as Hs (and Tp) asked of a database of wind seas.

namespace {

// EQ-SEA-1 (generator/sea/sea.hpp), Pierson-Moskowitz: Hs = 0.2092 U^2 / g and
// w_p = 0.877 g / U, U the wind at 19.5 m.
constexpr double kPmHsCoefficient = 0.2092;
constexpr double kPmPeakCoefficient = 0.877;
// A Tp within this fraction of the fully developed sea's own is taken as that
// sea (a choice, not a published limit: the planner's Tp is an estimate, and
// the answer says which wind it used). Farther, the sea is swell or a young
// sea, which a database of fully developed wind seas does not hold.
constexpr double kEquivalentWindTpRelTol = 0.20;

double pm_peak_period_s(double wind_kt) {
  const double u_m_s = wind_kt * kMetersPerSecondPerKnot;
  return 2.0 * std::numbers::pi * u_m_s / (kPmPeakCoefficient * kGravity_m_s2);
}

}  // namespace

double equivalent_wind_kt(double hs_ft) {
  const double hs_m = hs_ft * kMetersPerFoot;
  return std::sqrt(hs_m * kGravity_m_s2 / kPmHsCoefficient) / kMetersPerSecondPerKnot;
}

// The request to answer: `r` itself, or, when `r` gives hs_ft and the
// database holds only wind seas for its tug, tow and line, the same question
// at the equivalent wind (EQ-QUERY-10); *wind_kt receives that wind (NaN when
// not converted). A Tp far from the wind sea's is refused naming both.
Request Engine::resolve_sea(const Request& r, double* wind_kt) const {
  *wind_kt = kNaN;
  const bool pm_family = r.spectrum.empty() || normalise_name(r.spectrum).rfind("pierson", 0) == 0;
  if (std::isnan(r.hs_ft) || !pm_family) return r;
  try {
    (void)find_group(r);
    return r;
  } catch (const InputError&) {
    Request w = r;
    w.hs_ft = kNaN;
    w.tp_s = kNaN;
    w.spectrum.clear();
    w.wind_kt = equivalent_wind_kt(r.hs_ft);
    const Group& g = find_group(w);  // throws, naming the seas stored, when there are no wind seas either
    if (!std::isnan(r.tp_s)) {
      const double tp_pm = pm_peak_period_s(w.wind_kt);
      if (std::abs(r.tp_s - tp_pm) > kEquivalentWindTpRelTol * tp_pm) {
        throw OutOfRangeError("tp_s = " + format_value(r.tp_s) + " s: the database holds fully developed " +
                              "(Pierson-Moskowitz) wind seas only for " + g.name() +
                              "; the wind sea of Hs = " + format_value(r.hs_ft) + " ft (wind " +
                              format_value(std::round(w.wind_kt * 100.0) / 100.0) + " kt) has Tp = " +
                              format_value(std::round(tp_pm * 100.0) / 100.0) + " s, and a Tp within " +
                              format_value(kEquivalentWindTpRelTol * 100.0) + " % of it is answered as that sea");
      }
    }
    *wind_kt = w.wind_kt;
    return w;
  }
}

// ---------------------------------------------------------------------------
// The query (EQ-QUERY-3 .. EQ-QUERY-7).

Answer Engine::query(const Request& asked) const {
  asked.validate();
  double wind_from_hs_kt = kNaN;
  const Request r = resolve_sea(asked, &wind_from_hs_kt);
  const Group& g = find_group(r);
  try {
    return answer(asked, r, g, wind_from_hs_kt);
  } catch (const OutOfRangeError& e) {
    const std::string why = coverage_reason(g, r);
    if (why.empty()) throw;
    throw OutOfRangeError(e.what() + why);
  }
}

// The builds' notes on what they left out for g's tug and tow: every grid
// note, and the skipped condition nearest the question (speed in kt, heading
// in 30 deg units) with the count of the others.
std::string Engine::coverage_reason(const Group& g, const Request& r) const {
  std::string why;
  std::vector<std::string> seen;
  const CoverageNote* nearest = nullptr;
  double best = std::numeric_limits<double>::infinity();
  int skipped = 0;
  for (const CoverageNote& n : coverage_) {
    if (n.tug != g.tug || n.tow != g.tow) continue;
    if (!n.skipped) {
      if (std::find(seen.begin(), seen.end(), n.note) != seen.end()) continue;
      seen.push_back(n.note);
      why += "; the database's build says of " + g.tug + " / " + g.tow + " (grid '" + n.sweep_label + "'): " + n.note;
      continue;
    }
    ++skipped;
    const double d = std::abs(n.nominal_speed_kt - r.speed_kt) +
                     std::abs(fold_heading_deg(n.heading_deg) - fold_heading_deg(r.heading_deg)) / 30.0;
    if (d < best) {
      best = d;
      nearest = &n;
    }
  }
  if (nearest) {
    why += "; the build could not tow " + std::to_string(skipped) + " condition" + (skipped == 1 ? "" : "s") +
           " of " + g.tug + " / " + g.tow + " (EQ-SWEEP-3), nearest: " + format_value(nearest->nominal_speed_kt) +
           " kt, " + nearest->sea + ", heading " + format_value(nearest->heading_deg) + " deg: " + nearest->note;
  }
  return why;
}

namespace {

// The request field of grid axis a in group g.
std::string axis_field(const Group& g, int a) {
  return a == kSea ? (g.wind_sea ? "wind_kt" : "hs_ft") : kAxisField[a];
}

// The question's grid coordinates and its cell on every axis (EQ-QUERY-6).
struct Located {
  std::array<double, kGridAxes> q{};
  Brackets br;
};

Located locate(const Group& g, const Request& r) {
  Located at;
  at.q[kSpeed] = r.speed_kt;
  at.q[kSea] = g.wind_sea ? r.wind_kt : r.hs_ft;
  at.q[kHeading] = fold_heading_deg(r.heading_deg);
  at.q[kLength] = r.length_ft;
  if (g.wind_sea) {
    at.q[kPeriod] = 0.0;
  } else if (std::isnan(r.tp_s)) {
    if (g.axis[kPeriod].size() > 1) {
      throw InputError("tp_s: a peak period is required; " + g.name() + " stores " +
                       std::to_string(g.axis[kPeriod].size()) + " periods from " +
                       format_value(g.axis[kPeriod].front()) + " to " + format_value(g.axis[kPeriod].back()) + " s");
    }
    at.q[kPeriod] = g.axis[kPeriod].front();
  } else {
    at.q[kPeriod] = r.tp_s;
  }
  for (int a = 0; a < kGridAxes; ++a) {
    const std::string unit = a == kSea ? (g.wind_sea ? "kt" : "ft") : kAxisUnit[a];
    at.br[a] = make_bracket(g.axis[a], at.q[a], r.extrapolate, axis_field(g, a), unit, g.name());
  }
  return at;
}

// Runs fn. Extrapolated far, the interpolant can leave the cell's nodes behind
// or stop being a distribution: a refusal from fn then names the fields that
// were extrapolated and their stored spans.
template <class F>
void naming_extrapolated(const Group& g, const Located& at, const Request& r, F&& fn) {
  std::string fields;
  for (int a = 0; a < kGridAxes; ++a) {
    if (!at.br[a].outside) continue;
    fields += (fields.empty() ? "" : ", ") + axis_field(g, a) + " = " + format_value(at.q[a]) + " (stored " +
              format_value(g.axis[a].front()) + " to " + format_value(g.axis[a].back()) + ")";
  }
  if (fields.empty() && !std::isnan(r.mean_tension_lbf)) fields = "mean_tension_lbf = " + format_value(r.mean_tension_lbf);
  if (!r.extrapolate || fields.empty()) return fn();
  const std::string prefix = "extrapolated from " + fields + ": ";
  try {
    fn();
  } catch (const NumericalError& e) {
    throw NumericalError(prefix + e.what());
  } catch (const OutOfRangeError& e) {
    throw OutOfRangeError(prefix + e.what());
  }
}

// EQ-QUERY-3..5: the numbers of the answer from the evaluated cell, c the
// frequency term of the question's probability and tow days.
void fill_values(const Group& g, const Evaluation& ev, const Request& r, const QueryOptions& o, Space s, double c,
                 Answer* ans) {
  const double c999 = gumbel_reduced_variate(kPlanningProbability);
  ans->tug = g.tug;
  ans->tow = g.tow;
  ans->space = s;
  ans->gumbel_u_kips = ev.u;
  ans->gumbel_alpha_per_kip = 1.0 / ev.beta;
  ans->dynamic_tension_kips = ev.u + ev.beta * c;
  ans->dynamic_999_kips = ev.u + ev.beta * c999;
  // The query's own mean tension when given (the weighted sum only rounds it).
  ans->mean_tension_lbf = !std::isnan(r.mean_tension_lbf) ? r.mean_tension_lbf
                          : g.relative                   ? ev.calc_lbf
                                                         : ev.mean_lbf;
  ans->calculated_mean_tension_lbf = ev.calc_lbf;
  ans->mean_tension_factor = ev.factor;
  ans->extreme_tension_lbf = ans->mean_tension_lbf + ans->dynamic_tension_kips * 1000.0;
  ans->breaking_strength_lbf = ev.bs_min;
  ans->extreme_limit_lbf = ev.bs_min / o.extreme_safety_factor;
  ans->mean_limit_lbf = ev.bs_min / (r.on_brake ? o.mean_safety_factor_brake : o.mean_safety_factor_machine);
  ans->extreme_check_passed = ans->extreme_tension_lbf <= ans->extreme_limit_lbf;
  ans->mean_check_passed = ans->mean_tension_lbf <= ans->mean_limit_lbf;
  ans->slack_fraction = ev.slack;
  ans->catenary_sag_ft = ev.sag_ft;
  ans->catenary_depth_ft = -ev.lowest_ft;
  ans->ci_level = ev.ci_level;
  ans->ci_low_kips = ev.ci_low;
  ans->ci_high_kips = ev.ci_high;
}

// Monotonicity (a warning): more wind (or a higher sea) never lowers the
// dynamic tension (thesis 6.3.1); a longer towline never raises it (6.3.3).
void warn_not_monotone(const Group& g, const Located& at, const Evaluation& ev, Space s, double c, Answer* ans) {
  auto x_at = [&](const NodeValue& v) { return node_u(v, s) + node_beta(v, s) * c; };
  const int n_corners = 1 << ev.active_count;
  for (int j = 0; j < ev.active_count; ++j) {
    const int a = ev.active[j];
    if (a != kSea && a != kLength) continue;
    for (int mask = 0; mask < n_corners; ++mask) {
      if ((mask >> j) & 1) continue;
      const Corner& lo = ev.corners[mask];
      const Corner& hi = ev.corners[mask | (1 << j)];
      if (lo.node < 0 || hi.node < 0) continue;
      const double xl = x_at(lo.value), xh = x_at(hi.value);
      const bool bad = a == kSea ? xh < xl : xh > xl;
      if (!bad) continue;
      const std::string what = a == kSea ? (g.wind_sea ? "more wind" : "a higher sea") : "a longer towline";
      ans->warnings.push_back(
          {WarningKind::kNotMonotone,
           "the stored data are not monotone: " + what + " " + (a == kSea ? "lowers" : "raises") +
               " the dynamic tension between " + axis_field(g, a) + " = " + format_value(g.axis[a][at.br[a].i0]) +
               " and " + format_value(g.axis[a][at.br[a].i1]) + " (" + format_value(xl) + " -> " +
               format_value(xh) + " kips) at " + g.describe(lo.idx) + ", against the physics (thesis 6.3); check "
               "these cases"});
      break;
    }
  }
}

// The warnings of EQ-QUERY-5 and the data's limits, in a fixed order.
void add_warnings(const Group& g, const Located& at, const Evaluation& ev, const Request& asked, const Request& r,
                  double wind_from_hs_kt, const QueryOptions& o, Answer* ans) {
  auto warn = [&](WarningKind kind, std::string msg) { ans->warnings.push_back({kind, std::move(msg)}); };
  if (!std::isnan(wind_from_hs_kt)) {
    warn(WarningKind::kEquivalentWind,
         "hs_ft = " + format_value(asked.hs_ft) + " ft answered as the fully developed (Pierson-Moskowitz) sea of " +
             format_value(std::round(wind_from_hs_kt * 100.0) / 100.0) + " kt wind (Hs = 0.2092 U^2 / g, Tp " +
             format_value(std::round(pm_peak_period_s(wind_from_hs_kt) * 100.0) / 100.0) +
             " s): the database holds wind seas only");
  }
  for (int a = 0; a < kGridAxes; ++a) {
    if (!at.br[a].outside) continue;
    ans->extrapolated = true;
    warn(WarningKind::kExtrapolated,
         axis_field(g, a) + " = " + format_value(at.q[a]) + " is outside the stored range [" +
             format_value(g.axis[a].front()) + ", " + format_value(g.axis[a].back()) + "] of " + g.name() + ": " +
             (g.axis[a].size() == 1 ? "held at the one stored value" : "extrapolated linearly from the end cell"));
  }
  if (ev.mean_extrapolated) {
    ans->extrapolated = true;
    warn(WarningKind::kExtrapolated, "mean_tension_lbf = " + format_value(r.mean_tension_lbf) +
                                         " is outside the mean tensions stored at some grid nodes: extrapolated "
                                         "linearly from each node's two nearest mean tensions");
  }
  if (ans->mean_tension_lbf > o.tug_capacity_lbf) {
    warn(WarningKind::kAboveCapacity,
         "mean tension " + format_value(std::round(ans->mean_tension_lbf)) + " lbf is above " +
             format_value(o.tug_capacity_lbf) +
             " lbf, beyond the capacity of the tugs (thesis ch. 5): the tow would have to slow down; the answer "
             "is for the speed asked");
  }
  if (ev.missing > 0) {
    ans->extrapolated = true;
    warn(WarningKind::kIncompleteGrid, std::to_string(ev.missing) + " of " + std::to_string(1 << ev.active_count) +
                                           " grid nodes around the query are not stored; the answer uses the others "
                                           "(weights renormalised)");
  }
  if (ans->extreme_tension_lbf > ans->breaking_strength_lbf || ev.above_bs) {
    warn(WarningKind::kAboveBreaking,
         "extreme tension " + format_value(std::round(ans->extreme_tension_lbf)) + " lbf" +
             (ans->extreme_tension_lbf > ans->breaking_strength_lbf ? " exceeds" : " is near cases above") +
             " the towline breaking strength " + format_value(ans->breaking_strength_lbf) +
             " lbf: the polynomial towline model is not valid above breaking strength (thesis 6.1); the dynamic "
             "tension is of unknown accuracy there");
  }
  if (ans->dynamic_tension_kips > o.high_tension_warning_kips) {
    warn(WarningKind::kHighTension, "dynamic tension " + format_value(std::round(ans->dynamic_tension_kips * 10) / 10) +
                                        " kips is above " + format_value(o.high_tension_warning_kips) +
                                        " kips, outside the bounds of the towline simulation model (thesis 6.2)");
  }
  if (ans->slack_fraction > o.slack_warning_fraction) {
    warn(WarningKind::kSlack, "slack-prone: the towline is slack " +
                                  format_value(std::round(ans->slack_fraction * 1e4) / 100) +
                                  " % of the time in the stored cases; snatch loads make the Type I fit "
                                  "underestimate the peak tension (thesis 4.2, YRBM in trailing seas)");
  }
  if (ev.bs_max > ev.bs_min * (1.0 + kSameValueRelTol)) {
    warn(WarningKind::kBreakingDiffers, "the cases around the query store different breaking strengths (" +
                                            format_value(ev.bs_min) + " to " + format_value(ev.bs_max) +
                                            " lbf); the smallest is used");
  }
}

// The stored cases of the cell's corner nodes nearest the question (distance
// in cell units along the active axes and relative mean tension), at most count.
std::vector<NearCase> nearest_cases(const Group& g, const Located& at, const Evaluation& ev, double c, int count) {
  std::vector<NearCase> cand;
  for (int mask = 0; mask < (1 << ev.active_count); ++mask) {
    std::array<int, kGridAxes> idx{};
    for (int a = 0; a < kGridAxes; ++a) idx[a] = at.br[a].i0;
    for (int j = 0; j < ev.active_count; ++j) {
      if ((mask >> j) & 1) idx[ev.active[j]] = at.br[ev.active[j]].i1;
    }
    const int node = g.node_index(idx);
    if (node < 0) continue;
    for (const MeanPoint& p : g.nodes[node].points) {
      for (int ci : p.cases) {
        const CaseRec& cr = g.cases[ci];
        NearCase nc;
        nc.case_id = cr.id;
        nc.speed_kt = cr.speed_kt;
        nc.wind_kt = cr.wind_kt;
        nc.hs_ft = cr.hs_ft;
        nc.tp_s = g.wind_sea ? kNaN : cr.tp_s;
        nc.heading_deg = cr.heading_deg;
        nc.length_ft = cr.length_ft;
        nc.mean_tension_lbf = cr.mean_lbf;
        nc.days = cr.days;
        nc.dynamic_999_kips = cr.dynamic_999_kips;
        nc.dynamic_tension_kips = cr.u_kips + cr.beta_kips * c;
        double d2 = 0.0;
        for (int j = 0; j < ev.active_count; ++j) {
          const int a = ev.active[j];
          const double h = g.axis[a][at.br[a].i1] - g.axis[a][at.br[a].i0];
          const double dq = (at.q[a] - g.axis[a][idx[a]]) / h;
          d2 += dq * dq;
        }
        const double dm = (ev.mean_lbf - cr.mean_lbf) / ev.mean_lbf;
        nc.distance = std::sqrt(d2 + dm * dm);
        cand.push_back(nc);
      }
    }
  }
  const std::size_t keep = std::min(cand.size(), static_cast<std::size_t>(count));
  std::partial_sort(cand.begin(), cand.begin() + static_cast<std::ptrdiff_t>(keep), cand.end(),
                    [](const NearCase& a, const NearCase& b) {
                      return a.distance != b.distance ? a.distance < b.distance : a.case_id < b.case_id;
                    });
  cand.resize(keep);
  return cand;
}

}  // namespace

// EQ-QUERY-3..7 for one resolved request in group g: locate the cell,
// evaluate it, the answer's numbers, its uncertainty, warnings and nearest cases.
Answer Engine::answer(const Request& asked, const Request& r, const Group& g, double wind_from_hs_kt) const {
  const Space s = space_;
  const Located at = locate(g, r);
  Evaluation ev;
  naming_extrapolated(g, at, r, [&] { evaluate(g, at.br, MeanTarget{r.mean_tension_lbf, kNaN}, s, r.extrapolate, &ev); });

  const double c = std::log(r.tow_days) + gumbel_reduced_variate(r.probability);
  const double c999 = gumbel_reduced_variate(kPlanningProbability);
  Answer ans;
  ans.equivalent_wind_kt = wind_from_hs_kt;
  fill_values(g, ev, r, options_, s, c, &ans);
  double err = 0.0;
  naming_extrapolated(g, at, r, [&] {
    err = interpolation_error_kips(g, at.br, ev, MeanTarget{r.mean_tension_lbf, ev.factor}, s, r.extrapolate, c,
                                   ans.dynamic_tension_kips);
  });
  ans.interpolation_error_kips = err;
  const double ci_half = 0.5 * (ev.ci_high - ev.ci_low) * quantile_se_factor(c) / quantile_se_factor(c999);
  ans.uncertainty_kips = std::hypot(err, ci_half);
  naming_extrapolated(g, at, r, [&] { require_physical_answer(ans); });

  add_warnings(g, at, ev, asked, r, wind_from_hs_kt, options_, &ans);
  warn_not_monotone(g, at, ev, s, c, &ans);
  if (options_.nearest_cases > 0) ans.nearest = nearest_cases(g, at, ev, c, options_.nearest_cases);
  return ans;
}

// ---------------------------------------------------------------------------
// EQ-QUERY-8: leave-one-out.

LooStats Engine::leave_one_out(Space s, int axis) const {
  if (s == Space::kAuto) throw InputError("space = auto: a leave-one-out report needs linear or log");
  if (s == Space::kLog && !log_ok_) {
    throw InputError("space = log: some stored gumbel_u_kips <= 0, so log-space interpolation is impossible");
  }
  if (axis < kAllAxes || axis > kMeanTensionAxis) {
    throw InputError("axis = " + std::to_string(axis) + ": must be -1 (all) or 0..5");
  }
  const double c999 = gumbel_reduced_variate(kPlanningProbability);
  std::vector<double> rel, abs_err;
  auto record = [&](double pred, double truth) {
    if (!(std::abs(truth) > 0.0)) return;
    rel.push_back(std::abs(pred - truth) / std::abs(truth));
    abs_err.push_back(std::abs(pred - truth));
  };
  for (const Group& g : groups_) {
    for (const Node& node : g.nodes) {
      for (int a = 0; a < kGridAxes; ++a) {
        if (axis != kAllAxes && axis != a) continue;
        const int i = node.index[a], n = static_cast<int>(g.axis[a].size());
        if (i - 1 < 0 || i + 1 >= n) continue;
        auto left_idx = node.index, right_idx = node.index;
        left_idx[a] = i - 1;
        right_idx[a] = i + 1;
        const int l = g.node_index(left_idx), rt = g.node_index(right_idx);
        if (l < 0 || rt < 0) continue;
        const double t = (g.axis[a][i] - g.axis[a][i - 1]) / (g.axis[a][i + 1] - g.axis[a][i - 1]);
        for (const MeanPoint& p : node.points) {
          NodeValue vl, vr;
          // EQ-QUERY-9: on the relative axis the neighbours are read at the same factor.
          const double f = g.relative ? p.mean_lbf / node.calc_lbf : kNaN;
          try {
            vl = node_value(g, g.nodes[l], g.relative ? f * g.nodes[l].calc_lbf : p.mean_lbf, s, false);
            vr = node_value(g, g.nodes[rt], g.relative ? f * g.nodes[rt].calc_lbf : p.mean_lbf, s, false);
          } catch (const OutOfRangeError&) {
            continue;  // the neighbours do not bracket this mean tension
          }
          const double u = from_space((1.0 - t) * vl.g_u + t * vr.g_u, s);
          const double beta = from_space((1.0 - t) * vl.g_beta + t * vr.g_beta, s);
          record(u + beta * c999, p.u_kips + p.beta_kips * c999);
        }
      }
      if (axis == kAllAxes || axis == kMeanTensionAxis) {
        const auto& pts = node.points;
        for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
          const double t = (pts[k].mean_lbf - pts[k - 1].mean_lbf) / (pts[k + 1].mean_lbf - pts[k - 1].mean_lbf);
          const double u = from_space(
              (1.0 - t) * to_space(pts[k - 1].u_kips, s) + t * to_space(pts[k + 1].u_kips, s), s);
          const double beta = from_space(
              (1.0 - t) * to_space(pts[k - 1].beta_kips, s) + t * to_space(pts[k + 1].beta_kips, s), s);
          record(u + beta * c999, pts[k].u_kips + pts[k].beta_kips * c999);
        }
      }
    }
  }
  LooStats st;
  st.space = s;
  st.axis = axis;
  st.samples = static_cast<int>(rel.size());
  std::sort(rel.begin(), rel.end());
  std::sort(abs_err.begin(), abs_err.end());
  st.median_rel_error = percentile(rel, 0.5);
  st.p90_rel_error = percentile(rel, 0.9);
  st.max_rel_error = rel.empty() ? kNaN : rel.back();
  st.median_abs_error_kips = percentile(abs_err, 0.5);
  return st;
}

// ---------------------------------------------------------------------------
// Inverse queries: bracketed search over the interpolant.

SearchResult Engine::max_speed(const Request& request) const { return search(request, kSpeed, true); }
SearchResult Engine::min_length(const Request& request) const { return search(request, kLength, false); }

SearchResult Engine::search(const Request& request, int axis, bool maximise) const {
  Request base = request;
  double& field = axis == kSpeed ? base.speed_kt : base.length_ft;
  const std::string name = axis == kSpeed ? "speed_kt" : "length_ft";
  field = 1.0;  // the searched field is ignored (query.h): a placeholder, validated below, then overwritten
  base.extrapolate = false;  // a search never extrapolates (query.h)
  base.validate();
  // A sea given as Hs is searched as query() answers it (EQ-QUERY-10): resolved
  // once here, not again at every evaluation.
  double wind_from_hs_kt = kNaN;
  base = resolve_sea(base, &wind_from_hs_kt);
  const Group& g = find_group(base);
  const auto& ax = g.axis[axis];
  SearchResult res;
  res.range_low = ax.front();
  res.range_high = ax.back();

  // Samples: every stored value and kSub - 1 points inside every cell.
  constexpr int kSub = 8;
  std::vector<double> xs;
  for (std::size_t i = 0; i + 1 < ax.size(); ++i) {
    for (int k = 0; k < kSub; ++k) xs.push_back(ax[i] + (ax[i + 1] - ax[i]) * k / kSub);
  }
  xs.push_back(ax.back());

  // The first failure, re-raised as its own kind when no value can be evaluated.
  enum class FailureKind { kInput, kRange, kNumerical };
  std::string first_failure;
  FailureKind first_kind = FailureKind::kInput;
  int failures = 0;
  auto fail = [&](const std::exception& e, FailureKind kind) {
    if (first_failure.empty()) {
      first_failure = e.what();
      first_kind = kind;
    }
    ++failures;
    return -1;
  };
  // 1: passes both checks; 0: fails one; -1: cannot be evaluated (outside the data there).
  // Passing also needs a mean tension the tugs can hold (options_.tug_capacity_lbf,
  // thesis ch. 5, the sweep's EQ-SWEEP-3 limit): with the calculated mean
  // tension, which rises with speed, that is the tow's speed limit.
  double above_capacity_lbf = kNaN;
  auto passes = [&](double x) {
    ++res.evaluations;
    field = x;
    try {
      const Answer a = query(base);
      const bool holdable = a.mean_tension_lbf <= options_.tug_capacity_lbf;
      if (!holdable && std::isnan(above_capacity_lbf)) above_capacity_lbf = a.mean_tension_lbf;
      return a.extreme_check_passed && a.mean_check_passed && holdable ? 1 : 0;
    } catch (const DatabaseError&) {
      throw;  // the database itself, not these conditions
    } catch (const OutOfRangeError& e) {
      return fail(e, FailureKind::kRange);
    } catch (const InputError& e) {
      return fail(e, FailureKind::kInput);
    } catch (const NumericalError& e) {
      return fail(e, FailureKind::kNumerical);
    }
  };
  const int n = static_cast<int>(xs.size());
  int hit = -1;
  if (maximise) {
    for (int i = n - 1; i >= 0 && hit < 0; --i) {
      if (passes(xs[i]) == 1) hit = i;
    }
  } else {
    for (int i = 0; i < n && hit < 0; ++i) {
      if (passes(xs[i]) == 1) hit = i;
    }
  }
  if (hit >= 0) {
    res.found = true;
    const bool at_end = maximise ? hit == n - 1 : hit == 0;
    if (at_end) {
      res.value = xs[hit];
    } else {
      double good = xs[hit], bad = maximise ? xs[hit + 1] : xs[hit - 1];
      // Bisection to a millionth of the searched range.
      const double tol = 1e-6 * std::max(res.range_high - res.range_low, 1.0);
      while (std::abs(bad - good) > tol) {
        const double mid = 0.5 * (good + bad);
        if (passes(mid) == 1) {
          good = mid;
        } else {
          bad = mid;
        }
      }
      res.value = good;
    }
  }
  if (failures == res.evaluations) {
    // Not one value could be evaluated: the conditions themselves are outside
    // the stored data (as query() would say), not "no value passes".
    const std::string why = "no " + name + " in the stored range " + format_value(res.range_low) + " to " +
                            format_value(res.range_high) + " can be evaluated for these conditions; first: " +
                            first_failure;
    if (first_kind == FailureKind::kRange) throw OutOfRangeError(why);
    if (first_kind == FailureKind::kNumerical) throw NumericalError(why);
    throw InputError(why);
  }
  if (!std::isnan(above_capacity_lbf)) {
    res.warnings.push_back({WarningKind::kAboveCapacity,
                            "some " + name + " values searched need a mean tension above the tugs' " +
                                format_value(options_.tug_capacity_lbf) + " lbf (first seen: " +
                                format_value(std::round(above_capacity_lbf)) +
                                " lbf; thesis ch. 5): counted as failing"});
  }
  if (failures > 0) {
    res.warnings.push_back({WarningKind::kIncompleteGrid,
                            std::to_string(failures) + " of " + std::to_string(res.evaluations) + " " + name +
                                " values searched could not be evaluated (treated as failing); first: " +
                                first_failure});
  }
  return res;
}

}  // namespace towdb::query
