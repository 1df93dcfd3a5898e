#pragma once
/// Compensation (chapter 5) applied to the error model through the
/// injection points of fig. 5.1, and the resulting position error as a
/// linear map of the extended vector z (extended_vector.h):
///   point 2    a step added to the accelerometer signals (a frame ≈ a′);
///   integrators into point 2: a ramp;
///   point 4    gyro torquer rates: drift angles growing from the time applied;
///   points 5, 6 velocity and position integrators reset at T to the values
///              the computer calculates for a stationary vehicle;
///   realignment a new alignment with fresh ζ_r, ∂f_r, (u)V (and any torquer
///              compensation already active), then a new switch-over.
/// Each scheme adds its own terms (schemes/); this file holds what the
/// traits switch on: the realignment's fresh draws, the resets at T and the
/// torquer response.
/// The residual is what propagating the compensated model gives; the
/// report's printed residual matrices are only used to check it (tests).
#include <vector>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/compensation/extended_vector.h"
#include "lib/compensation/scheme.h"
#include "lib/compensation/schemes/scheme_definition.h"
#include "lib/preflight/test_run.h"

namespace insmc {

struct SchemeMaps {
  /// δr^{a'} at each requested time on the scheme's clock (clock_of).
  std::vector<ExtendedMap> position;
  /// Time since the switch-over of the a′ frame the errors are expressed in,
  /// at t = 0 on the scheme's clock (T for 5.2/5.3, else 0): the
  /// horizontal component uses the local-level frame at that time + t.
  double frame_time_offset_s = 0.0;
  /// From the first switch-over until the vehicle may fly (T plus the
  /// realignment where there is one; 0 for none and 5.4).
  double ready_time_s = 0.0;
};

SchemeMaps scheme_position_maps(Scheme scheme, System system, Fidelity fidelity, const ModelOptions& model,
                                const TestRunOptions& test, const std::vector<double>& clock_times_s,
                                SchemeForms paper_forms = SchemeForms::kPrinted);

}  // namespace insmc
