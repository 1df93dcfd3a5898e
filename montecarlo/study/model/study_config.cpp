#include "montecarlo/study/model/study_config.h"

#include <cmath>
#include <fmt/format.h>

#include "lib/common/input_error.h"
#include "lib/truth/simulator.h"
#include "lib/units/units.h"

namespace insmc::mc {

void validate(const StudyConfig& c) {
  if (c.systems.empty()) throw InputError("--system", "(none)", "select system 1, 2 or 1,2");
  if (c.schemes.empty()) throw InputError("--scheme", "(none)", "select at least one scheme");
  if (c.samples < 2 || c.samples > kMaxSamples)
    throw InputError("--samples", fmt::format("{}", c.samples), fmt::format("must lie in [2, {}]", kMaxSamples));
  require_in_range("--confidence", c.confidence, Dimension::kDimensionless, kConfidenceRange);
  if (c.threads < 0 || c.threads > kMaxThreads)
    throw InputError("--threads", fmt::format("{}", c.threads), fmt::format("must lie in [0, {}] (0 = all cores)", kMaxThreads));
  if (!(c.grid_step_s > 0) || !std::isfinite(c.grid_step_s))
    throw InputError("--grid-step", fmt::format("{}s", c.grid_step_s), "must be > 0");
  if (!(c.grid_end_s > 0) || !std::isfinite(c.grid_end_s) || c.grid_end_s > 6 * 3600.0)
    throw InputError("--grid-end", fmt::format("{}s", c.grid_end_s), "must lie in (0, 6h]");
  if (c.grid_end_s / c.grid_step_s > 10000)
    throw InputError("--grid-step", fmt::format("{}s", c.grid_step_s), "gives more than 10000 grid points");
  bool uses_system2 = false;
  for (System s : c.systems) uses_system2 |= s == System::kGyrocompass;
  if (uses_system2 && !(std::abs(c.model.latitude_rad) < M_PI / 2 - 1e-9))
    throw InputError("--latitude", fmt::format("{}rad", c.model.latitude_rad),
                     "must lie strictly between -90deg and 90deg for system 2 (2.16 divides by cos L0)");
  // Every latitude, one value or a sweep's point (point_config validates
  // each), meets the single value's check (apps/cli_common.cpp) whatever the systems.
  if (!(std::abs(c.model.latitude_rad) <= 90.0 * kDegToRad))
    throw InputError("--latitude", fmt::format("{:.12g}deg", c.model.latitude_rad / kDegToRad), "must lie within ±90deg");
  if (c.fidelity == Fidelity::kTruth)
    if (const auto err = truth_latitude_error(c.model.latitude_rad, "--latitude")) throw *err;
  if (c.test.alignment_loops && c.fidelity != Fidelity::kTruth)
    throw InputError("--alignment-time", fmt::format("{}s", c.test.alignment_loops->duration_s),
                     "the time-domain alignment is simulated at the truth level only: add --fidelity truth or use steady");
  validate(c.test);
  if (c.test.intervals() > kMaxStudyIntervals)
    throw InputError("--filter-interval", format_quantity(c.test.filter_interval_s, Dimension::kTime),
                     fmt::format("gives {} intervals in the test run of a study; allowed: 4 to {}",
                                 c.test.intervals(), kMaxStudyIntervals));
  for (int i = 0; i < uncertainty_slot::kDim; ++i) {
    const auto& p = c.uncertainties.at(i);
    require_in_range(fmt::format("--bound {}", catalogue()[i].name), p.bound_si, catalogue()[i].dimension,
                     bound_range(catalogue()[i]));
  }
}

}  // namespace insmc::mc
