#pragma once
/// Physical constants and the only unit-conversion factors in insmc.
///
/// SI inside: every quantity in lib/ and montecarlo/ is in metres, seconds,
/// radians (and their products). The paper's units (ft, mg, meru, mrad, ppm,
/// n.mi.) appear only at the edges (apps/, tables/, montecarlo/report/), via the
/// constants below, each named by both of its units.
///
/// Constants the report does not print (tables/notes/errata.md#transcription-slips):
/// ω_ie = 7.292115e-5 rad/s, g = 32.174 ft/s² = 9.80665 m/s², r0 = 20.9e6 ft,
/// giving a Schuler period of 84.4 min.
#include <cmath>
#include <numbers>

namespace insmc {

// ---- base conversions -------------------------------------------------------
inline constexpr double kFtToM = 0.3048;                   ///< international foot
inline constexpr double kNmiToM = 1852.0;                  ///< nautical mile
inline constexpr double kMinToS = 60.0;
inline constexpr double kHourToS = 3600.0;
inline constexpr double kDegToRad = std::numbers::pi / 180.0;
inline constexpr double kArcminToRad = kDegToRad / 60.0;
inline constexpr double kArcsecToRad = kDegToRad / 3600.0;
inline constexpr double kMradToRad = 1e-3;
inline constexpr double kUradToRad = 1e-6;
inline constexpr double kPpmToUnit = 1e-6;                 ///< parts per million → dimensionless

// ---- earth and gravity ------------------------------------------------------
inline constexpr double kEarthRateRadps = 7.292115e-5;    ///< ω_ie, earth rate w.r.t. inertial space
inline constexpr double kGravityMps2 = 9.80665;           ///< g (= 32.174 ft/s²)
inline constexpr double kEarthRadiusM = 20.9e6 * kFtToM;  ///< r0 = 20.9e6 ft = 6.37032e6 m

/// ω_s = sqrt(g / r0), the Schuler frequency (§3.2.2: ω_s² = E/r0³ = g/r0).
inline double schuler_frequency_radps(double gravity_mps2 = kGravityMps2,
                                      double radius_m = kEarthRadiusM) {
  return std::sqrt(gravity_mps2 / radius_m);
}

// ---- paper units ------------------------------------------------------------
inline constexpr double kMeruToRadps = 1e-3 * kEarthRateRadps;  ///< milli earth rate unit
inline constexpr double kMgToMps2 = 1e-3 * kGravityMps2;
inline constexpr double kUgToMps2 = 1e-6 * kGravityMps2;
inline constexpr double kFtpsToMps = kFtToM;
inline constexpr double kDegphToRadps = kDegToRad / kHourToS;

}  // namespace insmc
