// insmc run: the Monte Carlo study. Prints a summary of the envelope
// (apps/stdout_choice.h), writes the output files of the README's contract
// into --out DIR. With --checkpoint it saves its progress
// (montecarlo/study/run/checkpoint.h) and --resume continues it; under MPI the
// ranks share the blocks (montecarlo/study/run/study_runner.h, montecarlo/study/run/join_processes.h).
#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <optional>
#include <stdexcept>

#include "apps/progress.h"
#include "apps/cli_common.h"
#include "apps/interrupt.h"
#include "apps/option_sources.h"
#include "apps/report_output.h"
#include "montecarlo/study/run/join_processes.h"
#include "apps/run_watch.h"
#include "apps/study_options.h"
#include "apps/sweep.h"
#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/units/physical_range.h"
#include "lib/units/quantity.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/run/checkpoint.h"
#include "montecarlo/study/run/resume.h"
#include "montecarlo/study/run/run_file.h"
#include "montecarlo/study/run/run_report.h"
#include "montecarlo/study/run/sample_replay.h"

namespace insmc::app {
namespace {

/// settings_json with the arguments that made the numbers (apps/option_sources.h,
/// read back by montecarlo/study/run/run_file.h).
mc::Json run_settings(const mc::StudyConfig& config, const po::variables_map& vm, const po::options_description& opts) {
  mc::Json settings = mc::settings_json(config);
  mc::Json arguments = mc::Json::array();
  for (const std::string& a : explicit_arguments(vm, opts, not_in_run_files())) arguments.push_back(a);
  settings["arguments"] = arguments;
  return settings;
}

/// The options a --resume command line may give; every other setting comes
/// from the checkpoint.
const std::vector<std::string> kResumeOptions = {"--out",     "--format",     "--quiet",           "--full",
                                                 "--threads", "--checkpoint", "--checkpoint-every"};

/// --resume restores every setting: only --out, --format, ... may be given beside it.
void refuse_options_beside_resume(const Args& args, const po::options_description& opts, const std::string& resume_path) {
  for (const GivenOption& o : given_options(args, opts))
    if (o.name != "resume" && std::find(kResumeOptions.begin(), kResumeOptions.end(), "--" + o.name) == kResumeOptions.end())
      throw InputError("--resume", resume_path,
                       fmt::format("the checkpoint restores every setting; --{} cannot be given with it (only {} can)",
                                   o.name, mc::listed(kResumeOptions)));
}

/// A sweep: each point's study split over the processes, then sweep.csv,
/// sweep.md, sweep.json and the figure, and the summary on stdout.
int run_sweep_points(const po::variables_map& vm, const mc::StudyConfig& config, const std::vector<SweepAxis>& sweeps,
                     const std::string& checkpoint_path, const mc::Json& settings, const StdoutChoice& shown,
                     mc::LengthUnit unit, std::optional<OutputFolderOption>& out, mc::Processes& processes) {
  if (vm.count("replay")) throw InputError("--replay", vm["replay"].as<std::string>(), "cannot be combined with a sweep");
  if (!checkpoint_path.empty())
    throw InputError("--checkpoint", checkpoint_path,
                     "cannot be combined with a sweep (checkpoint the points as separate runs)");
  // Each point's blocks are split over the ranks (one rank without MPI).
  const auto sweep_start = std::chrono::steady_clock::now();
  std::uint64_t points_total = 1, points_done = 0;
  for (const SweepAxis& a : sweeps) points_total *= a.texts.size();
  std::optional<Progress> points_progress;
  if (processes.root()) {
    points_progress.emplace(points_total, "points");
    points_progress->update("sweep", 0, points_total, "points");
  }
  mc::SweepFiles files =
      mc::run_sweep(config, sweeps, unit, [&](const mc::StudyConfig& c, const mc::StudyMap& m) {
        mc::RunPlan plan;
        plan.result_everywhere = true;
        mc::StudyAccumulator state =
            run_study_watched(c, m, processes, mc::StudyProgress{{}, mc::StudyAccumulator(m)}, plan, false)
                .progress.state;
        // The sweep's own count (a point's samples have their own line while it runs).
        if (points_progress) points_progress->update("sweep", ++points_done, points_total, "points");
        return state;
      });
  points_progress.reset();
  if (!processes.root()) return 0;
  mc::SweepFacts facts;
  facts.points = points_total;
  for (const SweepAxis& a : sweeps) facts.swept.push_back(mc::quantity_name(a.column));
  facts.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep_start).count();
  write_report(mc::sweep_report(config, std::move(files), settings, facts, unit), shown, out, vm);
  return 0;
}

/// --replay's INDEX: a sample of the study.
std::uint64_t replay_index(const std::string& text, std::uint64_t samples) {
  std::uint64_t index = 0;
  try {
    std::size_t used = 0;
    index = std::stoull(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw InputError("--replay", text, "must be a sample index, 0 <= INDEX < --samples");
  }
  if (index >= samples) throw InputError("--replay", text, fmt::format("must be below --samples = {}", samples));
  return index;
}

/// run.json: the settings, the time, where a resumed run started, the
/// run's options: its outputs, --replay, checkpoints, --resume, --from,
/// and the study's.
po::options_description run_options() {
  po::options_description opts("Options");
  opts.add_options()("out", po::value<std::string>(), (out_folder_help(mc::envelope_report_outline()) + "; a sweep writes " +
                                                       mc::sweep_report_outline().set_text())
                                                          .c_str())(
      "format", po::value<std::string>()->default_value("markdown"),
      "stdout: markdown (horizontal RMS per scheme and system), csv (envelope.csv alone) or json (run.json alone)")(
      "replay", po::value<std::string>(), "recompute sample INDEX alone and print its uncertainties and errors")(
      "checkpoint", po::value<std::string>(),
      "write FILE (every setting and the merged state of the finished samples) every --checkpoint-every of work, "
      "at the end (the file is kept) and on SIGINT/SIGTERM, which then exit 130/143")(
      "checkpoint-every", po::value<std::string>()->default_value("10s"), "work between two checkpoints, in [10ms, 24h]")(
      "resume", po::value<std::string>(),
      "continue the run of checkpoint FILE to the same result, byte for byte; no other option is needed, and only "
      "--out, --format, --quiet, --full, --threads, --checkpoint (default FILE) and --checkpoint-every may be given")(
      "from", po::value<std::string>(),
      "run again the run of DIR/run.json (its settings.arguments), to the same files byte for byte (run.json's "
      "elapsed_s aside); options given here replace the file's");
  add_stdout_switches(opts, "the RMS of every axis at every report time");
  opts.add(study_options_description(true));
  return opts;
}

int run_command(const Args& args, mc::Processes& processes) {
  const po::options_description opts = run_options();
  const std::string synopsis = "[options]\n       insmc run --resume FILE [--out DIR] [--format F]";
  auto vm = parse_args(args, "run", synopsis, opts, Lists::kSweeps);
  if (!vm) return 0;
  // The files this command line reads (the --from or --resume file is gone
  // from the options once they are rebuilt from it): no output may be one.
  std::vector<InputFile> inputs = input_files(*vm);

  // --from: the options a run.json kept (values by name, each checked as
  // every file of options is: apps/option_sources.h), under this command
  // line's.
  if (vm->count("from")) {
    const std::string from = (*vm)["from"].as<std::string>();
    if (vm->count("resume"))
      throw InputError("--from", echo_input(from), "cannot be given with --resume (a checkpoint restores its own run)");
    const po::parsed_options kept =
        run_file_options(mc::read_run_arguments(from), opts, "--from", from, "settings.arguments");
    vm = parse_args_with_file(args, "from", kept, opts);
  }

  // --resume: the options the checkpoint kept, checked likewise, under this
  // command line's --out, --format, ...
  std::optional<mc::Checkpoint> resumed;
  const std::string resume_path = vm->count("resume") ? (*vm)["resume"].as<std::string>() : "";
  if (vm->count("resume")) {
    refuse_options_beside_resume(args, opts, resume_path);
    resumed = mc::load_checkpoint(resume_path, processes);
    const po::parsed_options kept =
        run_file_options(resumed->args, opts, "--resume", resume_path, "the checkpoint's arguments");
    std::vector<po::option> added;
    if (!vm->count("checkpoint")) added.emplace_back("checkpoint", std::vector<std::string>{resume_path});
    vm = parse_args_with_file(args, "resume", kept, opts, added);
  }

  const mc::StudyConfig config = read_study_config(*vm, true);
  // Now, before any work: an option run.json cannot keep fails here rather
  // than after a finished study.
  const mc::Json settings = run_settings(config, *vm, opts);
  const StdoutChoice shown = read_stdout_choice(*vm, mc::envelope_report_outline());  // a sweep's offers the same
  const mc::LengthUnit unit = read_length_unit(*vm);
  const std::string checkpoint_path = vm->count("checkpoint") ? (*vm)["checkpoint"].as<std::string>() : "";
  const std::string every_text = (*vm)["checkpoint-every"].as<std::string>();
  const double checkpoint_every_s = parse_quantity(every_text, Dimension::kTime, "--checkpoint-every");
  // From 10 ms (each checkpoint is written atomically; tests use 0.1 s) to a day.
  require_in_range("--checkpoint-every", checkpoint_every_s, Dimension::kTime, {0.01, 24 * 3600.0});
  const std::vector<SweepAxis> sweeps = find_sweeps(*vm);
  mc::check_sweep_points(config, sweeps);  // every value of every list, before any work
  // Every output path is checked and locked now, before any work: a path
  // the user can fix costs no computing (docs/outputs.md).
  std::optional<OutputFolderOption> out;
  std::optional<OutputFileOption> checkpoint_file;
  if (!vm->count("replay")) {
    mc::on_root_input_errors(processes, [&] {
      for (InputFile& in : input_files(*vm)) inputs.push_back(std::move(in));
      out = prepare_report_folder(*vm, sweeps.empty() ? mc::envelope_report_outline() : mc::sweep_report_outline(),
                                  inputs);
      if (!checkpoint_path.empty() && sweeps.empty()) checkpoint_file.emplace("--checkpoint", checkpoint_path, inputs);
    });
  }
  if (!sweeps.empty()) return run_sweep_points(*vm, config, sweeps, checkpoint_path, settings, shown, unit, out, processes);
  const mc::StudyLayout layout = mc::make_layout(config);
  const mc::StudyMap map(config, layout);

  if (vm->count("replay")) {
    const std::string text = (*vm)["replay"].as<std::string>();
    if (!checkpoint_path.empty()) throw InputError("--checkpoint", checkpoint_path, "cannot be combined with --replay");
    if (shown.quiet) throw InputError("--replay", text, "prints one sample: cannot be combined with --quiet");
    const std::uint64_t index = replay_index(text, config.samples);
    if (processes.root()) {
      std::optional<OutputFolderOption> no_set;
      write_report(mc::replay_report(config, layout, map, index), {}, no_set, *vm);
    }
    return 0;
  }

  mc::StudyProgress start{{}, mc::StudyAccumulator(map)};
  if (resumed) start = mc::restore_progress(*resumed, resume_path, config, layout, map, processes);
  const std::uint64_t resumed_from_sample = mc::sample_total(start.done, config.samples);
  mc::RunPlan plan;
  bool stop_on_signals = false;  // SIGINT/SIGTERM: a checkpoint, then exit
  if (!checkpoint_path.empty()) {
    // What defines the study, as run.json keeps it.
    mc::Checkpoint ck = mc::checkpoint_of(config, map, explicit_arguments(*vm, opts, not_in_run_files()));
    plan.checkpoint_every_s = checkpoint_every_s;
    stop_on_signals = true;
    plan.write_checkpoint = [ck = std::move(ck), &checkpoint_file](const mc::StudyProgress& p) mutable {
      ck.done = p.done;
      ck.state = p.state.serialize();
      checkpoint_file->write(mc::encode_checkpoint(ck));
    };
    // A path that cannot be written fails now, not after the first stretch of work.
    mc::on_root_input_errors(processes, [&] { plan.write_checkpoint(start); });
  }

  const auto started = std::chrono::steady_clock::now();
  const mc::RunOutcome outcome = run_study_watched(config, map, processes, std::move(start), plan, stop_on_signals);
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (outcome.signal != 0) {
    if (processes.root())
      fmt::print(stderr, "insmc run: interrupted by {}: checkpoint {} written ({} of {} samples finished); continue "
                         "with: insmc run --resume {}{}\n",
                 signal_name(outcome.signal), checkpoint_path, mc::sample_total(outcome.progress.done, config.samples),
                 config.samples, checkpoint_path,
                 vm->count("out") ? " --out " + (*vm)["out"].as<std::string>() : std::string());
    processes.barrier();  // every rank exits after rank 0 has written and said so
    return 128 + outcome.signal;
  }
  if (!processes.root()) return 0;
  const mc::StudyAccumulator& acc = outcome.progress.state;

  mc::RunFacts facts{settings, elapsed_s, resumed_from_sample, processes.distributed() ? processes.size() : 0, outcome.shares};
  write_report(mc::envelope_report(config, mc::render_envelope(config, layout, map, acc, unit), facts), shown, out, *vm);
  return 0;
}

}  // namespace

int cmd_run(const Args& args) {
  const std::unique_ptr<mc::Processes> processes = mc::join_processes();
  if (!processes->distributed()) return run_command(args, *processes);
  // Under MPI every rank parses the same arguments, so bad input fails on
  // every rank alike: rank 0 reports it, before MPI_Finalize (mpirun may end
  // the job once a rank has exited non-zero), and every rank exits 2.
  try {
    return run_command(args, *processes);
  } catch (const InputError& e) {
    if (processes->root()) fmt::print(stderr, "insmc run: {}\n", e.what());
    return 2;
  } catch (const po::error& e) {
    if (processes->root()) fmt::print(stderr, "insmc run: {} (see insmc run --help)\n", parse_error_message(e));
    return 2;
  } catch (const std::exception& e) {  // the other ranks may be waiting for this one: end them all
    fmt::print(stderr, "insmc run: error on rank {}: {}\n", processes->rank(), e.what());
    processes->abort(3);
    return 3;
  }
}

}  // namespace insmc::app
