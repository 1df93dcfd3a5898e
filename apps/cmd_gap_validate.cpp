// insmc gap-validate: the gap diagnosis run blind on truth-level records with
// withheld effects (docs/gap.md); exit 0 when every target holds, 1 when one
// fails (named on stderr), 2 for bad input.
#include <charconv>
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "apps/progress.h"
#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "lib/truth/effect.h"
#include "montecarlo/records/gap/validation/validation.h"

namespace insmc::app {

int cmd_gap_validate(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("quick", "the CI subset (10-run files, magnitude 30x the defaults, 4 null files)")(
      "out", po::value<std::string>(), out_folder_help(gap::validation_report_outline()).c_str())(
      "seed", po::value<std::string>()->default_value("1000"), "seed of the first simulated file")(
      "null-files", po::value<int>(), "null files (default 100, quick 4)")(
      "seeds", po::value<int>(), "files per effect and magnitude (default 3, quick 1)")(
      "effect", po::value<std::vector<std::string>>(), "validate only this effect (repeatable; names: insmc effects)")(
      "magnitudes", po::value<std::string>(), "factors on the effects' defaults, comma list (default 1,3,10,30; quick 30)")(
      "layout", po::value<std::string>()->default_value("own"),
      "own (the records as insmc simulate writes them) or foreign (each file in another recorder's conventions: "
      "f and r on grids of their own, runs of unequal length, no pulse-weight key) or fuzzed (conventions drawn at "
      "random per file: spacings 1-60 s, each run's own dropouts, resolution, short runs, header keys; "
      "docs/gap-method.md section 5)");
  const auto vm = parse_args(args, "gap-validate", "[--quick] [--out DIR]", opts);
  if (!vm) return 0;
  gap::ValidationOptions options = vm->count("quick") ? gap::ValidationOptions::quick_subset() : gap::ValidationOptions{};
  options.seed = read_count(*vm, "seed");
  if (vm->count("null-files")) options.null_files = (*vm)["null-files"].as<int>();
  if (vm->count("seeds")) options.seeds = (*vm)["seeds"].as<int>();
  if (vm->count("effect")) options.effects = (*vm)["effect"].as<std::vector<std::string>>();
  options.writer = read_record_writer(*vm);
  if (vm->count("magnitudes")) {
    const std::string text = (*vm)["magnitudes"].as<std::string>();
    options.magnitudes.clear();
    for (const std::string& item : split_commas(text)) {
      double m = 0;
      const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), m);
      if (ec != std::errc{} || end != item.data() + item.size())
        throw InputError("--magnitudes", text, "must be a comma list of factors in (0, 1000]");
      options.magnitudes.push_back(m);
    }
  }
  gap::validate(options);
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, gap::validation_report_outline());
  gap::ValidationResult r;
  {
    Progress progress(0, "files");
    options.progress = [&progress](std::string_view stage, std::uint64_t done, std::uint64_t total,
                                   std::string_view unit) { progress.update(stage, done, total, unit); };
    r = gap::validate_diagnosis(options);
  }
  write_report(gap::validation_report(r, options), {}, out, *vm);
  for (const std::string& f : r.failures) fmt::print(stderr, "gap-validate: target not met: {}\n", f);
  return r.failures.empty() ? 0 : 1;
}

}  // namespace insmc::app
