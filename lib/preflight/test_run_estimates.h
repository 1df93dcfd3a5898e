#pragma once
/// What the preflight test run revealed: the estimates a compensation
/// scheme uses.
#include "lib/frames/frames.h"

namespace insmc {

struct TestRunEstimates {
  Vec3 u2 = Vec3::Zero();        ///< Û2 from position data (4.8b)
  Vec3 u3 = Vec3::Zero();        ///< Û3 from position data (4.8c)
  Vec3 u3_accel = Vec3::Zero();  ///< Û3 from the accelerometer data, slope of (5.12)
  Vec3 df_at_test_end_mps2 = Vec3::Zero();  ///< filtered Δf̂(T) (5.10)
};

}  // namespace insmc
