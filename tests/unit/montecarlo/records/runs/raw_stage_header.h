#pragma once
// A record header with the raw-sensor stage's keys (runs/records/raw_stage.h),
// every gyro and every accelerometer at one fitted noise.
#include <string>

#include "lib/records/record.h"

namespace insmc::runs::testing {

inline RecordHeader header_with(double gyro_equivalent_radps, double accel_equivalent_mps2) {
  RecordHeader h = RecordHeader::make(51.0, System::kTheodolite, 900.0, Scheme::kNone);
  h.set("imu.noise", std::string("on"));
  for (const char* c : {"gyro_x", "gyro_y", "gyro_z"}) h.set(std::string("imu.noise.") + c + ".equivalent_si", gyro_equivalent_radps);
  for (const char* c : {"accel_x", "accel_y", "accel_z"})
    h.set(std::string("imu.noise.") + c + ".equivalent_si", accel_equivalent_mps2);
  h.set("imu.noise.gyro_z.warm_up_excluded", 1.0);
  return h;
}

}  // namespace insmc::runs::testing
