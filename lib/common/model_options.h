#pragma once
/// Settings of the error model that are not uncertainties: the site, the
/// alignment loop gains and the physical constants. SI units.
#include <limits>

#include "lib/units/units.h"

namespace insmc {

struct ModelOptions {
  /// L_0, latitude of the stationary vehicle [rad]; |L_0| < 90° for system 2
  /// (tan L_0, 1/cos L_0 in (2.16)). Every table of the report uses 45°.
  double latitude_rad = 45.0 * kDegToRad;
  /// F(0)/ω_ie, DC gain of the system-1 leveling loops F_1 = F_2 = F(0)
  /// (§2.1: a 10 s low-pass, well damped, gives 500:1). > 0.
  double leveling_gain_ratio = 500.0;
  /// Its physical range: a loop gain below ten earth rates does not level
  /// (the tilt it leaves, ω_ie/F(0), is no longer small), and above 1e5 the
  /// loop is faster than the 10 s filter that shapes it.
  static constexpr double kMinLevelingGainRatio = 10.0, kMaxLevelingGainRatio = 1e5;
  /// F_T(0)/ω_ie of the system-1 theodolite azimuth loop; +inf (the default:
  /// §2.1 calls F_T(0) large and gives it no value) makes ψ_ωz(1) =
  /// ω_doz/F_T(0) vanish. > 0.
  double azimuth_gain_ratio = std::numeric_limits<double>::infinity();
  /// F_2(0)/ω_ie of the system-2 low-pass y loop (§2.2). F_1 and F_3 are
  /// proportional-plus-integral (infinite DC gain), which gives (2.16). > 0.
  double gyrocompass_f2_ratio = 500.0;
  double earth_rate_radps = kEarthRateRadps;  ///< ω_ie
  double gravity_mps2 = kGravityMps2;         ///< g
  double radius_m = kEarthRadiusM;            ///< r0 = r_e + h_0

  double schuler_radps() const { return schuler_frequency_radps(gravity_mps2, radius_m); }
};

}  // namespace insmc
