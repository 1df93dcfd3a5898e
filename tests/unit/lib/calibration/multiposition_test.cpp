// The multi-position calibration (lib/calibration/multiposition.h) on
// synthetic recordings written from the model's inverse: exact without
// noise; with noise, each interval covers its true value at its stated
// rate (binomial bounds at a family-wise 0.001 over the parameters).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include <boost/math/distributions/binomial.hpp>

#include "lib/calibration/multiposition.h"
#include "lib/calibration/static_segments.h"
#include "tests/unit/lib/calibration/multiposition_recording.h"

namespace insmc::testing {
namespace {

std::vector<const calibration::CalibratedParameter*> all_parameters(const calibration::MultipositionCalibration& c) {
  std::vector<const calibration::CalibratedParameter*> out;
  for (const auto* f : {&c.accel, &c.gyro_static, &c.gyro_turns})
    for (const auto& p : f->parameters) out.push_back(&p);
  return out;
}

TEST(StaticSegments, FindsEachStillAttitudeOnce) {
  std::mt19937_64 rng(7);
  SensorErrors e = draw_errors(rng);
  const ImuSamples s = multiposition_recording(e, 15, 6.0, rng);
  const auto segments = calibration::find_static_segments(s, {});
  ASSERT_EQ(segments.size(), 16u);  // the first attitude and 15 more
  for (const auto& seg : segments) EXPECT_GE(s.t_s[seg.end - 1] - s.t_s[seg.begin], 2.0);
}

TEST(Multiposition, RecoversEveryParameterWithoutNoise) {
  // Seed 4: its 20 random turns leave 21 attitudes at least 5° apart (seed 3,
  // drawn in order, put two within 2° of each other: 20 orientations).
  std::mt19937_64 rng(4);
  SensorErrors e = draw_errors(rng);
  e.accel_noise_mps2 = e.gyro_noise_radps = 0;
  const ImuSamples s = multiposition_recording(e, 20, 6.0, rng);
  const calibration::MultipositionCalibration c = calibration::calibrate_multiposition(s, {});
  ASSERT_TRUE(c.accel.fitted && c.gyro_static.fitted && c.gyro_turns.fitted) << c.accel.why_not;
  EXPECT_EQ(c.orientations, 21u);
  const auto truth = truth_of(e);
  for (const auto* p : all_parameters(c)) {
    ASSERT_TRUE(truth.count(p->name)) << p->name;
    // Rounding only: the difference steps of the Jacobian and the
    // first-order unit-vector residual leave ~1e-9 relative.
    EXPECT_NEAR(p->value_si, truth.at(p->name), 1e-7 * std::max(1.0, std::abs(truth.at(p->name)))) << p->name;
    EXPECT_TRUE(p->separable()) << p->name << " vif " << p->vif;
  }
}

TEST(Multiposition, FewAttitudesAreNotCalibrated) {
  std::mt19937_64 rng(5);
  const ImuSamples s = multiposition_recording(draw_errors(rng), 5, 6.0, rng);
  const calibration::MultipositionCalibration c = calibration::calibrate_multiposition(s, {});
  EXPECT_FALSE(c.accel.fitted);
  EXPECT_NE(c.accel.why_not.find("6 still attitudes"), std::string::npos) << c.accel.why_not;
}

TEST(Multiposition, AccelerometersThatDoNotSeeGravityAreNotCalibrated) {
  std::mt19937_64 rng(9);
  ImuSamples s = multiposition_recording(draw_errors(rng), 15, 6.0, rng);
  for (Vec3& a : s.accel_b_mps2) a /= kGravityMps2;  // a unit mistake: g read as m/s²
  const calibration::MultipositionCalibration c = calibration::calibrate_multiposition(s, {});
  EXPECT_FALSE(c.accel.fitted);
  EXPECT_NE(c.accel.why_not.find("not near gravity"), std::string::npos) << c.accel.why_not;
}

// Turns about one body axis keep gravity in the plane across it: that
// axis's accelerometer never sees gravity, and a fit would make up its
// scale factor.
TEST(Multiposition, AttitudesInOnePlaneAreNotCalibrated) {
  std::mt19937_64 rng(13);
  const ImuSamples s = multiposition_recording(draw_errors(rng), 20, 6.0, rng, Vec3::UnitX());
  const calibration::MultipositionCalibration c = calibration::calibrate_multiposition(s, {});
  EXPECT_GE(c.orientations, 6u);
  EXPECT_FALSE(c.accel.fitted);
  EXPECT_NE(c.accel.why_not.find("one plane"), std::string::npos) << c.accel.why_not;
}

// Gyro outputs read in the wrong unit (rad/s as deg/s): the turns do not
// follow the model from the declared scale (the scale factor would be
// 1/57.3 − 1), and (C.4) says so instead of fitting a local minimum.
TEST(Multiposition, GyrosInTheWrongUnitFailTheTurnsFit) {
  std::mt19937_64 rng(17);
  ImuSamples s = multiposition_recording(draw_errors(rng), 20, 6.0, rng);
  for (Vec3& w : s.gyro_b_radps) w /= kDegToRad;
  const calibration::MultipositionCalibration c = calibration::calibrate_multiposition(s, {});
  EXPECT_TRUE(c.accel.fitted);
  EXPECT_FALSE(c.gyro_turns.fitted);
  EXPECT_NE(c.gyro_turns.why_not.find("gyro columns and their unit"), std::string::npos) << c.gyro_turns.why_not;
}

// Turns at a steady rate about the vertical change neither the gravity
// direction nor the gyro variance: the gyro means must tell them apart.
TEST(StaticSegments, ASteadyTurnAboutTheVerticalIsNotStill) {
  std::mt19937_64 rng(23);
  const ImuSamples s = multiposition_recording(draw_errors(rng), 10, 6.0, rng, Vec3::UnitZ());
  EXPECT_EQ(calibration::find_static_segments(s, {}).size(), 11u);
}

// A quiet quantized sensor: most windows have zero variance, and one step
// of the quantum must not count as a turn (the reference is floored at q²/12).
TEST(StaticSegments, AQuantizedQuietSensorKeepsItsAttitudesWhole) {
  std::mt19937_64 rng(19);
  SensorErrors e = draw_errors(rng);
  e.accel_noise_mps2 = 0.2 * kMgToMps2;  // 0.2 of a 1 mg step
  e.gyro_noise_radps = 0.2 * 1e-3;       // 0.2 of a 1 mrad/s step
  ImuSamples s = multiposition_recording(e, 20, 6.0, rng);
  for (Vec3& a : s.accel_b_mps2) a = (a / kMgToMps2).array().round().matrix() * kMgToMps2;
  for (Vec3& w : s.gyro_b_radps) w = (w / 1e-3).array().round().matrix() * 1e-3;
  EXPECT_EQ(calibration::find_static_segments(s, {}).size(), 21u);
}

}  // namespace
}  // namespace insmc::testing
