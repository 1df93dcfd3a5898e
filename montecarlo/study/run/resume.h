#pragma once
/// A run continued from its checkpoint (`insmc run --resume FILE`) and the
/// checkpoint a run writes: the file read on rank 0 and sent to the others
/// (no shared file system needed), checked against the study it claims to
/// be, and its finished blocks and merged state restored.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "montecarlo/study/model/study_config.h"
#include "montecarlo/study/model/study_map.h"
#include "montecarlo/study/run/checkpoint.h"
#include "montecarlo/study/run/processes.h"
#include "montecarlo/study/run/study_runner.h"

namespace insmc::mc {

/// Runs `checks` (the command's checks of its output paths) on rank 0; an
/// InputError there becomes the same one-line error on every rank (the
/// others would otherwise wait for rank 0 in the next collective).
void on_root_input_errors(Processes& processes, const std::function<void()>& checks);

/// The checkpoint at `path`, read on rank 0 and broadcast; a file that
/// cannot be read or decoded is an InputError naming --resume on every rank.
Checkpoint load_checkpoint(const std::string& path, Processes& processes);

/// The finished blocks and the merged state of `checkpoint`, on every rank
/// (the state on rank 0, which merges): an InputError naming --resume when
/// the study no longer matches the checkpoint's or the file is corrupt.
StudyProgress restore_progress(const Checkpoint& checkpoint, const std::string& path, const StudyConfig& config,
                               const StudyLayout& layout, const StudyMap& map, Processes& processes);

/// What every checkpoint of this study holds besides its progress: the
/// version, the arguments that define the study (as run.json keeps them),
/// its settings without the thread count, its fingerprint and samples.
Checkpoint checkpoint_of(const StudyConfig& config, const StudyMap& map, std::vector<std::string> arguments);

}  // namespace insmc::mc
