#pragma once
/// The parallel Monte Carlo engine: samples are cut into fixed blocks of
/// kBlockSize indices; oneTBB runs blocks on any number of threads; each
/// block is drawn in bulk from the counter-based stream, pushed through the
/// study map as one matrix product and summed in index order; block sums
/// go into exactly associative totals. The result is the same bits for any
/// thread count or split of the block range.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "montecarlo/study/aggregate/horizontal_accuracy.h"
#include "montecarlo/study/aggregate/kept_samples.h"
#include "montecarlo/study/aggregate/output_stats.h"
#include "montecarlo/study/model/study_map.h"

namespace insmc::mc {

/// Statistics of every output of a study (layout order), and the kept
/// per-sample values of the outputs the layout marks (StudyLayout::kept_slot).
class StudyAccumulator {
 public:
  StudyAccumulator() = default;
  /// `keep_samples` false: no kept values (the engine's per-thread partials,
  /// whose blocks' values go straight into the run's one store).
  explicit StudyAccumulator(const StudyMap& map, bool keep_samples = true);
  void merge(const StudyAccumulator& other);
  /// The same, taking `other`'s states whole where this one has none yet.
  void merge(StudyAccumulator&& other);
  std::vector<OutputStats>& outputs() { return outputs_; }
  const std::vector<OutputStats>& outputs() const { return outputs_; }
  KeptSamples& kept() { return kept_; }
  const KeptSamples& kept() const { return kept_; }
  /// Output o's accuracy metrics (horizontal_accuracy.h) from its summary
  /// `s` at `confidence` and its kept values; none when they are not kept.
  std::optional<HorizontalAccuracy> accuracy(const StudyLayout& layout, std::size_t o, const OutputSummary& s,
                                             double confidence) const;
  std::string serialize() const;
  static StudyAccumulator deserialize(std::string_view bytes);
  friend bool operator==(const StudyAccumulator&, const StudyAccumulator&) = default;

 private:
  std::vector<OutputStats> outputs_;
  KeptSamples kept_;
};

/// Called from worker threads with the number of samples finished so far:
/// after each block, and at the truth level also after each truth sample
/// (then counting the samples of blocks still running, for display only).
using ProgressCallback = std::function<void(std::uint64_t samples_done)>;

/// Runs blocks [first_block, end_block) of the study (all blocks by default).
///
/// Cancellation: when `stop` is given and becomes true, no further block is
/// started; blocks already started are finished. Blocks are started in
/// increasing index order, so the finished blocks are always exactly
/// [first_block, *finished_end): the result is their state, and
/// *finished_end (when given) is set to end_block unless the run stopped
/// early. A checkpoint can record the cut exactly (no block lost or counted
/// twice).
StudyAccumulator run_blocks(const StudyConfig& config, const StudyMap& map, std::uint64_t first_block,
                            std::uint64_t end_block, const ProgressCallback& progress = {},
                            const std::atomic<bool>* stop = nullptr, std::uint64_t* finished_end = nullptr);

inline std::uint64_t block_count(std::uint64_t samples) { return (samples + kBlockSize - 1) / kBlockSize; }

/// The outputs of sample `index` with uncertainties x, layout order (for
/// --replay and tests): the engine's maps, pipeline and product kernel for
/// one sample, so the same bits as the sample's values in a run.
std::vector<double> evaluate_sample(const StudyConfig& config, const StudyMap& map, const StudyLayout& layout,
                                    std::uint64_t index, const UncertaintyVector& x);

}  // namespace insmc::mc
