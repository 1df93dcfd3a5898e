// The strapdown import path against closed forms: a perfect stationary IMU
// navigates without error; a horizontal accelerometer bias step gives the
// Schuler response; a gyro drift gives the tilt-driven position error of a
// hand derivation; alignment recovers tilt, heading and gyro bias.
#include "tests/unit/input_error_of.h"
#include "lib/imu/strapdown.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "tests/unit/lib/imu/synthetic_imu.h"

namespace insmc {
namespace {

using testing::perfect_outputs;
using testing::synthetic_samples;
using testing::SyntheticSite;
using testing::PerfectOutputs;

// A perfect IMU leaves only the integrator's error: first-order rotation
// compensation drops (ωh)²/6 ≈ 1e-11 of f at 10 Hz, quaternion round-off
// ~1e-16 per step; both stay far below these bounds over 105 min.
constexpr double kPerfectPositionTolM = 1.0;       // 1 m over 105 min
constexpr double kPerfectForceTolMps2 = 1e-8;      // 1 ng: "tiny"
constexpr double kClosedFormRelTol = 0.01;         // 1 % of the closed form

StrapdownOptions options_for(const SyntheticSite& s) {
  StrapdownOptions o;
  o.latitude_rad = s.latitude_rad;
  o.altitude_m = s.altitude_m;
  o.azimuth_rad = s.heading_rad;
  return o;  // 300 s + 15 min + 90 min, τ = 10 s
}

double max_norm(const std::vector<Vec3>& v) {
  double m = 0.0;
  for (const Vec3& x : v) m = std::max(m, x.norm());
  return m;
}

TEST(ImuStrapdown, PerfectImuFromCsvNavigatesWithoutError) {
  SyntheticSite site;
  site.latitude_rad = 51.08 * kDegToRad;
  site.altitude_m = 1100.0;
  site.heading_rad = 30.0 * kDegToRad;
  site.pitch_rad = -1.5 * kDegToRad;
  site.roll_rad = 2.0 * kDegToRad;
  const StrapdownOptions o = options_for(site);
  const double rate_hz = 10.0;
  const ImuSamples made = synthetic_samples(site, rate_hz, o.run_duration_s());
  const auto path = std::filesystem::temp_directory_path() / "insmc_strapdown_perfect.csv";
  {
    std::ofstream out(path);
    out << testing::samples_csv(made, "wx,wy,wz,ax,ay,az");
  }
  ImuCsvOptions csv;
  csv.gyro_columns = {"wx", "wy", "wz"};
  csv.accel_columns = {"ax", "ay", "az"};
  csv.gyro_unit = GyroUnit::kRadPerS;
  csv.accel_unit = AccelUnit::kMps2;
  csv.rate_hz = rate_hz;
  const ImuSamples read = read_imu_csv(path, csv);
  std::filesystem::remove(path);
  ASSERT_EQ(read.size(), made.size());

  const StrapdownRun run = run_strapdown(read, 0.0, o);
  ASSERT_EQ(run.t_s.size(), 630u);  // 105 min every 10 s
  EXPECT_DOUBLE_EQ(run.t_s.back(), 6300.0);
  EXPECT_DOUBLE_EQ(run.switch_time_s, 300.0);
  EXPECT_NEAR(run.alignment.roll_rad, site.roll_rad, 1e-12);
  EXPECT_NEAR(run.alignment.pitch_rad, site.pitch_rad, 1e-12);
  EXPECT_LT(run.alignment.gyro_bias_b_radps.norm(), 1e-15);
  EXPECT_NEAR(run.alignment.mean_accel_b_mps2.norm(), perfect_outputs(site).gravity_mps2, 1e-12);
  const double r_max = max_norm(run.position_error_ap_m), f_max = max_norm(run.accel_error_ap_mps2);
  EXPECT_LT(r_max, kPerfectPositionTolM);
  EXPECT_LT(f_max, kPerfectForceTolMps2);
  RecordProperty("max_position_error_m", std::to_string(r_max));
  RecordProperty("max_accel_error_mps2", std::to_string(f_max));
}

TEST(ImuStrapdown, GyroBiasIsEstimatedAndRemoved) {
  SyntheticSite site;
  site.heading_rad = -120.0 * kDegToRad;
  site.pitch_rad = 0.5 * kDegToRad;
  const Vec3 bias(4e-3, -7e-3, 5e-3);  // ADIS-sized turn-on biases, rad/s
  const StrapdownOptions o = options_for(site);
  const ImuSamples s = synthetic_samples(site, 10.0, o.run_duration_s(),
                                         [&](double, Vec3& w, Vec3&) { w += bias; });
  const StrapdownRun run = run_strapdown(s, 0.0, o);
  EXPECT_LT((run.alignment.gyro_bias_b_radps - bias).norm(), 1e-15);
  EXPECT_LT(max_norm(run.position_error_ap_m), kPerfectPositionTolM);
}

// Forcing of a constant bias b^n fixed in the body (body fixed to the earth):
// in a' it is C_n^{a'}(t) b^n = (I + B(t)) b^n with B of (3.5):
// B = −(1 − cos Ωt) P − sin(Ωt) Q, so the forcing is
// (I − P) b + cos(Ωt) P b − sin(Ωt) Q b. The position error obeys
// δr̈ = −ω_s² δr + forcing (3.21 linear in δr, zero initial error), whose
// response to 1, cos Ωt, sin Ωt from rest is (1 − cos ω_s t)/ω_s²,
// (cos Ωt − cos ω_s t)/(ω_s² − Ω²), (sin Ωt − (Ω/ω_s) sin ω_s t)/(ω_s² − Ω²).
Vec3 schuler_response_to_body_bias(const Vec3& b_n, double latitude_rad, double t) {
  const double sL = std::sin(latitude_rad), cL = std::cos(latitude_rad);
  Mat3 P, Q;
  P << sL * sL, 0, sL * cL, 0, 1, 0, sL * cL, 0, cL * cL;
  Q << 0, -sL, 0, sL, 0, cL, 0, -cL, 0;
  const double ws = schuler_frequency_radps(), W = kEarthRateRadps;
  const double d = ws * ws - W * W;
  const Vec3 constant = (Mat3::Identity() - P) * b_n, cosine = P * b_n, sine = -(Q * b_n);
  return constant * (1.0 - std::cos(ws * t)) / (ws * ws) + cosine * (std::cos(W * t) - std::cos(ws * t)) / d +
         sine * (std::sin(W * t) - W / ws * std::sin(ws * t)) / d;
}

TEST(ImuStrapdown, AccelerometerBiasStepGivesTheSchulerResponse) {
  SyntheticSite site;  // level, sensor x north: b^b = b^n
  const double b = 1e-3 * kGravityMps2;  // 1 mg on the north accelerometer from t = 0
  StrapdownOptions o = options_for(site);
  const ImuSamples s = synthetic_samples(site, 10.0, o.run_duration_s(), [&](double t, Vec3&, Vec3& f) {
    if (t >= o.align_duration_s) f.x() += b;
  });
  const StrapdownRun run = run_strapdown(s, 0.0, o);
  double peak = 0.0;
  for (double t : run.t_s) peak = std::max(peak, schuler_response_to_body_bias(Vec3(b, 0, 0), site.latitude_rad, t).norm());
  const double ws = schuler_frequency_radps();
  for (std::size_t k = 0; k < run.t_s.size(); ++k) {
    const double t = run.t_s[k];
    const Vec3 expected = schuler_response_to_body_bias(Vec3(b, 0, 0), site.latitude_rad, t);
    EXPECT_LT((run.position_error_ap_m[k] - expected).norm(), kClosedFormRelTol * peak) << "t = " << t;
    if (t <= o.test_duration_s) {
      // The plain b (1 − cos ω_s t)/ω_s² on the north axis: the earth's turn
      // changes the north forcing by sin²L (1 − cos Ωt) < 0.2% within T.
      const double plain = b * (1.0 - std::cos(ws * t)) / (ws * ws);
      EXPECT_NEAR(run.position_error_ap_m[k].x(), plain, kClosedFormRelTol * plain) << "t = " << t;
      // Δf^a is the bias itself (turned by < 1 mrad·(Ωt)), sign and size.
      EXPECT_NEAR(run.accel_error_ap_mps2[k].x(), b, kClosedFormRelTol * b) << "t = " << t;
    }
  }
  // The closed form is met far inside 1%: the integration is exact to round-off.
  const double at_84min = run.position_error_ap_m[503].x();  // t = 5040 s
  EXPECT_NEAR(at_84min, schuler_response_to_body_bias(Vec3(b, 0, 0), site.latitude_rad, 5040.0).x(), 1e-3);
}

// Gyro drift ε about the north axis (sensor x, level) with the bias kept:
// the computed platform turns by θ = ε t about north relative to a', so the
// measured up-force −g e_z appears in â as R_x(εt)(0, 0, −g) ≈ (0, g ε t, −g):
// an east acceleration error g ε t, hence δr_y = g ε t³/6 to first order
// (positive: east), before the Schuler feedback −ω_s² δr bends it to
// g ε (t − sin(ω_s t)/ω_s)/ω_s². Neglected: (ω_s t)²/20 in the plain form
// (0.7% at 300 s) and terms of order (Ω t)² from the earth's turn of ε and f.
TEST(ImuStrapdown, KeptGyroDriftTiltsThePlatformAsDerived) {
  SyntheticSite site;
  const double eps = 1e-5;  // rad/s ≈ 2.1 deg/h
  StrapdownOptions o = options_for(site);
  o.gyro_bias = GyroBiasMode::kKeep;
  const ImuSamples s = synthetic_samples(site, 10.0, o.run_duration_s(), [&](double, Vec3& w, Vec3&) { w.x() += eps; });
  const StrapdownRun run = run_strapdown(s, 0.0, o);
  EXPECT_NEAR(run.alignment.gyro_bias_b_radps.x(), eps, 1e-15);  // estimated, reported, not removed
  const double g = perfect_outputs(site).gravity_mps2, ws = schuler_frequency_radps();
  for (std::size_t k = 0; k < run.t_s.size(); ++k) {
    const double t = run.t_s[k];
    const double r_y = run.position_error_ap_m[k].y();
    if (t <= 300.0) {
      const double cubic = g * eps * t * t * t / 6.0;
      EXPECT_GT(r_y, 0.0) << "t = " << t;
      EXPECT_NEAR(r_y, cubic, kClosedFormRelTol * cubic) << "t = " << t;
    }
    if (t <= o.test_duration_s) {
      const double schuler = g * eps * (t - std::sin(ws * t) / ws) / (ws * ws);
      EXPECT_NEAR(r_y, schuler, kClosedFormRelTol * schuler) << "t = " << t;
      // Δf_y = g ε t, the tilt times g (the filter mean lags by τ/2).
      EXPECT_NEAR(run.accel_error_ap_mps2[k].y(), g * eps * (t - 0.5 * o.output_interval_s),
                  kClosedFormRelTol * g * eps * t) << "t = " << t;
    }
  }
}

TEST(ImuStrapdown, SplitCutsConsecutiveRunsAndRefusesShortData) {
  SyntheticSite site;
  StrapdownOptions o = options_for(site);
  o.align_duration_s = 20.0;
  o.test_duration_s = 60.0;
  o.nav_duration_s = 120.0;
  const ImuSamples s = synthetic_samples(site, 10.0, 2.5 * o.run_duration_s());
  EXPECT_EQ(runs_available(s, o), 2);
  const StrapdownRun second = run_strapdown(s, o.run_duration_s(), o);
  EXPECT_DOUBLE_EQ(second.switch_time_s, o.run_duration_s() + o.align_duration_s);
  EXPECT_LT(max_norm(second.position_error_ap_m), 1e-3);
  try {
    run_strapdown(s, 2.0 * o.run_duration_s(), o);
    FAIL() << "a run past the end of the data must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("synthetic: the samples cover 500 s"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--nav-duration"), std::string::npos) << e.what();
  }
}

TEST(ImuStrapdown, TheTestRunEndsExactlyOnTheOutputGrid) {
  SyntheticSite site;
  StrapdownOptions o = options_for(site);
  o.align_duration_s = 1.0;
  o.test_duration_s = 0.3;  // 3 × 0.1 = 0.30000000000000004 in doubles
  o.nav_duration_s = 0.2;
  o.output_interval_s = 0.1;
  const StrapdownRun run = run_strapdown(synthetic_samples(site, 100.0, o.run_duration_s()), 0.0, o);
  ASSERT_EQ(run.t_s.size(), 5u);
  EXPECT_EQ(run.t_s[2], 0.3);
  EXPECT_GT(run.t_s[3], 0.3);
}

TEST(ImuStrapdown, AlignmentRefusesWhatNoStationaryImuMeasures) {
  SyntheticSite site;
  StrapdownOptions o = options_for(site);
  const StationarySite st = stationary_site(o);
  const PerfectOutputs p = perfect_outputs(site);
  EXPECT_THROW(align_stationary(p.accel_b_mps2 * kGravityMps2, p.gyro_b_radps, 1, o, st, "f"), InputError);
  EXPECT_THROW(align_stationary(p.accel_b_mps2, Vec3(1.0, 0, 0), 1, o, st, "f"), InputError);
  // Sensor x pointing up: heading undefined.
  EXPECT_THROW(align_stationary(Vec3(-kGravityMps2, 0, 0), p.gyro_b_radps, 1, o, st, "f"), InputError);
  // The site: f^n points up with |f| = g − ω²r cos²L (approximately).
  EXPECT_NEAR(st.specific_force_n_mps2.x(), 0.0, 1e-12);
  EXPECT_NEAR(st.specific_force_n_mps2.y(), 0.0, 1e-12);
  EXPECT_NEAR(st.gravity_mps2, -st.specific_force_n_mps2.z(), 1e-12);
  EXPECT_NEAR(st.gravity_mps2, kGravityMps2 - kEarthRateRadps * kEarthRateRadps * kEarthRadiusM * 0.5, 1e-4);
}

TEST(ImuStrapdown, OptionsAreValidated) {
  StrapdownOptions o;
  EXPECT_FALSE(test::thrown_by([&] { validate(o); }).has_value());
  o.output_interval_s = 0.0;
  ASSERT_TRUE(test::thrown_by([&] { validate(o); }).has_value());
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "--interval");
  o = StrapdownOptions{};
  o.latitude_rad = 0.5 * std::numbers::pi;
  ASSERT_TRUE(test::thrown_by([&] { validate(o); }).has_value());
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "--latitude");
  o = StrapdownOptions{};
  o.nav_duration_s = -1.0;
  EXPECT_EQ(test::thrown_by([&] { validate(o); })->field(), "--nav-duration");
  EXPECT_EQ(parse_gyro_bias_mode("keep", "--gyro-bias"), GyroBiasMode::kKeep);
  EXPECT_THROW(parse_gyro_bias_mode("drop", "--gyro-bias"), InputError);
}

}  // namespace
}  // namespace insmc
