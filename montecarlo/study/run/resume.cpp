#include "montecarlo/study/run/resume.h"

#include <fmt/format.h>

#include <stdexcept>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/common/version.h"
#include "montecarlo/study/write/study_writer.h"

namespace insmc::mc {
namespace {

/// Runs `work` on rank 0; a failure there becomes the same InputError on
/// every rank, naming `field` = `value`.
void on_root_or_fail_everywhere(Processes& processes, const std::string& field, const std::string& value,
                                const std::function<void()>& work) {
  std::string error;
  if (processes.root()) {
    try {
      work();
    } catch (const std::exception& e) {
      error = e.what();
      if (error.empty()) error = "failed";
    }
  }
  error = processes.broadcast(error);
  if (!error.empty()) throw InputError(field, value, error);
}

}  // namespace

void on_root_input_errors(Processes& processes, const std::function<void()>& checks) {
  std::string error;
  if (processes.root()) {
    try {
      checks();
    } catch (const InputError& e) {
      error = e.what();
    }
  }
  error = processes.broadcast(error);
  if (!error.empty()) throw InputError(error);
}

Checkpoint load_checkpoint(const std::string& path, Processes& processes) {
  std::string bytes;
  on_root_or_fail_everywhere(processes, "--resume", path, [&] {
    try {  // capped; a directory or a read error is an error
      bytes = read_checkpoint_file(path);
    } catch (const FileReadError& e) {
      throw std::runtime_error(e.why());  // named "--resume = PATH" by the caller
    }
  });
  return decode_checkpoint(processes.broadcast(std::move(bytes)), path);
}

StudyProgress restore_progress(const Checkpoint& checkpoint, const std::string& path, const StudyConfig& config,
                               const StudyLayout& layout, const StudyMap& map, Processes& processes) {
  if (checkpoint.fingerprint != study_fingerprint(config, map) || checkpoint.samples != config.samples)
    throw InputError("--resume", path, "the study no longer matches the checkpoint's (was its --config file changed?)");
  const std::uint64_t blocks = block_count(config.samples);
  const BlockSet& done = checkpoint.done;
  for (std::size_t i = 0; i < done.size(); ++i)
    if (done[i].end > blocks || (i > 0 && done[i].begin < done[i - 1].end))
      throw InputError("--resume", path, "the checkpoint is corrupt (finished blocks)");
  StudyProgress progress;
  progress.done = normalize(done);
  progress.state = StudyAccumulator(map);
  on_root_or_fail_everywhere(processes, "--resume", path, [&] {  // rank 0 merges the states
    try {
      progress.state = StudyAccumulator::deserialize(checkpoint.state);
    } catch (const std::exception& e) {
      throw std::runtime_error(fmt::format("the checkpoint is corrupt ({})", e.what()));
    }
    const std::uint64_t expected = sample_total(progress.done, config.samples);
    if (progress.state.outputs().size() != layout.outputs.size() ||
        (!progress.state.outputs().empty() && progress.state.outputs().front().count() != expected))
      throw std::runtime_error("the checkpoint is corrupt (its state does not match its finished blocks)");
  });
  return progress;
}

Checkpoint checkpoint_of(const StudyConfig& config, const StudyMap& map, std::vector<std::string> arguments) {
  StudyConfig settings = config;
  settings.threads = 0;  // a resumed run may use other threads, to the same bits
  Checkpoint checkpoint;
  checkpoint.version = kVersion;
  checkpoint.args = std::move(arguments);
  checkpoint.settings = settings_json(settings).dump();
  checkpoint.fingerprint = study_fingerprint(config, map);
  checkpoint.samples = config.samples;
  return checkpoint;
}

}  // namespace insmc::mc
