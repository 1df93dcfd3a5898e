#include "montecarlo/study/bench/pipeline_throughput.h"

#include <Eigen/Core>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <vector>

#include "montecarlo/study/bench/timing.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/kernels/map_product.h"
#include "montecarlo/study/random/philox.h"

namespace insmc::mc {
namespace {

// Uniforms per sample besides x that the pipeline draws: the counter phases
// (ΔV at switch-over, torquer, alignment ΔV: 9) and the realignment (8).
constexpr int kExtraDraws = 9 + static_cast<int>(std::size(kRealignedSlots));

/// One system's matrices of the floor: the pipeline's shapes, as the block
/// product takes them (the columns of each map: m[r·ldm + k]).
struct SystemProducts {
  Eigen::MatrixXd observe;       // 33 × (6K + 3 + 6): ΔV and Δr per k and axis, r(0), alignment data
  Eigen::MatrixXd accel_fit;     // K × 3 (4.4)
  Eigen::MatrixXd position_fit;  // K × 4 (4.7)
  const Eigen::MatrixXd* map_t;  // z_slot::kDim × output rows
};

/// Seconds of the floor over blocks [first_block, end_block): the
/// generator, the observation maps, the fits on each axis' K data and the
/// output map, all as vectorised block products (kernels/map_product.h) on
/// draw-major blocks, and lane sums of the outputs.
double time_floor(const StudyConfig& c, const StudyMap& map, std::uint64_t first_block, std::uint64_t end_block) {
  const int k = c.test.intervals();
  const int observed_rows = 6 * k + 9;
  std::vector<SystemProducts> systems;
  for (std::size_t j = 0; j < c.systems.size(); ++j) {
    const SystemPipeline& p = map.pipeline(static_cast<int>(j));
    // The observation maps are private to the pipeline; a product's time
    // does not depend on the values, so random ones of the same shape stand in.
    systems.push_back({Eigen::MatrixXd::Random(uncertainty_slot::kDim, observed_rows), p.estimators().accel.transpose(),
                       p.estimators().position.transpose(), &map.transposed(static_cast<int>(j))});
  }
  UncertaintyVector bounds;
  for (int j = 0; j < uncertainty_slot::kDim; ++j) bounds[j] = c.uncertainties.at(j).bound_si;
  const auto one_block = [&](std::uint64_t b) {
    constexpr std::size_t n = kBlockSize;
    const Eigen::Index ni = static_cast<Eigen::Index>(n);
    thread_local std::vector<double> u(n * uncertainty_slot::kDim), extra(n * kExtraDraws);
    thread_local Eigen::MatrixXd x(ni, uncertainty_slot::kDim), observed(ni, observed_rows), z = Eigen::MatrixXd::Zero(ni, z_slot::kDim),
                                 accel(ni, 3), position(ni, 4), y;
    fill_uniform01_draw_major(c.seed, Stream::Uncertainties, b * n, uncertainty_slot::kDim, n, u);
    fill_uniform01_draw_major(c.seed, Stream::PulsePhase, b * n, kExtraDraws, n, extra);
    for (int j = 0; j < uncertainty_slot::kDim; ++j)
      for (std::size_t s = 0; s < n; ++s) x(static_cast<Eigen::Index>(s), j) = (2 * u[j * n + s] - 1) * bounds[j];
    const Eigen::Map<const Eigen::MatrixXd> draws(extra.data(), ni, kExtraDraws);
    double sums = 0.0;
    for (const SystemProducts& sp : systems) {
      y.resize(ni, sp.map_t->cols());
      map_product({n, uncertainty_slot::kDim, observed_rows}, x.data(), n, sp.observe.data(), uncertainty_slot::kDim, observed.data(), n);
      z.leftCols<uncertainty_slot::kDim>() = x;
      z.middleCols(z_slot::kRealignZeta, kExtraDraws - 9) = draws.rightCols(kExtraDraws - 9);
      for (int a = 0; a < 3; ++a) {  // the fits on each axis' K data, every sample at once
        map_product({n, k, 3}, observed.col(a * k).data(), n, sp.accel_fit.data(), static_cast<std::size_t>(k),
                    accel.data(), n);
        map_product({n, k, 4}, observed.col(3 * k + a * k).data(), n, sp.position_fit.data(),
                    static_cast<std::size_t>(k), position.data(), n);
        z.col(z_slot::kU2 + a) = position.col(1);
        z.col(z_slot::kU3 + a) = position.col(2);
        z.col(z_slot::kU3Accel + a) = accel.col(1);
        z.col(z_slot::kDfT + a) = accel.col(0);
      }
      z.middleCols<6>(z_slot::kTorquerCommands) = observed.rightCols<6>();
      map_product({n, z_slot::kDim, static_cast<int>(y.cols())}, z.data(), n, sp.map_t->data(),
                  static_cast<std::size_t>(sp.map_t->rows()), y.data(), n);
      sums += bench::lane_sums(y.data(), n, static_cast<std::size_t>(y.cols()), n);
    }
    bench::keep(sums);
  };
  // Untimed first: every worker thread's buffers exist and are touched (their
  // page faults would otherwise fall in the timed part, by a varying share:
  // 0.16 to 0.38 M samples/s over five rounds when they did).
  tbb::parallel_for(std::uint64_t{0}, std::uint64_t{4} * tbb::this_task_arena::max_concurrency(), one_block);
  const auto t0 = std::chrono::steady_clock::now();
  tbb::parallel_for(first_block, end_block, one_block);
  return bench::seconds_since(t0);
}

/// Seconds of the engine over blocks [first_block, end_block).
double time_engine(const StudyConfig& c, const StudyMap& map, std::uint64_t first_block, std::uint64_t end_block) {
  const auto t0 = std::chrono::steady_clock::now();
  const StudyAccumulator acc = run_blocks(c, map, first_block, end_block);
  const double seconds = bench::seconds_since(t0);
  bench::keep(acc.outputs()[0].sum_squares());
  return seconds;
}

/// Every scheme, systems 1 and 2, the report times (no grid).
StudyConfig pipeline_study(Fidelity fidelity, std::uint64_t samples, int threads) {
  StudyConfig c;
  c.fidelity = fidelity;
  c.samples = samples;
  c.threads = threads;
  c.with_grid = false;
  return c;
}

}  // namespace

PipelineThroughput measure_pipeline_throughput(std::uint64_t samples, int threads) {
  const StudyConfig paper = pipeline_study(Fidelity::kPaper, samples, threads);
  const StudyConfig linear = pipeline_study(Fidelity::kLinear, samples, threads);
  const StudyLayout paper_layout = make_layout(paper), linear_layout = make_layout(linear);
  const StudyMap paper_map(paper, paper_layout), linear_map(linear, linear_layout);
  // One run_blocks call per level, as in a run: each call builds and merges
  // accumulators with a 4097-bin histogram per output (168 outputs here), a
  // fixed cost that splitting the measurement into chunks would multiply.
  const std::uint64_t blocks = block_count(samples);
  double floor_s = 0.0;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads > 0 ? threads : 2));
    floor_s = time_floor(linear, linear_map, 0, blocks);
  }
  const double paper_s = time_engine(paper, paper_map, 0, blocks);
  const double linear_s = time_engine(linear, linear_map, 0, blocks);
  // The last block may be partial in the engine; the floor always runs whole blocks.
  PipelineThroughput r{};
  r.floor_samples_per_s = static_cast<double>(blocks * kBlockSize) / floor_s;
  r.paper_samples_per_s = static_cast<double>(samples) / paper_s;
  r.linear_samples_per_s = static_cast<double>(samples) / linear_s;
  return r;
}

}  // namespace insmc::mc
