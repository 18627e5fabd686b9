// Unit conversions at the edges of towdb. Every function name says both units:
// ft_to_m(x) takes feet and returns metres. Solvers work in SI only.
#ifndef TOWDB_COMMON_UNITS_HPP
#define TOWDB_COMMON_UNITS_HPP

#include "common/constants.hpp"

namespace towdb::units {

constexpr double ft_to_m(double ft) { return ft * kMetersPerFoot; }
constexpr double m_to_ft(double m) { return m / kMetersPerFoot; }
constexpr double ft2_to_m2(double ft2) { return ft2 * kMetersPerFoot * kMetersPerFoot; }
constexpr double m2_to_ft2(double m2) { return m2 / (kMetersPerFoot * kMetersPerFoot); }
constexpr double in_to_m(double in) { return in * kMetersPerInch; }
constexpr double kt_to_m_s(double kt) { return kt * kMetersPerSecondPerKnot; }
constexpr double m_s_to_kt(double m_s) { return m_s / kMetersPerSecondPerKnot; }
constexpr double ft_s_to_m_s(double ft_s) { return ft_s * kMetersPerFoot; }
constexpr double m_s_to_ft_s(double m_s) { return m_s / kMetersPerFoot; }
constexpr double lbf_to_n(double lbf) { return lbf * kNewtonsPerPoundForce; }
constexpr double n_to_lbf(double n) { return n / kNewtonsPerPoundForce; }
constexpr double kips_to_n(double kips) { return kips * kNewtonsPerKip; }
constexpr double n_to_kips(double n) { return n / kNewtonsPerKip; }
constexpr double lbf_per_ft_to_n_per_m(double x) { return x * kNewtonsPerPoundForce / kMetersPerFoot; }
constexpr double n_per_m_to_lbf_per_ft(double x) { return x * kMetersPerFoot / kNewtonsPerPoundForce; }
// Mass per length from a weight per length in lb/ft (pound-mass per foot).
constexpr double lb_per_ft_to_kg_per_m(double x) { return x * kKilogramsPerPound / kMetersPerFoot; }
constexpr double lbf_s_per_ft_to_n_s_per_m(double x) { return x * kNewtonsPerPoundForce / kMetersPerFoot; }
constexpr double n_s_per_m_to_lbf_s_per_ft(double x) { return x * kMetersPerFoot / kNewtonsPerPoundForce; }
constexpr double long_tons_to_kg(double lt) { return lt * kKilogramsPerLongTon; }
constexpr double kg_to_long_tons(double kg) { return kg / kKilogramsPerLongTon; }
constexpr double hp_to_w(double hp) { return hp * kWattsPerHorsepower; }
constexpr double deg_to_rad(double deg) { return deg * kRadiansPerDegree; }
constexpr double rad_to_deg(double rad) { return rad / kRadiansPerDegree; }
constexpr double rpm_to_rev_s(double rpm) { return rpm / 60.0; }

}  // namespace towdb::units

#endif  // TOWDB_COMMON_UNITS_HPP
