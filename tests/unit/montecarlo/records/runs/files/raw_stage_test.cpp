// The raw-sensor stage's keys in a record header, read back.
#include "montecarlo/records/runs/files/raw_stage.h"

#include <gtest/gtest.h>

#include "lib/noise/noise_budget.h"
#include "tests/unit/montecarlo/records/runs/raw_stage_header.h"

namespace insmc::runs {
namespace {

using testing::header_with;

TEST(RawStage, ReadsTheRatiosToTable31) {
  const double gyro_bound = noise::table31_bound_si(noise::SensorKind::kGyro);
  const double accel_bound = noise::table31_bound_si(noise::SensorKind::kAccelerometer);
  const auto raw = raw_stage_from_header(header_with(200 * gyro_bound, 3 * accel_bound));
  ASSERT_TRUE(raw);
  EXPECT_EQ(raw->channels.size(), 6u);
  EXPECT_NEAR(raw->gyro_ratio, 200, 1e-9);
  EXPECT_NEAR(raw->accel_ratio, 3, 1e-9);
  EXPECT_TRUE(raw->channels[2].warm_up_excluded);
  EXPECT_FALSE(raw_stage_from_header(RecordHeader::make(51.0, System::kTheodolite, 900.0, Scheme::kNone)));
}

}  // namespace
}  // namespace insmc::runs
