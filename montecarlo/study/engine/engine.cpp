#include "montecarlo/study/engine/engine.h"

#include "montecarlo/study/aggregate/accumulator_state.h"

#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <cmath>
#include <stdexcept>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "lib/common/assert.h"
#include "lib/propagation/position_maps.h"
#include "lib/compensation/truth_compensation.h"
#include "montecarlo/study/kernels/map_product.h"
#include "montecarlo/study/random/philox.h"
#include "montecarlo/study/sampler/sampler.h"
#include "montecarlo/study/sampler/truth_sample.h"

namespace insmc::mc {
namespace {

/// Per-thread buffers, sized once: nothing is allocated per sample.
struct Workspace {
  Workspace(const StudyMap& map, int n_systems)
      : uniforms(kBlockSize * uncertainty_slot::kDim),
        x_by_draw(kBlockSize * uncertainty_slot::kDim),
        x(uncertainty_slot::kDim, kBlockSize),
        z_by_draw(kBlockSize, z_slot::kDim),
        h(kBlockSize) {
    for (int j = 0; j < n_systems; ++j) y.emplace_back(kBlockSize, map.transposed(j).cols());
  }
  std::vector<double> uniforms;    // kDim × n, draw-major
  std::vector<double> x_by_draw;   // kDim × n, draw-major: x[j * n + s]
  Eigen::MatrixXd x;               // kDim × block, one column per sample (the truth simulator's input)
  Eigen::MatrixXd z_by_draw;       // block × z_slot::kDim: row s = sample s's extended vector
  std::vector<Eigen::MatrixXd> y;  // per system: block × rows
  std::vector<double> h;
};

/// y = vᵀ · (the first `depth` rows of system j's map) for n samples of v
/// held draw-major with stride ldv: the vectorised kernel (map_product.h),
/// each sample's values a function of that sample alone.
void map_rows(const StudyMap& map, int j, int depth, const double* v, std::size_t ldv, std::size_t n,
              Eigen::MatrixXd& y) {
  const Eigen::MatrixXd& m = map.transposed(j);
  map_product({n, depth, static_cast<int>(m.cols())}, v, ldv, m.data(), static_cast<std::size_t>(m.rows()), y.data(),
              static_cast<std::size_t>(y.rows()));
}

/// The truth level's per-system setup (the same estimators as the system's
/// pipeline), built once per run.
std::vector<TruthSchemeSetup> truth_setups(const StudyConfig& c, const StudyMap& map) {
  std::vector<TruthSchemeSetup> out;
  if (c.fidelity != Fidelity::kTruth) return out;
  for (std::size_t j = 0; j < c.systems.size(); ++j) {
    TruthOptions o;
    o.model = c.model;
    o.system = c.systems[j];
    o.dv_pulse_mps = c.test.dv_pulse_mps;
    o.filter_interval_s = c.test.filter_interval_s;
    o.alignment_loops = c.test.alignment_loops;
    out.emplace_back(o, c.test, map.pipeline(static_cast<int>(j)).estimators());
  }
  return out;
}

/// Rows (x, y, z, north, east per scheme and time) of system j from the
/// truth simulator with each scheme applied (truth_compensation.h), sample by
/// sample. The draws besides x are those of the linear pipeline: the
/// realignment's fresh ζ_r, ∂f_r, (u)V and the pulse counters' phases.
void truth_rows(const StudyConfig& c, const StudyMap& map, const Sampler& sampler, const TruthSchemeSetup& setup,
                std::uint64_t first, std::size_t n, const Eigen::MatrixXd& x, Eigen::MatrixXd& y,
                const std::function<void()>& sample_done) {
  const std::vector<double>& times = map.layout().times_s;
  const double T = c.test.duration_s;
  // One test run per sample serves every scheme that uses it.
  const bool any_test = std::any_of(c.schemes.begin(), c.schemes.end(), uses_test_run);
  for (std::size_t s = 0; s < n; ++s) {
    const Eigen::Index si = static_cast<Eigen::Index>(s);
    const TruthSchemeSample sample = draw_truth_sample(sampler, c.seed, first + s, x.col(si));
    const TruthRun test = any_test ? run_truth_test(setup, sample) : TruthRun{};
    for (std::size_t i = 0; i < c.schemes.size(); ++i) {
      const Scheme scheme = c.schemes[i];
      const TruthRun run = run_truth_scheme(scheme, setup, sample, times, {}, any_test ? &test : nullptr).flight;
      const double frame_offset = frame_time_offset_s(scheme, T);
      for (std::size_t k = 0; k < times.size(); ++k) {
        const Vec3& r = run.position_error_ap_m[k];
        const Eigen::Vector2d ne = local_level_horizontal(frame_offset + times[k], c.model) * r;
        const Eigen::Index base = kRowsPerMap * static_cast<Eigen::Index>(i * times.size() + k);
        for (int a = 0; a < 3; ++a) y(si, base + a) = r[a];
        y(si, base + 3) = ne[0];
        y(si, base + 4) = ne[1];
      }
    }
    if (sample_done) sample_done();
  }
}

/// Runs one block into `acc`; the kept outputs' values also go into `kept`
/// (the run's one store: distinct blocks are distinct memory).
void run_block(const StudyConfig& c, const StudyMap& map, const Sampler& sampler,
               const std::vector<TruthSchemeSetup>& truth, std::uint64_t block, Workspace& ws, StudyAccumulator& acc,
               KeptSamples& kept, const std::function<void()>& truth_sample_done) {
  const std::uint64_t first = block * kBlockSize;
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kBlockSize, c.samples - first));
  // The block's draws with the samples of each uncertainty contiguous, as
  // the vectorised product takes them.
  fill_uniform01_draw_major(c.seed, Stream::Uncertainties, first, uncertainty_slot::kDim, n,
                            std::span<double>(ws.uniforms.data(), n * uncertainty_slot::kDim));
  sampler.transform_draw_major(ws.uniforms.data(), n, ws.x_by_draw.data());
  const Eigen::Index ni = static_cast<Eigen::Index>(n);
  if (c.fidelity == Fidelity::kTruth)  // one column per sample, for the truth simulator
    ws.x.leftCols(ni) = Eigen::Map<const Eigen::MatrixXd>(ws.x_by_draw.data(), ni, uncertainty_slot::kDim).transpose();
  for (std::size_t j = 0; j < ws.y.size(); ++j) {
    const int sj = static_cast<int>(j);
    if (c.fidelity == Fidelity::kTruth) {  // the nonlinear simulator, sample by sample
      truth_rows(c, map, sampler, truth[j], first, n, ws.x, ws.y[j], truth_sample_done);
      continue;
    }
    if (map.depends_on_x_only(sj)) {  // z = [x; 0]: the same product on the rows that matter
      map_rows(map, sj, uncertainty_slot::kDim, ws.x_by_draw.data(), n, n, ws.y[j]);
      continue;
    }
    map.pipeline(sj).extended_vectors_by_draw(first, n, ws.x_by_draw.data(), ws.z_by_draw);
    map_rows(map, sj, z_slot::kDim, ws.z_by_draw.data(), static_cast<std::size_t>(ws.z_by_draw.rows()), n, ws.y[j]);
  }
  auto& outs = acc.outputs();
  const std::vector<int>& kept_slot = map.layout().kept_slot;
  const bool keep = kept.keeps(block);
  for (std::size_t o = 0; o < outs.size(); ++o) {
    const Eigen::MatrixXd& y = ws.y[static_cast<std::size_t>(map.system_index(o))];
    const int base = map.row_base(o);
    const int axis = static_cast<int>(o % 4);
    if (axis < 3) {
      outs[o].add_block(y.col(base + axis).data(), n);
    } else {
      const double* north = y.col(base + 3).data();
      const double* east = y.col(base + 4).data();
      // The horizontal radial error r = sqrt(N² + E²).
      for (std::size_t s = 0; s < n; ++s) ws.h[s] = std::sqrt(north[s] * north[s] + east[s] * east[s]);
      outs[o].add_block(ws.h.data(), n);
      if (keep && kept_slot[o] >= 0)
        std::transform(ws.h.begin(), ws.h.begin() + static_cast<std::ptrdiff_t>(n),
                       kept.slot(block, static_cast<std::uint64_t>(kept_slot[o])),
                       [](double r) { return static_cast<float>(r); });
    }
  }
  if (keep) kept.mark_filled(block);
}

}  // namespace

StudyAccumulator::StudyAccumulator(const StudyMap& map, bool keep_samples) {
  const auto& mean = map.predicted_mean();
  const auto& rms = map.predicted_rms();
  outputs_.reserve(mean.size());
  for (size_t o = 0; o < mean.size(); ++o) outputs_.emplace_back(mean[o], rms[o]);
  if (keep_samples && map.layout().n_kept > 0)
    kept_ = KeptSamples(static_cast<std::uint64_t>(map.layout().n_kept), map.config().samples);
}

void StudyAccumulator::merge(const StudyAccumulator& other) {
  if (other.outputs_.empty()) return;  // a default-constructed accumulator is the identity
  if (outputs_.empty()) {
    *this = other;
    return;
  }
  INSMC_ASSERT(other.outputs_.size() == outputs_.size(), "merging accumulators of {} and {} outputs",
               outputs_.size(), other.outputs_.size());
  for (size_t o = 0; o < outputs_.size(); ++o) outputs_[o].merge(other.outputs_[o]);
  kept_.merge(other.kept_);
}

void StudyAccumulator::merge(StudyAccumulator&& other) {
  if (other.outputs_.empty()) return;
  if (outputs_.empty()) {
    *this = std::move(other);
    return;
  }
  INSMC_ASSERT(other.outputs_.size() == outputs_.size(), "merging accumulators of {} and {} outputs",
               outputs_.size(), other.outputs_.size());
  for (size_t o = 0; o < outputs_.size(); ++o) outputs_[o].merge(std::move(other.outputs_[o]));
  kept_.merge(other.kept_);
}

std::optional<HorizontalAccuracy> StudyAccumulator::accuracy(const StudyLayout& l, std::size_t o,
                                                             const OutputSummary& s, double confidence) const {
  const int slot = l.kept_slot[o];
  if (slot < 0 || kept_.outputs() == 0) return std::nullopt;
  return horizontal_accuracy(s, kept_.values(static_cast<std::uint64_t>(slot)), l.times_s[l.outputs[o].time_index],
                             confidence);
}

std::string StudyAccumulator::serialize() const { return serialize_state(outputs_, kept_); }

StudyAccumulator StudyAccumulator::deserialize(std::string_view bytes) {
  AccumulatorState state = deserialize_state(bytes);
  StudyAccumulator acc;
  acc.outputs_ = std::move(state.outputs);
  acc.kept_ = std::move(state.kept);
  return acc;
}

StudyAccumulator run_blocks(const StudyConfig& c, const StudyMap& map, std::uint64_t first_block,
                            std::uint64_t end_block, const ProgressCallback& progress, const std::atomic<bool>* stop,
                            std::uint64_t* finished_end) {
  const int threads = c.threads > 0 ? c.threads
                                    : static_cast<int>(tbb::info::default_concurrency());
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  const Sampler sampler(c.uncertainties);
  const std::vector<TruthSchemeSetup> truth = truth_setups(c, map);
  const StudyAccumulator empty(map, false);
  // The kept values go straight into the result's store, block by block.
  StudyAccumulator total(map);
  tbb::enumerable_thread_specific<StudyAccumulator> partial(empty);
  tbb::enumerable_thread_specific<Workspace> workspaces(map, static_cast<int>(c.systems.size()));
  std::atomic<std::uint64_t> done{0};
  // One task per thread; each claims the next block from a shared counter.
  // Blocks are therefore started in index order, and a claimed block is
  // always finished: when `stop` ends the run early, the finished blocks are
  // exactly [first_block, next).
  std::atomic<std::uint64_t> next{first_block};
  const auto stopped = [stop] { return stop != nullptr && stop->load(std::memory_order_acquire); };
  // A truth sample takes milliseconds, a block of them seconds to minutes:
  // progress counts them as they finish ((sample, system) pairs of blocks
  // still running, over the systems), not only whole blocks.
  std::atomic<std::uint64_t> truth_pairs{0};
  const std::uint64_t systems = c.systems.size();
  std::function<void()> truth_sample_done;
  if (progress && c.fidelity == Fidelity::kTruth)
    truth_sample_done = [&] { progress(done.load() + (truth_pairs.fetch_add(1) + 1) / systems); };
  tbb::parallel_for(
      tbb::blocked_range<int>(0, threads, 1),
      [&](const tbb::blocked_range<int>&) {
        Workspace& ws = workspaces.local();
        StudyAccumulator& acc = partial.local();
        while (!stopped()) {
          const std::uint64_t b = next.fetch_add(1);
          if (b >= end_block) break;
          run_block(c, map, sampler, truth, b, ws, acc, total.kept(), truth_sample_done);
          const std::uint64_t n = std::min<std::uint64_t>(kBlockSize, c.samples - b * kBlockSize);
          const std::uint64_t samples_done = done.fetch_add(n) + n;
          if (truth_sample_done) truth_pairs.fetch_sub(n * systems);
          if (progress) progress(samples_done);
        }
      },
      tbb::simple_partitioner());
  if (finished_end) *finished_end = std::min(next.load(), end_block);
  // Exact, associative and commutative merge: the order does not matter.
  for (StudyAccumulator& p : partial) total.merge(std::move(p));
  return total;
}

std::vector<double> evaluate_sample(const StudyConfig& c, const StudyMap& map, const StudyLayout& layout,
                                    std::uint64_t index, const UncertaintyVector& x) {
  Eigen::MatrixXd xm = x;
  Eigen::MatrixXd z(z_slot::kDim, 1);
  std::vector<Eigen::MatrixXd> rows;
  for (std::size_t j = 0; j < c.systems.size(); ++j) {
    map.pipeline(static_cast<int>(j)).extended_vectors(index, 1, xm, z);
    rows.emplace_back(1, map.transposed(static_cast<int>(j)).cols());
    map_rows(map, static_cast<int>(j), z_slot::kDim, z.data(), 1, 1, rows.back());  // the block's kernel: its bits
  }
  std::vector<double> out;
  for (size_t o = 0; o < layout.outputs.size(); ++o)
    out.push_back(StudyMap::output_value(rows[static_cast<std::size_t>(map.system_index(o))].data() + map.row_base(o),
                                         layout.outputs[o].axis));
  return out;
}

}  // namespace insmc::mc
