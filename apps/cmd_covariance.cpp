// insmc covariance: the exact linear-covariance RMS of every output
// (S(t) P S(t)ᵀ plus the squared mean) and the error budget. Prints a
// summary (apps/stdout_choice.h); the files hold every output.
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "montecarlo/study/write/covariance_report.h"

namespace insmc::app {
namespace {

/// The covariance is exact and linear: no samples, no intervals, no
/// time-domain alignment. An option that would change nothing is refused
/// rather than accepted and ignored.
void refuse_unused_options(const po::variables_map& vm) {
  refuse_truth_level_options(vm, "covariance",
                             "covariance is the linear model's exact covariance: paper or linear (the truth level "
                             "needs samples: insmc run --fidelity truth)");
  if (!vm["confidence"].defaulted())
    throw InputError("--confidence", fmt::format("{}", vm["confidence"].as<double>()),
                     "not used by covariance (exact: no samples, no intervals); use insmc run");
}

}  // namespace

int cmd_covariance(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("out", po::value<std::string>(), out_folder_help(mc::covariance_report_outline()).c_str())(
      "format", po::value<std::string>()->default_value("markdown"),
      "stdout: markdown (horizontal RMS per scheme and system), csv (covariance.csv alone) or json");
  add_stdout_switches(opts, "covariance.md (the RMS of every axis at every report time)");
  opts.add(study_options_description(false));
  const auto vm = parse_args(args, "covariance", "[options]", opts);
  if (!vm) return 0;
  refuse_unused_options(*vm);
  const mc::StudyConfig config = read_study_config(*vm, false);
  const StdoutChoice shown = read_stdout_choice(*vm, mc::covariance_report_outline());
  const mc::LengthUnit unit = read_length_unit(*vm);
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, mc::covariance_report_outline());
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);
  write_report(mc::covariance_report(config, layout, map, unit), shown, out, *vm);
  return 0;
}

}  // namespace insmc::app
