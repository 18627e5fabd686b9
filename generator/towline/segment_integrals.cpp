#include "towline/segment_integrals.hpp"

#include <cmath>

namespace towdb::towline {

namespace {

double r_of(double u) { return std::sqrt(1.0 + u * u); }

// asinh(b) - asinh(a) for 0 <= a <= b, without cancellation:
// log((b + r_b) / (a + r_a)) = log1p((b - a) (1 + (a + b)/(r_a + r_b)) / (a + r_a)).
double asinh_diff_nonneg(double a, double b) {
  const double ra = r_of(a);
  const double rb = r_of(b);
  return std::log1p((b - a) * (1.0 + (a + b) / (ra + rb)) / (a + ra));
}

// <1/r> over [a, b].
double mean_inv_r(double a, double b) {
  const double d = b - a;
  if (d == 0.0) return 1.0 / r_of(a);
  if (a >= 0.0) return asinh_diff_nonneg(a, b) / d;
  if (b <= 0.0) return asinh_diff_nonneg(-b, -a) / d;
  return (std::asinh(b) - std::asinh(a)) / d;  // opposite signs: no cancellation
}

// <u/r> over [a, b] (exact for d = 0 too).
double mean_u_over_r(double a, double b) { return (a + b) / (r_of(a) + r_of(b)); }

// <1/r^3> over [a, b]: (b/r_b - a/r_a)/d.
double mean_inv_r3(double a, double b) {
  const double d = b - a;
  const double ra = r_of(a);
  const double rb = r_of(b);
  if (d == 0.0) return 1.0 / (ra * ra * ra);
  if (a < 0.0 && b > 0.0) return (b / rb - a / ra) / d;
  // Same sign: b r_a - a r_b = d (a + b) / (b r_a + a r_b).
  return (a + b) / ((b * ra + a * rb) * ra * rb);
}

// <u/r^3> over [a, b]: (1/r_a - 1/r_b)/d.
double mean_u_over_r3(double a, double b) {
  const double ra = r_of(a);
  const double rb = r_of(b);
  return (a + b) / ((ra + rb) * ra * rb);
}

// <r> over [a, b]: (1/2)[u r + asinh u]_a^b / d; Simpson's rule for a very
// short interval (error ~ d^4 / 2880, below 1e-16 for d < 1e-3).
double mean_r(double a, double b) {
  const double d = b - a;
  if (d < 1e-3) return (r_of(a) + 4.0 * r_of(0.5 * (a + b)) + r_of(b)) / 6.0;
  return 0.5 * ((b * r_of(b) - a * r_of(a)) / d + mean_inv_r(a, b));
}

}  // namespace

SegmentIncrements segment_increments(double h_n, double v_start_n, double w_n_m, double ea_n,
                                     double length_m) {
  SegmentIncrements inc;
  const double l = length_m;
  const double a = v_start_n / h_n;
  const double b = a + w_n_m * l / h_n;
  const double elastic = l / ea_n;  // L / EA [m/N]
  const double i1 = mean_inv_r(a, b);
  const double i3 = mean_inv_r3(a, b);
  const double i4 = mean_u_over_r3(a, b);
  inc.dx_m = l * i1 + h_n * elastic;
  inc.dy_m = l * mean_u_over_r(a, b) + elastic * (v_start_n + 0.5 * w_n_m * l);
  inc.dp_m = l + h_n * elastic * mean_r(a, b);
  inc.dx_dh_m_n = (l / h_n) * (i1 - i3) + elastic;  // <u^2/r^3> = <1/r> - <1/r^3>
  inc.dx_dv_m_n = -(l / h_n) * i4;
  inc.dy_dh_m_n = inc.dx_dv_m_n;
  inc.dy_dv_m_n = (l / h_n) * i3 + elastic;
  return inc;
}

}  // namespace towdb::towline
