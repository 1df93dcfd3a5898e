// The truth simulator's earth: gravitation, plumb-line latitude and its inverse.
#include "lib/truth/earth_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lib/common/model_options.h"

namespace insmc {
namespace {

TEST(EarthModel, SchulerFrequencyOfTheFieldIsTheModels) {
  const ModelOptions o;
  const GravityField f = model_gravity_field(o.gravity_mps2, o.radius_m, 0.0);
  EXPECT_NEAR(std::sqrt(f.mu_m3ps2 / std::pow(o.radius_m, 3)), o.schuler_radps(), 1e-18);
  EXPECT_NEAR(f.gravitation(Vec3(0, o.radius_m, 0)).norm(), o.gravity_mps2, 1e-12);
}

TEST(EarthModel, PlumbLatitudeInvertsToRoundOff) {
  const ModelOptions o;
  for (double j2 : {0.0, kEarthJ2}) {
    const GravityField f = model_gravity_field(o.gravity_mps2, o.radius_m, j2);
    for (double deg : {-80.0, -45.0, 0.0, 1e-9, 30.0, 45.0, 89.0}) {
      const double L = deg * kDegToRad;
      const double phi = geocentric_latitude_for_plumb(f, o.earth_rate_radps, o.radius_m, L);
      EXPECT_NEAR(plumb_latitude(f, o.earth_rate_radps, o.radius_m, phi), L, 1e-15) << deg;
    }
  }
}

TEST(EarthModel, PlumbLineOfTheRotatingSphereLeansByTheCentrifugalRatio) {
  // tan L = tan φ / (1 − m), m = ω² r0/g (exact for the sphere): at 45° the
  // plumb latitude exceeds the geocentric one by ≈ m/2 = 1.73 mrad.
  const ModelOptions o;
  const GravityField f = model_gravity_field(o.gravity_mps2, o.radius_m, 0.0);
  const double m = o.earth_rate_radps * o.earth_rate_radps * o.radius_m / o.gravity_mps2;
  const double L = 45.0 * kDegToRad;
  const double phi = geocentric_latitude_for_plumb(f, o.earth_rate_radps, o.radius_m, L);
  EXPECT_NEAR(std::tan(phi), (1 - m) * std::tan(L), 1e-14);
  EXPECT_NEAR(L - phi, 0.5 * m, 0.01 * m);
}

TEST(EarthModel, J2TiltsThePlumbLineByOneAndAHalfJ2Sin2L) {
  // The J2 term adds a north gravitation component −(3/2) J2 g sin 2φ, so the
  // plumb line at a given φ is steeper by (3/2) J2 sin 2φ.
  const ModelOptions o;
  const double w = o.earth_rate_radps, R = o.radius_m;
  const GravityField sphere = model_gravity_field(o.gravity_mps2, R, 0.0);
  const GravityField oblate = model_gravity_field(o.gravity_mps2, R, kEarthJ2);
  const double phi = 0.78;
  const double tilt = plumb_latitude(oblate, w, R, phi) - plumb_latitude(sphere, w, R, phi);
  EXPECT_NEAR(tilt, 1.5 * kEarthJ2 * std::sin(2 * phi), 0.01 * tilt);
}

}  // namespace
}  // namespace insmc
