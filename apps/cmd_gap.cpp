// insmc gap: the sim-to-real gap diagnosis of record files (docs/records.md,
// docs/gap.md): the gap and its significance, where it lies, which candidate
// effect removes it on held-out runs, and how far it shrinks.
#include <fmt/format.h>

#include "apps/cli_common.h"
#include "apps/report_output.h"
#include "apps/progress.h"
#include "apps/study_options.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/records/record_io.h"
#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/records/gap/report/report.h"
#include "montecarlo/records/runs/files/merge_records.h"

namespace insmc::app {

int cmd_gap(const Args& args) {
  po::options_description opts("Options");
  opts.add_options()("records", po::value<std::vector<std::string>>()->composing(),
                     "record file (format v1), repeatable; all of one site")(
      "out", po::value<std::string>(), out_folder_help(gap::diagnosis_report_outline()).c_str())(
      "format", po::value<std::string>()->default_value("markdown"), "what to print: markdown or json")(
      "alpha", po::value<double>()->default_value(0.01), "false-alarm rate of a significant gap, [1e-4, 0.5)")(
      "seed", po::value<std::string>()->default_value("1"), "seed of the null runs and the resampling")(
      "calibration-runs", po::value<int>()->default_value(0), "null runs (0: max(200, 10 x runs))")(
      "max-effects", po::value<int>()->default_value(3), "effects added greedily at most, >= 1")(
      "likelihood", po::value<int>()->default_value(0),
      "also fit the best N candidates by maximum likelihood between physical limits, with profile intervals and "
      "held-out log-likelihood gains, in [0, 15] (experimental: docs/gap-method.md section 4)")(
      "likelihood-pairs", po::value<int>()->default_value(0),
      "of those, pair the best N and fit each pair jointly, in [0, 5]")(
      "rank", po::value<std::string>()->default_value("always"),
      "fit and rank the candidate effects: always, significant (only when the gap is), never (screening: the gap, "
      "its significance and where it lies)");
  opts.add(uncertainty_options_description());
  const auto vm = parse_args(args, "gap", "--records FILE [--records FILE...] [--out DIR] [--format json]", opts);
  if (!vm) return 0;
  if (!vm->count("records")) throw InputError("--records", "(missing)", "give at least one record file");
  const mc::ReportOutline outline = gap::diagnosis_report_outline();
  const mc::ReportFormat format = read_report_format(*vm, outline);
  gap::DiagnosisOptions options;
  options.alpha = (*vm)["alpha"].as<double>();
  options.bootstrap = gap::null_files_for(options.alpha);
  options.seed = read_count(*vm, "seed");
  options.calibration_runs = (*vm)["calibration-runs"].as<int>();
  options.max_selected = (*vm)["max-effects"].as<int>();
  options.likelihood_candidates = (*vm)["likelihood"].as<int>();
  options.likelihood_pair_candidates = (*vm)["likelihood-pairs"].as<int>();
  const std::string rank = (*vm)["rank"].as<std::string>();
  if (rank == "always") options.rank = gap::RankWhen::kAlways;
  else if (rank == "significant") options.rank = gap::RankWhen::kIfSignificant;
  else if (rank == "never") options.rank = gap::RankWhen::kNever;
  else throw InputError("--rank", echo_input(rank), "always, significant or never");
  options.prior = read_uncertainty_model(*vm);
  gap::validate(options);
  std::optional<OutputFolderOption> out = prepare_report_folder(*vm, outline);

  const std::vector<std::string> names = (*vm)["records"].as<std::vector<std::string>>();
  std::vector<RecordFile> files;
  std::size_t runs = 0, rows = 0;
  for (const std::string& name : names) {
    files.push_back(without_truth(read_input("--records", name, [&] { return read_record_file(name); })));
    runs += files.back().runs.size();
    for (const RecordRun& run : files.back().runs) rows += run.rows.size();
    if (runs > gap::kMaxDiagnosedRuns || rows > kMaxRecordRows)
      throw InputError("--records", echo_input(name, 256),
                       fmt::format("{} runs and {} rows up to this file: the files of one diagnosis may hold at most "
                                   "{} runs and {} rows in all",
                                   runs, rows, gap::kMaxDiagnosedRuns, kMaxRecordRows));
  }
  const RecordFile merged = runs::merge_record_files(files, names);
  gap::Diagnosis d;
  {
    Progress progress(0, "");
    options.progress = [&progress](std::string_view stage, std::uint64_t done, std::uint64_t total,
                                   std::string_view unit) { progress.update(stage, done, total, unit); };
    d = gap::diagnose(merged, options);
  }

  write_report(gap::diagnosis_report(d, names), {format}, out, *vm);
  return 0;
}

}  // namespace insmc::app
