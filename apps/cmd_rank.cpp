// insmc rank: the compensation schemes in order of their horizontal RMS, per
// system and report time, with the significance of each adjacent pair's
// order (paired Monte Carlo on the same samples), and the values of the
// decisive assumptions at which the first place changes (the covariance
// level, exact). Writes ranking.csv, breakeven.csv, rank.md, rank.json and
// rank.gp/.svg/.png (montecarlo/study/rank/).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/cli_common.h"
#include "apps/progress.h"
#include "apps/report_output.h"
#include "apps/study_options.h"
#include "apps/sweep.h"
#include "lib/common/input_error.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/rank/rank_files.h"

namespace insmc::app {
namespace {

/// The break-even points need the covariance level, and one study: an option
/// that would change nothing is refused rather than ignored (a sweep is, by
/// parse_args).
void refuse_unused_options(const po::variables_map& vm) {
  refuse_truth_level_options(vm, "rank",
                             "rank needs the exact covariance of its level for the break-even points: paper or linear");
}

}  // namespace

int cmd_rank(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("out", po::value<std::string>(), out_folder_help(mc::rank_report_outline()).c_str())(
      "format", po::value<std::string>()->default_value("markdown"),
      "stdout: markdown (the order and the first place's limits at the last report time), csv (ranking.csv "
      "alone) or json (rank.json alone)");
  add_stdout_switches(opts, "rank.md (every report time)");
  opts.add(study_options_description(true));
  const auto vm = parse_args(args, "rank", "[options]", opts);
  if (!vm) return 0;
  refuse_unused_options(*vm);
  mc::StudyConfig config = read_study_config(*vm, true);
  const mc::LengthUnit unit = read_length_unit(*vm);
  const StdoutChoice shown = read_stdout_choice(*vm, mc::rank_report_outline());
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, mc::rank_report_outline());
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);
  mc::BreakEven even;
  std::vector<mc::SchemeOrder> orders;
  {
    Progress progress(0, "");
    progress.update("Monte Carlo study", 0, config.samples, "samples");
    const mc::StudyAccumulator state =
        mc::run_blocks(config, map, 0, mc::block_count(config.samples), [&progress, &config](std::uint64_t done) {
          progress.update("Monte Carlo study", done, config.samples, "samples");
        });
    orders = mc::order_schemes(config, layout, state);
    even = mc::break_even(config, 40 * 60.0,
                          [&progress](std::string_view stage, std::uint64_t done, std::uint64_t total) {
                            progress.update(stage, done, total, "study maps");
                          });
  }
  write_report(mc::rank_report(config, orders, even, unit), shown, out, *vm);
  return 0;
}

}  // namespace insmc::app
