#include "montecarlo/bench/throughput.h"

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <vector>

#include "montecarlo/bench/timing.h"
#include "montecarlo/engine/engine.h"
#include "montecarlo/random/philox.h"

namespace insmc::mc {
using bench::keep;
using bench::seconds_since;

StudyConfig benchmark_study(std::uint64_t samples, int threads, Fidelity fidelity) {
  StudyConfig c;
  c.fidelity = fidelity;
  c.samples = samples;
  c.threads = threads;
  c.with_grid = false;
  c.schemes = {Scheme::kNone};
  return c;
}

ThroughputResult measure_throughput(const StudyConfig& c) {
  ThroughputResult r{};
  r.samples = c.samples;
  r.threads = c.threads;
  const StudyLayout layout = make_layout(c);
  const StudyMap map(c, layout);
  r.outputs = static_cast<int>(layout.outputs.size());

  {  // generator alone: bulk uniforms, one thread
    const std::uint64_t n = std::min<std::uint64_t>(c.samples, 1u << 18);
    std::vector<double> u(kBlockSize * ux::kDim);
    const auto t0 = std::chrono::steady_clock::now();
    double acc = 0;
    for (std::uint64_t first = 0; first < n; first += kBlockSize) {
      fill_uniform01(c.seed, Stream::Uncertainties, first, ux::kDim, kBlockSize, u);
      acc += u[7];
    }
    keep(acc);
    r.generator_variates_per_s = static_cast<double>(n * ux::kDim) / seconds_since(t0);
  }

  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(c.threads > 0 ? c.threads : 2));
  {  // floor: generator + map + sums, no aggregator, no layout, no framework
    // Uncompensated: z = [x; 0], so the map acting on x is the top of each system's.
    Eigen::MatrixXd mt(ux::kDim, map.transposed(0).cols() * static_cast<Eigen::Index>(c.systems.size()));
    for (size_t j = 0; j < c.systems.size(); ++j)
      mt.middleCols(static_cast<Eigen::Index>(j) * map.transposed(0).cols(), map.transposed(0).cols()) =
          map.transposed(static_cast<int>(j)).topRows<ux::kDim>();
    const UncertaintyVector bounds = [&] {
      UncertaintyVector b;
      for (int j = 0; j < ux::kDim; ++j) b[j] = c.uncertainties.at(j).bound_si;
      return b;
    }();
    const std::uint64_t blocks = block_count(c.samples);
    const auto t0 = std::chrono::steady_clock::now();
    tbb::parallel_for(std::uint64_t{0}, blocks, [&](std::uint64_t b) {
      thread_local std::vector<double> u(kBlockSize * ux::kDim);
      thread_local Eigen::MatrixXd x(ux::kDim, kBlockSize), y(kBlockSize, mt.cols());
      fill_uniform01(c.seed, Stream::Uncertainties, b * kBlockSize, ux::kDim, kBlockSize, u);
      for (std::size_t s = 0; s < kBlockSize; ++s)
        for (int j = 0; j < ux::kDim; ++j) x(j, s) = (2 * u[s * ux::kDim + j] - 1) * bounds[j];
      y.noalias() = x.transpose() * mt;
      double s1 = 0, s2 = 0, s4 = 0;
      for (Eigen::Index col = 0; col < y.cols(); ++col)
        for (Eigen::Index s = 0; s < y.rows(); ++s) {
          const double v = y(s, col), v2 = v * v;
          s1 += v, s2 += v2, s4 += v2 * v2;
        }
      keep(s1 + s2 + s4);
    });
    r.floor_samples_per_s = static_cast<double>(blocks * kBlockSize) / seconds_since(t0);
  }
  {
    const auto t0 = std::chrono::steady_clock::now();
    const StudyAccumulator acc = run_blocks(c, map, 0, block_count(c.samples));
    r.engine_samples_per_s = static_cast<double>(c.samples) / seconds_since(t0);
    keep(acc.outputs()[0].sum_squares());
  }
  {  // the same study on one thread, measured right after: a paired scaling ratio
    StudyConfig one = c;
    one.threads = 1;
    const auto t0 = std::chrono::steady_clock::now();
    const StudyAccumulator acc = run_blocks(one, map, 0, block_count(c.samples));
    r.engine_one_thread_samples_per_s = static_cast<double>(c.samples) / seconds_since(t0);
    keep(acc.outputs()[0].sum_squares());
  }
  return r;
}

}  // namespace insmc::mc
