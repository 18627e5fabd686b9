// Closed-form increments of the elastic catenary over one uniform segment
// (EQ-TOWLINE-2 integrated), written so that they stay accurate from a
// weightless straight line (w = 0) to a deep slack catenary. Internal to the
// towline module.
//
// With u = V/H along the segment, u runs linearly from a = V_start/H to
// b = a + w L / H (delta = b - a >= 0), r(u) = sqrt(1 + u^2), T = H r.
//   dx = L <1/r> + H L / EA          dy = L <u/r> + L (V_start + V_end) / (2 EA)
//   dp = L + (H L / EA) <r>          (stretched length)
//   dx/dH = (L/H) <u^2/r^3> + L/EA   dx/dV = dy/dH = -(L/H) <u/r^3>
//   dy/dV = (L/H) <1/r^3> + L/EA
// where <f> = (1/delta) int_a^b f(u) du (the mean over the segment), and dV
// is a change of the vertical force at the segment start (equal all along).
// The means use differences rewritten to avoid cancellation, e.g.
//   <u/r> = (a + b) / (r_a + r_b),  asinh b - asinh a = log1p(...).
#ifndef TOWDB_TOWLINE_SEGMENT_INTEGRALS_HPP
#define TOWDB_TOWLINE_SEGMENT_INTEGRALS_HPP

namespace towdb::towline {

struct SegmentIncrements {
  double dx_m = 0.0;
  double dy_m = 0.0;
  double dp_m = 0.0;
  double dx_dh_m_n = 0.0;  // partial derivatives by H and V_0 [m/N]
  double dx_dv_m_n = 0.0;
  double dy_dh_m_n = 0.0;
  double dy_dv_m_n = 0.0;
};

// Increments over an unstretched length `length_m` of a segment with
// submerged weight w [N/m] and axial stiffness EA [N], starting with
// vertical force v_start [N], under horizontal tension h [N] > 0.
SegmentIncrements segment_increments(double h_n, double v_start_n, double w_n_m, double ea_n,
                                     double length_m);

}  // namespace towdb::towline

#endif  // TOWDB_TOWLINE_SEGMENT_INTEGRALS_HPP
