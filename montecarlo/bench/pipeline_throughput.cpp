#include "montecarlo/bench/pipeline_throughput.h"

#include <Eigen/Core>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <vector>

#include "montecarlo/bench/timing.h"
#include "montecarlo/engine/engine.h"
#include "montecarlo/random/philox.h"

namespace insmc::mc {
namespace {

// Uniforms per sample besides x that the pipeline draws: the counter phases
// (ΔV at switch-over, torquer, alignment ΔV: 9) and the realignment (8).
constexpr int kExtraDraws = 9 + static_cast<int>(std::size(kRealignedSlots));

/// One system's matrices of the floor: the pipeline's shapes.
struct SystemProducts {
  Eigen::MatrixXd observe;       // (6K + 3 + 6) × 33: ΔV and Δr per k and axis, r(0), alignment data
  Eigen::MatrixXd accel_fit;     // 3 × K (4.4)
  Eigen::MatrixXd position_fit;  // 4 × K (4.7)
  const Eigen::MatrixXd* map_t;  // ez::kDim × output rows
};

/// Seconds of the floor over blocks [first_block, end_block).
double time_floor(const StudyConfig& c, const StudyMap& map, std::uint64_t first_block, std::uint64_t end_block) {
  const int k = c.test.intervals();
  std::vector<SystemProducts> systems;
  for (std::size_t j = 0; j < c.systems.size(); ++j) {
    const SystemPipeline& p = map.pipeline(static_cast<int>(j));
    // The observation maps are private to the pipeline; a GEMM's time does
    // not depend on the values, so random ones of the same shape stand in.
    systems.push_back({Eigen::MatrixXd::Random(6 * k + 9, ux::kDim), p.estimators().accel,
                       p.estimators().position, &map.transposed(static_cast<int>(j))});
  }
  UncertaintyVector bounds;
  for (int j = 0; j < ux::kDim; ++j) bounds[j] = c.uncertainties.at(j).bound_si;
  const auto t0 = std::chrono::steady_clock::now();
  tbb::parallel_for(first_block, end_block, [&](std::uint64_t b) {
    const Eigen::Index n = static_cast<Eigen::Index>(kBlockSize);
    thread_local std::vector<double> u(kBlockSize * ux::kDim), extra(kBlockSize * kExtraDraws);
    thread_local Eigen::MatrixXd x(ux::kDim, n), observed(6 * k + 9, n), z = Eigen::MatrixXd::Zero(ez::kDim, n),
                                 accel(3, n), position(4, n), y;
    fill_uniform01(c.seed, Stream::Uncertainties, b * kBlockSize, ux::kDim, kBlockSize, u);
    fill_uniform01(c.seed, Stream::PulsePhase, b * kBlockSize, kExtraDraws, kBlockSize, extra);
    for (Eigen::Index s = 0; s < n; ++s)
      for (int j = 0; j < ux::kDim; ++j) x(j, s) = (2 * u[static_cast<std::size_t>(s * ux::kDim + j)] - 1) * bounds[j];
    const Eigen::Map<const Eigen::MatrixXd> draws(extra.data(), kExtraDraws, n);
    double sums = 0.0;
    for (const SystemProducts& sp : systems) {
      observed.noalias() = sp.observe * x;
      z.topRows<ux::kDim>() = x;
      z.middleRows(ez::kRealignZeta, kExtraDraws - 9) = draws.bottomRows(kExtraDraws - 9);
      for (int a = 0; a < 3; ++a) {  // the fits on each axis' K data, every sample at once
        accel.noalias() = sp.accel_fit * observed.middleRows(a * k, k);
        position.noalias() = sp.position_fit * observed.middleRows(3 * k + a * k, k);
        z.row(ez::kU2 + a) = position.row(1);
        z.row(ez::kU3 + a) = position.row(2);
        z.row(ez::kU3Accel + a) = accel.row(1);
        z.row(ez::kDfT + a) = accel.row(0);
      }
      z.middleRows<6>(ez::kTorquerCommands) = observed.bottomRows<6>();
      y.noalias() = z.transpose() * *sp.map_t;
      sums += y.sum() + y.squaredNorm();
    }
    bench::keep(sums);
  });
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

}  // namespace

StudyConfig pipeline_study(Fidelity fidelity, std::uint64_t samples, int threads) {
  StudyConfig c;
  c.fidelity = fidelity;
  c.samples = samples;
  c.threads = threads;
  c.with_grid = false;
  return c;
}

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
