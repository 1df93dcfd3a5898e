#include "montecarlo/engine/engine.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "montecarlo/random/philox.h"
#include "montecarlo/sampler/sampler.h"

namespace insmc::mc {
namespace {

constexpr int kRowsPerMap = 5;

/// Per-thread buffers, sized once: nothing is allocated per sample.
struct Workspace {
  explicit Workspace(int rows)
      : uniforms(kBlockSize * ux::kDim), x(ux::kDim, kBlockSize), y(kBlockSize, rows), h(kBlockSize) {}
  std::vector<double> uniforms;
  Eigen::MatrixXd x;  // kDim × block, one column per sample
  Eigen::MatrixXd y;  // block × rows, one column per map row
  std::vector<double> h;
};

void run_block(const StudyConfig& c, const StudyMap& map, const Sampler& sampler, std::uint64_t block,
               Workspace& ws, StudyAccumulator& acc) {
  const std::uint64_t first = block * kBlockSize;
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kBlockSize, c.samples - first));
  fill_uniform01(c.seed, Stream::Uncertainties, first, ux::kDim, n,
                 std::span<double>(ws.uniforms.data(), n * ux::kDim));
  sampler.transform(ws.uniforms.data(), n, ws.x.data());
  const Eigen::Index ni = static_cast<Eigen::Index>(n);
  ws.y.topRows(ni).noalias() = ws.x.leftCols(ni).transpose() * map.transposed();
  auto& outs = acc.outputs();
  for (std::size_t o = 0; o < outs.size(); ++o) {
    const int base = kRowsPerMap * static_cast<int>(o / 4);
    const int axis = static_cast<int>(o % 4);
    if (axis < 3) {
      outs[o].add_block(ws.y.col(base + axis).data(), n);
    } else {
      const double* north = ws.y.col(base + 3).data();
      const double* east = ws.y.col(base + 4).data();
      for (std::size_t s = 0; s < n; ++s) ws.h[s] = std::sqrt(north[s] * north[s] + east[s] * east[s]);
      outs[o].add_block(ws.h.data(), n);
    }
  }
}

}  // namespace

StudyAccumulator::StudyAccumulator(const StudyMap& map) {
  const auto& mean = map.predicted_mean();
  const auto& rms = map.predicted_rms();
  outputs_.reserve(mean.size());
  for (size_t o = 0; o < mean.size(); ++o) outputs_.emplace_back(mean[o], rms[o]);
}

void StudyAccumulator::merge(const StudyAccumulator& other) {
  if (outputs_.empty()) {
    *this = other;
    return;
  }
  for (size_t o = 0; o < outputs_.size(); ++o) outputs_[o].merge(other.outputs_[o]);
}

std::string StudyAccumulator::serialize() const {
  std::string out = "insmc-acc1";
  const std::uint64_t n = outputs_.size();
  for (int b = 0; b < 8; ++b) out.push_back(static_cast<char>((n >> (8 * b)) & 0xff));
  for (const auto& s : outputs_) s.append_to(out);
  return out;
}

StudyAccumulator StudyAccumulator::deserialize(std::string_view bytes) {
  if (bytes.substr(0, 10) != "insmc-acc1") throw std::runtime_error("not an insmc accumulator state");
  std::size_t pos = 10;
  if (bytes.size() < pos + 8) throw std::runtime_error("accumulator state truncated");
  std::uint64_t n = 0;
  for (int b = 0; b < 8; ++b) n |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[pos++])) << (8 * b);
  StudyAccumulator acc;
  for (std::uint64_t o = 0; o < n; ++o) acc.outputs_.push_back(OutputStats::read_from(bytes, pos));
  if (pos != bytes.size()) throw std::runtime_error("accumulator state has trailing bytes");
  return acc;
}

StudyAccumulator run_blocks(const StudyConfig& c, const StudyMap& map, std::uint64_t first_block,
                            std::uint64_t end_block, const ProgressCallback& progress) {
  const int threads = c.threads > 0 ? c.threads
                                    : static_cast<int>(tbb::info::default_concurrency());
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  const Sampler sampler(c.uncertainties);
  const StudyAccumulator empty(map);
  tbb::enumerable_thread_specific<StudyAccumulator> partial(empty);
  tbb::enumerable_thread_specific<Workspace> workspaces(map.rows());
  std::atomic<std::uint64_t> done{0};
  tbb::parallel_for(tbb::blocked_range<std::uint64_t>(first_block, end_block, 1),
                    [&](const tbb::blocked_range<std::uint64_t>& range) {
                      Workspace& ws = workspaces.local();
                      StudyAccumulator& acc = partial.local();
                      for (std::uint64_t b = range.begin(); b != range.end(); ++b) {
                        run_block(c, map, sampler, b, ws, acc);
                        const std::uint64_t n = std::min<std::uint64_t>(kBlockSize, c.samples - b * kBlockSize);
                        const std::uint64_t total = done.fetch_add(n) + n;
                        if (progress) progress(total);
                      }
                    });
  // Exact, associative and commutative merge: the order does not matter.
  StudyAccumulator total = empty;
  for (const StudyAccumulator& p : partial) total.merge(p);
  return total;
}

std::vector<double> evaluate_sample(const StudyConfig&, const StudyMap& map, const StudyLayout& layout,
                                    const UncertaintyVector& x) {
  const Eigen::VectorXd rows = map.transposed().transpose() * x;
  std::vector<double> out;
  for (size_t o = 0; o < layout.outputs.size(); ++o)
    out.push_back(StudyMap::output_value(rows.data() + kRowsPerMap * static_cast<int>(o / 4), layout.outputs[o].axis));
  return out;
}

}  // namespace insmc::mc
