// The checkpoint reader's caps (decode_checkpoint) and the capped file read.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "lib/common/input_error.h"
#include "lib/common/input_text.h"
#include "lib/common/version.h"
#include "montecarlo/study/aggregate/byte_io.h"
#include "montecarlo/study/run/checkpoint.h"
#include "tests/unit/input_error_of.h"

namespace insmc::mc {
namespace {

/// A checkpoint whose argument count (or range count) is `count`, with a
/// valid checksum: the header fields, the count and nothing more.
std::string with_count(bool args, std::uint64_t count) {
  Checkpoint c;
  c.version = kVersion;
  std::string bytes = encode_checkpoint(c);
  bytes.resize(bytes.size() - 8);  // the checksum
  // Fields after the version: argc (0), settings (""), fingerprint, samples, ranges (0), state ("").
  const std::size_t argc_at = std::string("insmc checkpoint\n").size() + 4 + 8 + c.version.size();
  const std::size_t ranges_at = argc_at + 8 + 8 + 8 + 8;
  std::string patched;
  byte_io::put_u64(patched, count);
  bytes.replace(args ? argc_at : ranges_at, 8, patched);
  byte_io::put_u64(bytes, fnv1a64(bytes));
  return bytes;
}

std::string error_of(const std::string& bytes) {
  return test::input_error_of([&] { decode_checkpoint(bytes, "ck.bin"); });
}

TEST(CheckpointReader, AnEmptyCheckpointDecodes) { EXPECT_EQ(error_of(with_count(true, 0)), "(accepted)"); }

TEST(CheckpointReader, CountsBeyondTheCapsAreRefusedBeforeReading) {
  EXPECT_EQ(error_of(with_count(true, kMaxCheckpointArgs + 1)),
            fmt::format("--resume = ck.bin: the checkpoint is corrupt ({} arguments; at most {})", kMaxCheckpointArgs + 1,
                        kMaxCheckpointArgs));
  EXPECT_EQ(error_of(with_count(false, std::uint64_t{1} << 40)),
            fmt::format("--resume = ck.bin: the checkpoint is corrupt ({} block ranges; at most {})",
                        std::uint64_t{1} << 40, kMaxCheckpointRanges));
}

TEST(CheckpointReader, ThePathIsEscaped) {
  try {
    decode_checkpoint("nonsense", "ck\n.bin");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--resume = ck\\n.bin: not an insmc checkpoint file");
  }
}

TEST(CheckpointReader, ADirectoryIsAReadError) {
  EXPECT_THROW(read_checkpoint_file(std::filesystem::temp_directory_path().string()), FileReadError);
}

}  // namespace
}  // namespace insmc::mc
