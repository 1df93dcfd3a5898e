#pragma once
/// A hand-written fixed-step integrator of the truth simulator's equations
/// (lib/truth/simulator.h) for the case `insmc run --fidelity truth` runs:
/// no effects, spherical gravitation, no torquer command. Same state
/// (platform quaternion C_a^i, the navigation error δr, δv in i, the
/// accelerometer pulse accumulators), same RK4 steps landing on the same
/// stops, same pulse-remainder integral — but no options validation, no
/// effects registry, no std::function or virtual calls, and everything that
/// does not depend on the sample computed once. It is the floor the `truth`
/// path is timed against (docs/performance.md: truth within 2× of it) and nothing else:
/// the library's simulator remains the truth level.
#include <vector>

#include "lib/common/model_options.h"
#include "lib/common/system.h"
#include "lib/frames/frames.h"
#include "lib/uncertainty/uncertainty_vector.h"

namespace insmc::mc {

class TruthReference {
 public:
  /// Sample-independent constants of one system. output_times_s ascend from
  /// 0; the integration also stops at t − τ for each output t (as the
  /// simulator does for its filter-interval records), so the steps are the
  /// simulator's.
  TruthReference(const ModelOptions& model, System system, double dv_pulse_mps, double filter_interval_s,
                 std::vector<double> output_times_s, double step_s = 5.0);

  /// δr^{a'} = r_c − r in a' at each output time [m] for the uncertainties
  /// x and the pulse phase (in pulses, [−0.5, 0.5) per axis);
  /// position_error_ap_m has one entry per output time.
  void run(const UncertaintyVector& x, const Vec3& pulse_phase, Vec3* position_error_ap_m) const;

  std::size_t outputs() const { return output_stop_.size(); }

 private:
  ModelOptions model_;
  double dv_pulse_mps_, step_s_;
  std::vector<double> stops_s_;          // 0, outputs and t − τ, ascending
  std::vector<std::size_t> output_stop_;  // stop index of each output
  Sensitivity3 misalignment_map_;        // C' = M x (2.18a), with the site's g_s
  Vec3 site_position_e_m_, reference_gravitation_e_mps2_, centripetal_e_mps2_;
  double site_gravity_mps2_ = 0.0;       // g_s = |f| at the site
  Mat3 c_e_n_, c_i_ap_;
};

}  // namespace insmc::mc
