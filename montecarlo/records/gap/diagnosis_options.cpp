#include "montecarlo/records/gap/diagnosis_options.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <string>

#include "lib/common/input_error.h"

namespace insmc::gap {

void validate(const DiagnosisOptions& options) {
  if (!(options.alpha >= kMinAlpha && options.alpha < 0.5))
    throw InputError("--alpha", fmt::format("{}", options.alpha),
                     fmt::format("must lie in [{:g}, 0.5): a smaller false-alarm rate rests on the null files' tail "
                                 "beyond the calibration runs",
                                 kMinAlpha));
  if ((options.bootstrap + 1) * options.alpha < 2.0)
    throw InputError("--alpha", fmt::format("{}", options.alpha),
                     fmt::format("needs at least {:.0f} null files; with {} the least p-value is {:.2g}",
                                 std::ceil(2.0 / options.alpha - 1.0), options.bootstrap,
                                 1.0 / (options.bootstrap + 1)));
  if (options.calibration_runs < 0 || options.calibration_runs > 100000)
    throw InputError("--calibration-runs", std::to_string(options.calibration_runs), "must lie in [0, 100000]");
  if (options.calibration_runs > 0 && options.calibration_runs < 50)
    throw InputError("--calibration-runs", std::to_string(options.calibration_runs), "use 0 (automatic) or >= 50");
  if (options.max_selected < 1 || options.max_selected > 5)
    throw InputError("--max-effects", std::to_string(options.max_selected), "must lie in [1, 5]");
  if (options.likelihood_candidates < 0 || options.likelihood_candidates > 15)
    throw InputError("--likelihood", std::to_string(options.likelihood_candidates), "must lie in [0, 15]");
  if (options.likelihood_pair_candidates < 0 || options.likelihood_pair_candidates > 5 ||
      options.likelihood_pair_candidates > options.likelihood_candidates)
    throw InputError("--likelihood-pairs", std::to_string(options.likelihood_pair_candidates),
                     "must lie in [0, 5] and not exceed --likelihood");
}

int null_files_for(double alpha) {
  if (!(alpha >= kMinAlpha)) return DiagnosisOptions{}.bootstrap;  // refused by validate
  return std::max(DiagnosisOptions{}.bootstrap, static_cast<int>(std::ceil(10.0 / alpha - 1.0)));
}

}  // namespace insmc::gap
