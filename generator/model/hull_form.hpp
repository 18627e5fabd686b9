// Station table (Lewis-form strips) generated from a hull's principal
// particulars, for vessels whose lines are not published.
//
// Method: a parametric sectional-area curve matched to the prismatic
// coefficient and the LCB, a parametric waterline-beam curve matched to the
// waterplane coefficient, a constant draft, and sigma = A / (B T) per station.
// Literature: power-law ("parabolic") sectional-area and waterline curves are
// a common preliminary-design idealisation; C_p and LCB are the usual controls
// of a sectional-area curve (Lackenby, "On the systematic geometrical variation
// of ship forms", Trans. INA 92, 1950). The default waterplane coefficient is
// Papanikolaou, Ship Design (Springer 2014) eq. 2.83, for normal sections.
//
// Conventions (same as model/vessel.hpp; re-derived here):
//   x from midships (half of L_pp), positive forward; stations ordered aft to
//   forward, x_0 = -L/2 (aft perpendicular), x_{N-1} = +L/2 (fore perp.).
//   xi = 2 x / L in [-1, 1]; LCB positive forward of midships.
//   Sign check (done for this module): the moment sum_i w_i x_i A_i gains from
//   the fore half (x > 0) and loses from the aft half, so filling the fore half
//   (larger n_f) at fixed volume (smaller n_a) moves the LCB forward: the LCB
//   is increasing in the fore half's area, which is what the bisection of
//   EQ-HULLFORM-4 brackets.
//
// Units: inputs and outputs SI: length_pp_m, beam_m, draft_m, lcb_m and the
//   station x_m, beam_m, draft_m in m; coefficients dimensionless.
//
// Equations (xi >= 0 forward half "f", xi < 0 aft half "a"):
//   EQ-HULLFORM-1  x_i = -L/2 + i L / (N - 1),  i = 0..N-1;  xi_i = 2 x_i / L.
//   EQ-HULLFORM-2  sectional area A(x) = a(xi) A_M,  A_M = C_m B T,
//                  a(xi) = 1 - |xi|^n_h  (n_f forward, n_a aft, n_h > 0);
//                  a = 1 at midships, a = 0 at a pointed end.
//   EQ-HULLFORM-3  continuous half fullness and first moment of one half:
//                  C_h = int_0^1 a dxi = n_h / (n_h + 1),
//                  int_0^1 xi a dxi = C_h / (2 (2 - C_h)),
//                  so C_p = (C_f + C_a) / 2 and
//                  2 LCB / L = [C_f/(2(2-C_f)) - C_a/(2(2-C_a))] / (C_f + C_a).
//   EQ-HULLFORM-4  n_f, n_a are fitted so that the trapezoidal sums over the
//                  generated stations (the integrals strip theory uses) give
//                  exactly (to the bisection tolerance)
//                    V   = sum_i w_i A(x_i)            = C_b L B T,
//                    LCB = sum_i w_i x_i A(x_i) / V    (given),
//                  w_i the trapezoid weights in x. C_p = C_b / C_m.
//   EQ-HULLFORM-5  waterline beam B(x) = b(xi) B, b(xi) = 1 - |xi|^p_h, with
//                  each half's fullness C_wh = 1 - r (1 - C_h),
//                  r = (1 - C_wp) / (1 - C_p), so that
//                  sum_i w_i B(x_i) = C_wp L B (trapezoid, fitted as in -4).
//                  Default C_wp = max((1 + 2 C_b) / 3, C_p).
//   EQ-HULLFORM-6  draft T(x) = T wherever B(x) > 0 (constant draft; no
//                  cut-up stern or rise of floor), T(x) = 0 at a pointed end;
//                  sigma(x) = A / (B(x) T(x)) = C_m a / b.
//                  C_wp >= C_p gives C_wh >= C_h, hence p_h >= n_h, hence
//                  b >= a and 0 < sigma <= C_m <= 1 at every station with
//                  B(x) > 0; sigma = 0 only where B(x) = T(x) = 0.
//   EQ-HULLFORM-7  box barge limit: C_p = 1 (C_b = C_m) gives a = b = 1 and
//                  sigma = C_m at every station, ends included.
// Because a pointed end has a = 0, each half's trapezoid fullness is at most
// 1 - 1/(N-1) (0.95 for 21 stations); fuller halves need more stations.
// Limitations: sigma is not checked against the Lewis-form validity range
// (the seakeeping module maps or clips it); appendages, bulbs, transoms and
// sonar domes are not represented.
#ifndef TOWDB_MODEL_HULL_FORM_HPP
#define TOWDB_MODEL_HULL_FORM_HPP

#include <vector>

#include "model/vessel.hpp"

namespace towdb::model {

// The particulars a station table is generated from (no defaults: all must be set).
struct HullFormParticulars {
  double length_pp_m = 0.0;             // L between perpendiculars, > 0
  double beam_m = 0.0;                  // waterline beam B, > 0
  double draft_m = 0.0;                 // hull draft T, > 0
  double block_coefficient = 0.0;       // C_b = V / (L B T), in (0, 1]
  double midship_coefficient = 0.0;     // C_m = A_M / (B T), in [C_b, 1]
  double lcb_m = 0.0;                   // LCB from midships, + forward, |LCB| < L/4
  double waterplane_coefficient = 0.0;  // C_wp in [C_p, 1); 0 = estimate (EQ-HULLFORM-5)

  // Throws InputError naming the field, its value and the allowed range.
  void validate() const;
  double prismatic_coefficient() const { return block_coefficient / midship_coefficient; }
};

struct HullFormOptions {
  int station_count = 21;            // N, 5..1001: 21 is the 5D/strip-theory custom (20 intervals)
  double relative_tolerance = 1e-12;  // bisection stops when the fitted integral is this close
  int max_iterations = 200;          // bisection steps per fitted exponent (2^-200 brackets anything)

  void validate() const;
};

struct HullForm {
  std::vector<Station> stations;    // aft to forward (EQ-HULLFORM-1, -6)
  double prismatic_coefficient = 0.0;
  double waterplane_coefficient = 0.0;  // the C_wp used (given or estimated)
  double area_exponent_fore = 0.0;      // n_f (EQ-HULLFORM-2); +infinity for a box
  double area_exponent_aft = 0.0;       // n_a
  double beam_exponent_fore = 0.0;      // p_f (EQ-HULLFORM-5)
  double beam_exponent_aft = 0.0;       // p_a
  bool is_box = false;                  // C_p = 1: a = b = 1 everywhere (EQ-HULLFORM-7)
};

// Generates the station table; throws InputError for invalid or unreachable
// particulars (e.g. an LCB no power-law curve with this C_p can place) and
// NumericalError if a bisection does not meet the tolerance.
HullForm generate_hull_form(const HullFormParticulars& particulars,
                            const HullFormOptions& options = {});

// Trapezoidal integrals over a station table (x in m), as strip theory sums them.
// Volume sum w_i sigma_i B_i T_i [m^3].
double station_volume_m3(const std::vector<Station>& stations);
// Centroid of the sectional areas [m from midships, + forward].
double station_lcb_m(const std::vector<Station>& stations);
// Waterplane area sum w_i B_i [m^2].
double station_waterplane_area_m2(const std::vector<Station>& stations);

}  // namespace towdb::model

#endif  // TOWDB_MODEL_HULL_FORM_HPP
