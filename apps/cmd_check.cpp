// insmc check --bounds FILE: statistical bounds for users' CI. Runs the study
// the bounds need and exits 1 naming every bound that the one-sided upper
// confidence limit of its metric exceeds (montecarlo/study/check/bounds_check.h),
// 0 when all hold, 2 for a malformed file.
#include <algorithm>
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "montecarlo/study/check/bounds_check.h"

namespace insmc::app {

int cmd_check(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("bounds", po::value<std::string>(),
                     "file of bounds, one a line: scheme=none system=2 axis=horizontal t_min=84 "
                     "rms_m<=9000 [confidence=0.95, one-sided, in [0.5, 0.999999]]; also rms_ft, rms_nmi, rms<=5nmi, and on "
                     "axis=horizontal cep50_m<=N, cep95_m<=N (or p95_m) and 2drms_m<=N; # comments");
  opts.add(study_options_description(true));
  const auto vm = parse_args(args, "check", "--bounds FILE [study options]", opts);
  if (!vm) return 0;
  if (!vm->count("bounds")) throw InputError("--bounds", "(missing)", "give the file of bounds to check");
  const std::string bounds_path = (*vm)["bounds"].as<std::string>();
  const std::vector<mc::Bound> bounds =
      read_input("--bounds", bounds_path, [&] { return mc::read_bounds_file(bounds_path); });
  const mc::StudyConfig study = read_study_config(*vm, true);
  const std::optional<mc::LengthUnit> units =
      (*vm)["units"].defaulted() ? std::nullopt : std::optional<mc::LengthUnit>(read_length_unit(*vm));
  const mc::StudyConfig config = mc::config_for_bounds(study, bounds);
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);
  const mc::StudyAccumulator acc = mc::run_blocks(config, map, 0, mc::block_count(config.samples));
  const std::vector<mc::BoundVerdict> verdicts = mc::judge_bounds(bounds, config, layout, acc);
  std::optional<OutputFolderOption> no_set;
  write_report(mc::check_report(verdicts, units), {}, no_set, *vm);
  const auto violated = std::count_if(verdicts.begin(), verdicts.end(), [](const auto& v) { return !v.holds; });
  if (violated) fmt::print(stderr, "insmc check: {} of {} bounds violated\n", violated, bounds.size());
  return violated ? 1 : 0;
}

}  // namespace insmc::app
