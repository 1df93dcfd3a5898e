#pragma once
/// What a record's header may leave out and its rows still show: the ΔV
/// pulse weight of `f` and the resolution of `r` (docs/gap.md "What the
/// diagnosis reads"). A counted output lies on a lattice: the computer's
/// velocity is w N(t) (§4.3), so over one filter window the velocity it
/// counts, f_k τ plus the nominal specific force's increment of a stationary
/// vehicle (what the counters count besides the errors), is a whole number
/// of pulses; a position computer of resolution q reads out the true
/// position plus r on the lattice q ℤ. Continuous outputs lie on no lattice.
#include <vector>

#include "lib/common/model_options.h"
#include "lib/records/record.h"

namespace insmc::runs {

struct LatticeFit {
  /// kLattice: every value is a whole multiple of `step`; kContinuous: no
  /// step from `finest_tried` up fits; kUndecided: too few values to say.
  enum class Kind { kLattice, kContinuous, kUndecided };
  Kind kind = Kind::kUndecided;
  double step = 0.0;           ///< the lattice step (least squares over the values)
  int values = 0;              ///< values tested
  int distinct_multiples = 0;  ///< distinct whole multiples seen (kLattice)
  double finest_tried = 0.0;   ///< the finest step tried (kContinuous)
  double coarsest_tried = 0.0;
};

/// The pulse weight of the test-run f rows: each run's consecutive f rows
/// (at most 2τ apart) give u_k − u_{k−1}, u_k = f_k τ + ∫ f̂ over the window
/// (nominal_velocity_increment, test_run.h); where those fit no lattice, the
/// second differences u_k − 2u_{k−1} + u_{k−2}, which cancel the leftover of
/// the site's specific force against the nominal's g (past 1 % of a pulse
/// for windows from about 20-30 s).
LatticeFit f_pulse_lattice(const RecordFile& file, const ModelOptions& model, double filter_interval_s);

/// The position resolution: each run's test-run r rows less its
/// first, each plus the true position in a′ (true_position_ap) less the
/// first's.
LatticeFit r_resolution_lattice(const RecordFile& file, const ModelOptions& model);

}  // namespace insmc::runs
