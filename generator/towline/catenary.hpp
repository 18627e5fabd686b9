// Static multi-segment elastic catenary between the tug's tow point and the
// tow's bow fitting. Equations EQ-TOWLINE-1..5 are stated in towline/towline.hpp.
//
// Axes: x horizontal from the tug's tow point towards the tow, y upward, both
// [m], origin at the waterline below the tug's tow point. s [m] is the
// unstretched (Lagrangian) arc length from the tug end, p [m] the stretched
// arc length. The line's slope angle phi [rad] is positive when the line rises
// towards the tow. End angles alpha_1 (tug) and alpha_2 (tow) are depression
// angles: positive when the line leaves the fitting below the horizontal
// (the usual sagging line has both positive).
#ifndef TOWDB_TOWLINE_CATENARY_HPP
#define TOWDB_TOWLINE_CATENARY_HPP

#include <array>
#include <vector>

#include "model/towline.hpp"

namespace towdb::towline {

// Heights of the two end points of the towline above the waterline [m].
struct TowPoints {
  double tug_height_m = 0.0;  // tug's tow point (thesis T-ATF: about 6 ft)
  double tow_height_m = 0.0;  // tow's bow fitting (about 20-30 ft)
};

struct CatenaryOptions {
  // Vertical closure |sum dy - (h_tow - h_tug)| allowed, relative to the
  // unstretched line length [-]; 1e-12 is a few ulp of the summed increments.
  double closure_tolerance = 1e-12;
  // Safeguarded Newton iterations allowed (each halves the bracket at worst,
  // so 200 covers any bracket down to machine precision).
  int max_iterations = 200;
  void validate() const;
};

// State of the static line at one point.
struct CatenaryPoint {
  double s_m = 0.0;             // unstretched arc length from the tug end
  double p_m = 0.0;             // stretched arc length from the tug end
  double x_m = 0.0;             // horizontal distance from the tug's tow point
  double y_m = 0.0;             // elevation above the waterline
  double tension_n = 0.0;       // T = sqrt(H^2 + V^2)
  double vertical_force_n = 0.0;  // V, the vertical component of the tension
  double slope_rad = 0.0;       // phi = atan(V / H), positive rising to the tow
  double curvature_1_m = 0.0;   // d phi / d p, positive for a sagging line
  int segment = 0;              // index into model::Towline::segments
};

// A solved catenary for one towline, tow-point heights and horizontal tension.
class Catenary {
 public:
  // Solves EQ-TOWLINE-3 for the tug-end vertical force V_0 by a bracketed,
  // safeguarded Newton iteration. `horizontal_tension_n` is the mean towline
  // tension H (the horizontal component, equal at both ends). Throws
  // InputError for an invalid towline or H <= 0, NumericalError if the
  // iteration does not close.
  static Catenary solve(const model::Towline& towline, const TowPoints& points,
                        double horizontal_tension_n, const CatenaryOptions& options = {});

  double horizontal_tension_n() const { return h_n_; }
  double tug_vertical_force_n() const { return v0_n_; }  // V at s = 0 (negative: line descends)
  double tow_vertical_force_n() const;                    // V at the tow end
  double tug_tension_n() const;
  double tow_tension_n() const;
  double tug_angle_rad() const;  // alpha_1, depression angle at the tug
  double tow_angle_rad() const;  // alpha_2, depression angle at the tow
  double span_m() const { return span_m_; }        // horizontal distance X
  double height_difference_m() const { return points_.tow_height_m - points_.tug_height_m; }
  double chord_m() const;                           // straight distance between the ends
  double unstretched_length_m() const { return total_length_m_; }
  double stretched_length_m() const { return stretched_length_m_; }
  // Maximum vertical distance of the line below the chord.
  double sag_m() const;
  // Lowest elevation of the line (negative: below the waterline).
  double lowest_elevation_m() const;
  // Minimum static tension along the line (= H where the line is horizontal).
  double min_tension_n() const;
  // EQ-TOWLINE-4: dH/dX at fixed end heights [N/m].
  double static_stiffness_n_m() const;
  // Flexibility of the tow end relative to the tug end (EQ-TOWLINE-4):
  // [dX, dY]^T = F [dH, dV_tow]^T, F symmetric positive definite [m/N].
  // Row/column 0 horizontal, 1 vertical.
  std::array<std::array<double, 2>, 2> flexibility_m_n() const { return flexibility_; }
  // Series compliance sum_i L_i / (EA)_i [m/N].
  double axial_compliance_m_n() const;

  const model::Towline& towline() const { return towline_; }
  const TowPoints& points() const { return points_; }
  // Start of segment i in unstretched arc length [m] (i = segments: total length).
  double segment_start_m(int i) const { return segment_start_m_[static_cast<std::size_t>(i)]; }
  int segment_count() const { return static_cast<int>(towline_.segments.size()); }

  // The point at unstretched arc length s in [0, unstretched_length_m()].
  CatenaryPoint point_at(double s_m) const;
  // n + 1 points equally spaced in s, from the tug (s = 0) to the tow.
  std::vector<CatenaryPoint> profile(int n) const;

 private:
  model::Towline towline_;
  TowPoints points_;
  double h_n_ = 0.0;
  double v0_n_ = 0.0;
  double span_m_ = 0.0;
  double total_length_m_ = 0.0;
  double stretched_length_m_ = 0.0;
  std::vector<double> segment_start_m_;
  std::vector<double> segment_start_v_n_;  // V at the start of each segment
  std::array<std::array<double, 2>, 2> flexibility_{};
};

}  // namespace towdb::towline

#endif  // TOWDB_TOWLINE_CATENARY_HPP
