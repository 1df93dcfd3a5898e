#pragma once
/// The per-sample values of a few outputs (the horizontal radial error at
/// the report times), kept for the quantiles that sums cannot give
/// (order_statistics.h; docs/outputs.md, "Accuracy metrics").
///
/// Kept: the samples of the first `kept_blocks` blocks (the first
/// kept_blocks · kBlockSize sample indices), at most kMaxKeptValues values
/// over all kept outputs. Samples are i.i.d. by index, so this prefix is a
/// fair sample of the study; its quantile intervals are computed for its own
/// count.
///
/// Storage is dense and preallocated, block-major: block b's values of kept
/// output s are at ((b · outputs + s) · kBlockSize). A block is written once,
/// by whichever thread or process computed it; merging copies the blocks
/// the other state holds. Unwritten entries stay 0, so the state, and its
/// serialization (of a fixed size, as the MPI reduction needs), are the same
/// bits for any split of the blocks.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace insmc::mc {

/// 2^24 values (64 MiB as float): 399,360 samples (390 blocks) for each of
/// the 42 horizontal report rows of the default study.
inline constexpr std::uint64_t kMaxKeptValues = std::uint64_t{1} << 24;

class KeptSamples {
 public:
  /// Keeps nothing (the merge identity; the engine's per-thread partials).
  KeptSamples() = default;
  /// `outputs` kept outputs of a study of `samples` samples.
  KeptSamples(std::uint64_t outputs, std::uint64_t samples);

  std::uint64_t outputs() const { return outputs_; }
  /// Blocks kept: min(block count, kMaxKeptValues / (outputs · kBlockSize)), at least 1.
  std::uint64_t kept_blocks() const { return kept_blocks_; }
  bool keeps(std::uint64_t block) const { return block < kept_blocks_; }

  /// The place for block b's n values of kept output s (b < kept_blocks()).
  /// Distinct blocks are distinct memory: threads may fill them concurrently.
  float* slot(std::uint64_t block, std::uint64_t output);
  /// Marks block b as filled for every kept output.
  void mark_filled(std::uint64_t block) { filled_[block] = 1; }

  /// Copies the blocks `other` filled (each block filled at most once over
  /// all states merged). An empty state on either side is the identity.
  void merge(const KeptSamples& other);

  /// Kept output s's values of the filled blocks (as many as were kept).
  std::vector<float> values(std::uint64_t output) const;

  void append_to(std::string& out) const;
  static KeptSamples read_from(std::string_view bytes, std::size_t& pos);

  friend bool operator==(const KeptSamples&, const KeptSamples&) = default;

 private:
  std::uint64_t block_values(std::uint64_t block) const;

  std::uint64_t outputs_ = 0, samples_ = 0, kept_blocks_ = 0;
  std::vector<std::uint8_t> filled_;  // per kept block
  std::vector<float> values_;         // kept_blocks · outputs · kBlockSize
};

}  // namespace insmc::mc
