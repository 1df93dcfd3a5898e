#pragma once
/// One definition per candidate, one file each in this folder, named as the
/// truth simulator's effect it stands for (lib/truth/effects/), plus the
/// model-level `bounds` and `nonlinearity`; registry.cpp lists them.
#include "montecarlo/gap/candidates/candidates.h"

namespace insmc::gap::candidates {

Candidate bounds();
Candidate quantization();
Candidate sway();
Candidate accel_bias_instability();
Candidate gyro_drift_instability();
Candidate angle_random_walk();
Candidate velocity_random_walk();
Candidate thermal_transient();
Candidate anisoelastic_drift();
Candidate scale_factor_nonlinearity();
Candidate deflection_of_vertical();
Candidate gravity_model();
Candidate alignment_transient();
Candidate switch_transient();
Candidate nonlinearity();

}  // namespace insmc::gap::candidates
