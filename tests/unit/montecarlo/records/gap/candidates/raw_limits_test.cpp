// The candidates limited by the raw-sensor stage, and the raw stage
// compared with the navigation-level ranking.
#include "montecarlo/records/gap/candidates/raw_limits.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "lib/noise/noise_budget.h"
#include "lib/units/quantity_display.h"
#include "tests/unit/montecarlo/records/runs/raw_stage_header.h"

namespace insmc::gap {
namespace {

using runs::testing::header_with;
using runs::raw_stage_from_header;

TEST(RawStage, SaysWhenTheTopCandidateIsOfTheOtherSensor) {
  const double gyro_bound = noise::table31_bound_si(noise::SensorKind::kGyro);
  const auto raw = raw_stage_from_header(header_with(200 * gyro_bound, 1e-6));
  ASSERT_TRUE(raw);
  EXPECT_EQ(raw_stage_statements(*raw, "gyro_drift_instability").size(), 1u);
  const auto disagree = raw_stage_statements(*raw, "accel_bias_instability|velocity_random_walk");
  ASSERT_EQ(disagree.size(), 2u);
  EXPECT_NE(disagree[1].find("disagree"), std::string::npos);
  EXPECT_NE(disagree[0].find("warm-up"), std::string::npos);
  EXPECT_EQ(raw_stage_statements(*raw, "sway").size(), 1u);  // neither sensor: nothing to compare
  EXPECT_EQ(sensor_of_effect("angle_random_walk|gyro_drift_instability"), "gyro");
  EXPECT_EQ(sensor_of_effect("angle_random_walk|accel_bias_instability"), "");
}

TEST(RawStage, LimitsTheNoiseCandidatesToWhatTheRawOutputsAllow) {
  RecordHeader h = header_with(1e-6, 1e-4);
  // Gyro x: white noise selected (its interval's upper end), no wander term:
  // the Allan bound stands in. Accelerometers: only bounds.
  h.set("imu.noise.gyro_x.angle_random_walk_upper_si", 2e-6);
  for (const char* c : {"gyro_x", "gyro_y", "gyro_z"}) h.set(std::string("imu.noise.") + c + ".wander_bound_si", 3e-7);
  for (const char* c : {"accel_x", "accel_y", "accel_z"}) {
    h.set(std::string("imu.noise.") + c + ".white_1h_bound_si", 0.02);
    h.set(std::string("imu.noise.") + c + ".wander_bound_si", 5e-5);
  }
  const auto raw = raw_stage_from_header(h);
  ASSERT_TRUE(raw);
  std::vector<std::string> statements;
  const auto limited = limit_candidates(gap::candidate_registry(), *raw, statements);
  EXPECT_EQ(statements.size(), 4u);
  auto cap_of = [&](const std::string& name, const std::string& parameter) {
    for (const gap::Candidate& c : limited)
      if (c.name == name)
        for (const gap::CandidateParameter& p : c.parameters)
          if (p.name == parameter) return p.grid.back();
    return -1.0;
  };
  EXPECT_NEAR(cap_of("angle_random_walk", "angle_1h"), 2e-6 * 60, 1e-15);
  EXPECT_NEAR(cap_of("gyro_drift_instability", "sigma"), 3e-7, 1e-18);
  EXPECT_NEAR(cap_of("velocity_random_walk", "velocity_1h"), 0.02, 1e-15);
  EXPECT_NEAR(cap_of("accel_bias_instability", "sigma"), 5e-5, 1e-15);
  // Each limit is stated in its unit (the quantity's display unit), not as "SI".
  for (const std::string& s : statements) EXPECT_EQ(s.find("SI"), std::string::npos) << s;
  const auto stated = [&](double si, Dimension d) {
    const std::string text = format_quantity_rounded(si, d);
    return std::any_of(statements.begin(), statements.end(),
                       [&](const std::string& s) { return s.find("raw outputs' " + text + " (") != std::string::npos; });
  };
  EXPECT_TRUE(stated(0.02, Dimension::kVelocity));
  EXPECT_TRUE(stated(5e-5, Dimension::kAcceleration));
  // Every other candidate is the registry's.
  EXPECT_EQ(limited.size(), gap::candidate_registry().size());
  for (std::size_t i = 0; i < limited.size(); ++i) {
    if (limited[i].name == "sway") {
      EXPECT_EQ(limited[i].parameters[0].grid, gap::candidate_registry()[i].parameters[0].grid);
    }
  }
}

}  // namespace
}  // namespace insmc::gap
