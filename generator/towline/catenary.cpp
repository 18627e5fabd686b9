#include "towline/catenary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/error.hpp"
#include "towline/segment_integrals.hpp"

namespace towdb::towline {

void CatenaryOptions::validate() const {
  require_in_range("catenary.closure_tolerance", closure_tolerance, 1e-16, 1e-3);
  require_in_range("catenary.max_iterations", max_iterations, 10, 10000);
}

namespace {

struct Closure {
  double x_m = 0.0;      // sum dx
  double y_m = 0.0;      // sum dy
  double p_m = 0.0;      // sum dp (stretched length)
  double x_h = 0.0;      // d x / d H
  double x_v = 0.0;      // d x / d V0
  double y_h = 0.0;      // d y / d H
  double y_v = 0.0;      // d y / d V0
};

// Sums the segment increments (EQ-TOWLINE-2) for given H and V0.
Closure close_line(const model::Towline& line, double h_n, double v0_n) {
  Closure c;
  double v_n = v0_n;
  for (const auto& seg : line.segments) {
    const SegmentIncrements inc =
        segment_increments(h_n, v_n, seg.component.weight_in_water_n_m, seg.component.ea_n,
                           seg.length_m);
    c.x_m += inc.dx_m;
    c.y_m += inc.dy_m;
    c.p_m += inc.dp_m;
    c.x_h += inc.dx_dh_m_n;
    c.x_v += inc.dx_dv_m_n;
    c.y_h += inc.dy_dh_m_n;
    c.y_v += inc.dy_dv_m_n;
    v_n += seg.component.weight_in_water_n_m * seg.length_m;
  }
  return c;
}

}  // namespace

Catenary Catenary::solve(const model::Towline& towline, const TowPoints& points,
                         double horizontal_tension_n, const CatenaryOptions& options) {
  model::validate(towline);
  options.validate();
  require_positive("catenary horizontal (mean) tension [N]", horizontal_tension_n);
  require_in_range("tow_points.tug_height_m", points.tug_height_m, -1e3, 1e3);
  require_in_range("tow_points.tow_height_m", points.tow_height_m, -1e3, 1e3);
  const double length_m = towline.total_length_m();
  const double dh_m = points.tow_height_m - points.tug_height_m;
  require_input(std::abs(dh_m) < 0.99 * length_m, "tow point height difference [m]", dh_m,
                "must be smaller in magnitude than 0.99 x the towline length " +
                    format_value(length_m) + " m");

  const double h = horizontal_tension_n;
  double weight_n = 0.0;
  for (const auto& seg : towline.segments) weight_n += seg.component.weight_in_water_n_m * seg.length_m;

  // f(V0) = sum dy - dh is strictly increasing in V0 (d f / d V0 = y_v > 0).
  // Bracket it around the guess "half the weight hangs from each end".
  auto residual = [&](double v0) { return close_line(towline, h, v0).y_m - dh_m; };
  const double guess = -0.5 * weight_n + h * dh_m / length_m;
  double step = std::max(weight_n, h) + 1.0;
  double lo = guess - step;
  double hi = guess + step;
  double f_lo = residual(lo);
  double f_hi = residual(hi);
  for (int k = 0; f_lo > 0.0 && k < 200; ++k) {
    lo -= step;
    step *= 2.0;
    f_lo = residual(lo);
  }
  step = std::max(weight_n, h) + 1.0;
  for (int k = 0; f_hi < 0.0 && k < 200; ++k) {
    hi += step;
    step *= 2.0;
    f_hi = residual(hi);
  }
  if (!(f_lo <= 0.0 && f_hi >= 0.0)) {
    throw NumericalError("catenary bracket for the tug-end vertical force failed: f(lo) = " +
                         format_value(f_lo) + ", f(hi) = " + format_value(f_hi));
  }

  // Safeguarded Newton: a Newton step that leaves the bracket is replaced by
  // bisection, so convergence is guaranteed from taut to slack.
  const double tol_m = options.closure_tolerance * length_m;
  double v0 = std::clamp(guess, lo, hi);
  double f = 0.0;
  int iteration = 0;
  for (; iteration < options.max_iterations; ++iteration) {
    const Closure c = close_line(towline, h, v0);
    f = c.y_m - dh_m;
    if (std::abs(f) <= tol_m) break;
    if (f < 0.0) {
      lo = v0;
    } else {
      hi = v0;
    }
    double next = v0 - f / c.y_v;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == v0 || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(v0)) {
      break;  // bracket at machine precision; residual checked below
    }
    v0 = next;
  }
  const Closure c = close_line(towline, h, v0);
  f = c.y_m - dh_m;
  if (!std::isfinite(f) || std::abs(f) > std::max(tol_m, 1e-9 * length_m)) {
    throw NumericalError("catenary closure (safeguarded Newton on V0) did not converge: iteration " +
                         std::to_string(iteration) + ", residual " + format_value(f) + " m");
  }

  Catenary cat;
  cat.towline_ = towline;
  cat.points_ = points;
  cat.h_n_ = h;
  cat.v0_n_ = v0;
  cat.span_m_ = c.x_m;
  cat.total_length_m_ = length_m;
  cat.stretched_length_m_ = c.p_m;
  cat.flexibility_ = {{{c.x_h, c.x_v}, {c.y_h, c.y_v}}};
  double s = 0.0;
  double v = v0;
  for (const auto& seg : towline.segments) {
    cat.segment_start_m_.push_back(s);
    cat.segment_start_v_n_.push_back(v);
    s += seg.length_m;
    v += seg.component.weight_in_water_n_m * seg.length_m;
  }
  cat.segment_start_m_.push_back(s);
  cat.segment_start_v_n_.push_back(v);
  return cat;
}

double Catenary::tow_vertical_force_n() const { return segment_start_v_n_.back(); }
double Catenary::tug_tension_n() const { return std::hypot(h_n_, v0_n_); }
double Catenary::tow_tension_n() const { return std::hypot(h_n_, tow_vertical_force_n()); }
double Catenary::tug_angle_rad() const { return std::atan2(-v0_n_, h_n_); }
double Catenary::tow_angle_rad() const { return std::atan2(tow_vertical_force_n(), h_n_); }
double Catenary::chord_m() const { return std::hypot(span_m_, height_difference_m()); }

double Catenary::axial_compliance_m_n() const { return towline_.axial_compliance_m_per_n(); }

double Catenary::static_stiffness_n_m() const {
  // EQ-TOWLINE-4: with the heights fixed, dY = 0 gives dV0 = -(Y_H / Y_V) dH,
  // so dX/dH = X_H - X_V Y_H / Y_V.
  const auto& f = flexibility_;
  const double dx_dh = f[0][0] - f[0][1] * f[1][0] / f[1][1];
  return 1.0 / dx_dh;
}

CatenaryPoint Catenary::point_at(double s_m) const {
  const double s = std::clamp(s_m, 0.0, total_length_m_);
  const int n = segment_count();
  int i = 0;
  while (i + 1 < n && s > segment_start_m_[static_cast<std::size_t>(i + 1)]) ++i;
  CatenaryPoint pt;
  double x = 0.0;
  double y = points_.tug_height_m;
  double p = 0.0;
  for (int k = 0; k < i; ++k) {
    const auto& seg = towline_.segments[static_cast<std::size_t>(k)];
    const SegmentIncrements inc =
        segment_increments(h_n_, segment_start_v_n_[static_cast<std::size_t>(k)],
                           seg.component.weight_in_water_n_m, seg.component.ea_n, seg.length_m);
    x += inc.dx_m;
    y += inc.dy_m;
    p += inc.dp_m;
  }
  const auto& seg = towline_.segments[static_cast<std::size_t>(i)];
  const double w = seg.component.weight_in_water_n_m;
  const double ea = seg.component.ea_n;
  const double part = s - segment_start_m_[static_cast<std::size_t>(i)];
  const double v_start = segment_start_v_n_[static_cast<std::size_t>(i)];
  const SegmentIncrements inc = segment_increments(h_n_, v_start, w, ea, part);
  pt.s_m = s;
  pt.x_m = x + inc.dx_m;
  pt.y_m = y + inc.dy_m;
  pt.p_m = p + inc.dp_m;
  pt.vertical_force_n = v_start + w * part;
  pt.tension_n = std::hypot(h_n_, pt.vertical_force_n);
  pt.slope_rad = std::atan2(pt.vertical_force_n, h_n_);
  // EQ-TOWLINE-5: kappa = d phi/dp = (H w / T^2) / (1 + T/EA).
  pt.curvature_1_m = h_n_ * w / (pt.tension_n * pt.tension_n * (1.0 + pt.tension_n / ea));
  pt.segment = i;
  return pt;
}

std::vector<CatenaryPoint> Catenary::profile(int n) const {
  require_in_range("catenary profile point count", n, 1, 1000000);
  std::vector<CatenaryPoint> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) out.push_back(point_at(total_length_m_ * k / n));
  return out;
}

namespace {
// Unstretched arc length at which the vertical force reaches `target_n`
// (V is non-decreasing along the line), clamped to the ends.
double arc_where_vertical_force(const Catenary& cat, double target_n) {
  const auto& segs = cat.towline().segments;
  double v = cat.tug_vertical_force_n();
  if (target_n <= v) return 0.0;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const double w = segs[i].component.weight_in_water_n_m;
    const double v_end = v + w * segs[i].length_m;
    if (target_n <= v_end && w > 0.0) {
      return cat.segment_start_m(static_cast<int>(i)) + (target_n - v) / w;
    }
    v = v_end;
  }
  return cat.unstretched_length_m();
}
}  // namespace

double Catenary::sag_m() const {
  // The largest distance below the chord is where the slope equals the
  // chord's: V* = H dh / X (the line is convex since w >= 0).
  const double dh = height_difference_m();
  const double s_star = arc_where_vertical_force(*this, h_n_ * dh / span_m_);
  const CatenaryPoint pt = point_at(s_star);
  const double y_chord = points_.tug_height_m + dh * pt.x_m / span_m_;
  return std::max(0.0, y_chord - pt.y_m);
}

double Catenary::lowest_elevation_m() const {
  return point_at(arc_where_vertical_force(*this, 0.0)).y_m;
}

double Catenary::min_tension_n() const {
  return point_at(arc_where_vertical_force(*this, 0.0)).tension_n;
}

}  // namespace towdb::towline
