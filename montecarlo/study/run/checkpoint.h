#pragma once
/// The checkpoint file of `insmc run --checkpoint FILE`: every setting of
/// the run (its options as `--name=value`, each checked by name on --resume
/// as every file of options is: apps/option_sources.h) and the merged
/// aggregator state of the finished blocks. Written atomically
/// (montecarlo/report/atomic_file.h), so a reader sees the previous
/// checkpoint or the new one, never a mix.
///
/// Layout (little-endian; str = u64 length + bytes):
///   "insmc checkpoint\n", u32 format (kCheckpointFormat), str version,
///   u64 argc, argc × str, str settings (JSON, for people), u64 fingerprint,
///   u64 samples, u64 ranges, ranges × (u64 begin, u64 end) finished blocks,
///   str accumulator state, u64 checksum of everything before it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "montecarlo/study/engine/block_ranges.h"
#include "montecarlo/study/model/study_map.h"

namespace insmc::mc {

inline constexpr std::uint32_t kCheckpointFormat = 2;  // 2: the arguments define the study only (no --out)

/// Caps of the reader. The state is a few sums and the filled bins of one
/// histogram per output (montecarlo/study/aggregate/output_stats.h: 12 bytes a
/// filled bin, at most 4097 bins, ~49 KB): a run with the time grid (49
/// times × 7 schemes × 2 systems × 4 axes) holds at most ~135 MB, a
/// 2-sample run a few hundred KB; 1 GiB leaves seven times the most. A command
/// line has tens of arguments; a run's finished blocks merge into a few
/// ranges (one per rank and interruption).
inline constexpr std::uint64_t kMaxCheckpointFileBytes = std::uint64_t{1} << 30;
inline constexpr std::uint64_t kMaxCheckpointArgs = 10'000;
inline constexpr std::uint64_t kMaxCheckpointRanges = 1'000'000;

struct Checkpoint {
  std::string version;            ///< the insmc that wrote it; --resume needs the same
  std::vector<std::string> args;  ///< the run's arguments without --checkpoint and --resume
  std::string settings;           ///< settings JSON of the run, threads 0 (for people)
  std::uint64_t fingerprint = 0;  ///< of the settings and the study's outputs (checked on resume)
  std::uint64_t samples = 0;
  BlockSet done;                  ///< finished blocks
  std::string state;              ///< StudyAccumulator::serialize(), merged over `done`
};

std::string encode_checkpoint(const Checkpoint& checkpoint);

/// Throws InputError naming `path` and what is wrong: not a checkpoint,
/// another format or program version, truncated or corrupt (checksum), more
/// arguments or ranges than the caps above.
Checkpoint decode_checkpoint(std::string_view bytes, const std::string& path);

/// The bytes of checkpoint file `path`, at most kMaxCheckpointFileBytes; a
/// directory, an unreadable file or a read error is an InputError. A file
/// that does not start with the magic line is not read past it (its first
/// bytes are returned, which decode_checkpoint refuses): `--resume
/// /dev/zero` holds 17 bytes, not the cap.
std::string read_checkpoint_file(const std::string& path);

/// Of the settings (threads aside) and of every output's predicted mean and
/// RMS: a resumed run must compute exactly the study it continues.
std::uint64_t study_fingerprint(const StudyConfig& config, const StudyMap& map);

/// 64-bit FNV-1a over the bytes (the checksum and fingerprint: detects
/// corruption, not tampering).
std::uint64_t fnv1a64(std::string_view bytes);

}  // namespace insmc::mc
