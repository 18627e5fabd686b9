// Physical constants and unit conversions: the only place in towdb where a
// numeric constant with a unit may be written (apart from 0, 1, 2 and
// dimensionless coefficients that belong to a cited formula).
//
// Internal unit system: SI (m, kg, s, N, rad). User-facing units (ft, kt, lbf,
// kips, long tons) are converted at the edges with the factors below.
#ifndef TOWDB_COMMON_CONSTANTS_HPP
#define TOWDB_COMMON_CONSTANTS_HPP

#include <numbers>

namespace towdb {

inline constexpr double kPi = std::numbers::pi;

// Standard gravity [m/s^2]. Source: CGPM 1901 / NIST SP 330.
inline constexpr double kGravity_m_s2 = 9.80665;

// Sea water density [kg/m^3] = 1.9905 slug/ft^3 (64.0 lb/ft^3), the naval
// architecture standard used by the thesis and the Navy Towing Manual.
// Source: docs/ship-data.md section 0.
inline constexpr double kRhoSeawater_kg_m3 = 1025.87;

// Air density [kg/m^3] = 0.002377 slug/ft^3 (standard sea-level atmosphere).
inline constexpr double kRhoAir_kg_m3 = 1.2250;

// Kinematic viscosity of sea water at 15 C [m^2/s] (ITTC 2011, 7.5-02-01-03:
// 1.1892e-6 at 15 C, 35 g/kg salinity).
inline constexpr double kNuSeawater_m2_s = 1.1892e-6;

// Euler-Mascheroni constant [-], used by the Gumbel method of moments.
inline constexpr double kEulerGamma = 0.57721566490153286;

// ---- Exact unit conversion factors (NIST SP 811, appendix B) ---------------
inline constexpr double kMetersPerFoot = 0.3048;
inline constexpr double kMetersPerInch = 0.0254;
inline constexpr double kMetersPerSecondPerKnot = 1852.0 / 3600.0;
inline constexpr double kKilogramsPerPound = 0.45359237;
inline constexpr double kNewtonsPerPoundForce = kKilogramsPerPound * kGravity_m_s2;  // 4.4482216...
inline constexpr double kNewtonsPerKip = 1000.0 * kNewtonsPerPoundForce;
inline constexpr double kKilogramsPerLongTon = 2240.0 * kKilogramsPerPound;  // 1016.0469 kg
inline constexpr double kWattsPerHorsepower = 745.69987158227022;          // mechanical hp
inline constexpr double kSecondsPerDay = 86400.0;
inline constexpr double kRadiansPerDegree = kPi / 180.0;

}  // namespace towdb

#endif  // TOWDB_COMMON_CONSTANTS_HPP
