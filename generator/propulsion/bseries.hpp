// Wageningen B-series open-water polynomials (EQ-PROPULSION-3 in
// propulsion/propulsion.hpp) and the pitch-ratio solve of EQ-PROPULSION-5.
//
// Inputs are dimensionless: advance ratio J = V_A / (n D), pitch ratio P/D,
// expanded area ratio A_E/A_0 and the blade count Z. Outputs K_T, K_Q and
// their derivatives are dimensionless.
#ifndef TOWDB_PROPULSION_BSERIES_HPP
#define TOWDB_PROPULSION_BSERIES_HPP

#include <span>

namespace towdb::propulsion {

// One polynomial term C * J^s * (P/D)^t * (A_E/A_0)^u * Z^v.
struct BSeriesTerm {
  double coefficient;
  int j_power;      // s
  int pitch_power;  // t
  int area_power;   // u
  int blade_power;  // v
};

// The 39 K_T and 47 K_Q terms of Oosterveld & van Oossanen (1975), Re = 2e6.
std::span<const BSeriesTerm> bseries_kt_terms();
std::span<const BSeriesTerm> bseries_kq_terms();

// Range of the series (Oosterveld & van Oossanen 1975, table 1).
inline constexpr int kBSeriesBladesMin = 2;
inline constexpr int kBSeriesBladesMax = 7;
inline constexpr double kBSeriesAreaRatioMin = 0.30;
inline constexpr double kBSeriesAreaRatioMax = 1.05;
inline constexpr double kBSeriesPitchRatioMin = 0.5;
inline constexpr double kBSeriesPitchRatioMax = 1.4;

// A B-series propeller without its pitch: blade count and A_E/A_0.
struct BSeriesBlades {
  int blades = 4;                    // Z
  double expanded_area_ratio = 0.55; // A_E / A_0

  // Throws InputError unless Z and A_E/A_0 lie inside the series range.
  void validate() const;
};

// K_T, K_Q and the partial derivatives dK_T/dJ, dK_T/d(P/D), dK_Q/dJ at
// (J, P/D). J >= 0; no range check here (callers validate once).
double bseries_kt(const BSeriesBlades& blades, double advance_ratio, double pitch_ratio);
double bseries_kq(const BSeriesBlades& blades, double advance_ratio, double pitch_ratio);
double bseries_dkt_dj(const BSeriesBlades& blades, double advance_ratio, double pitch_ratio);
double bseries_dkt_dpitch(const BSeriesBlades& blades, double advance_ratio, double pitch_ratio);
double bseries_dkq_dj(const BSeriesBlades& blades, double advance_ratio, double pitch_ratio);

// Solves K_T(J, P/D) = kt_target for P/D in [pitch_lo, pitch_hi] by a
// bracketed (safeguarded) Newton iteration. Requires the bracket:
// K_T(J, pitch_lo) <= kt_target <= K_T(J, pitch_hi) (throws InputError
// otherwise; callers check the ends first). Converges to |K_T - target| <=
// 1e-13; throws NumericalError (solver, iteration, residual) if it cannot.
double solve_bseries_pitch_ratio(const BSeriesBlades& blades, double advance_ratio, double kt_target,
                                 double pitch_lo = kBSeriesPitchRatioMin,
                                 double pitch_hi = kBSeriesPitchRatioMax);

}  // namespace towdb::propulsion

#endif  // TOWDB_PROPULSION_BSERIES_HPP
