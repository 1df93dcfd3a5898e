// The break-even values of montecarlo/study/rank/break_even.h are solved
// from polynomials in the assumption (A + C b² for a bound, quadratic in
// the random fraction F). Checked against the study map evaluated directly
// on either side of each crossing: the leader and the challenger swap
// there. The step, a millionth of the value, is far above the round-off of
// a root of exact evaluations and far below the distance between crossings.
#include "montecarlo/study/rank/break_even.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace insmc::mc {
namespace {

std::size_t index_of(const std::vector<Scheme>& schemes, Scheme s) {
  return static_cast<std::size_t>(std::find(schemes.begin(), schemes.end(), s) - schemes.begin());
}

TEST(BreakEven, TheLeaderAndTheChallengerSwapOnEitherSideOfEachCrossing) {
  StudyConfig config;
  config.systems = {System::kTheodolite};
  const BreakEven b = break_even(config, 10 * 60.0);
  int checked = 0;
  for (const Crossing& x : b.crossings) {
    if (x.assumption == Assumption::kTestDuration) continue;  // found on whole filter intervals, not a root
    const double at_study = study_value(config, x.assumption);
    if (!std::isfinite(at_study) || x.value_si <= 0 || x.value_si == at_study) continue;
    const auto k = static_cast<std::size_t>(
        std::find(config.report_times_s.begin(), config.report_times_s.end(), x.t_s) - config.report_times_s.begin());
    ASSERT_LT(k, config.report_times_s.size()) << x.t_s;
    const std::size_t leader = index_of(config.schemes, x.leader), challenger = index_of(config.schemes, x.challenger);
    // On the study's side of the crossing the leader is ahead of the challenger; beyond it, behind.
    const double toward_study = at_study < x.value_si ? -1.0 : 1.0;
    for (const double side : {toward_study, -toward_study}) {
      double value = x.value_si * (1.0 + 1e-6 * side);
      if (x.assumption == Assumption::kRandomFraction) value = std::clamp(value, 0.0, 1.0);
      const RmsTable rms = predicted_horizontal_rms(with_assumption(config, x.assumption, value));
      const double r_leader = rms[0][k][leader], r_challenger = rms[0][k][challenger];
      if (side == toward_study)
        EXPECT_LT(r_leader, r_challenger) << to_string(x.assumption) << " at " << value << ", t " << x.t_s;
      else
        EXPECT_GT(r_leader, r_challenger) << to_string(x.assumption) << " at " << value << ", t " << x.t_s;
    }
    ++checked;
  }
  EXPECT_GE(checked, 1) << "no crossing of a bound or of F to check";
}

}  // namespace
}  // namespace insmc::mc
