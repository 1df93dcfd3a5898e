#include "montecarlo/study/bench/throughput.h"

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string>
#include <thread>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <vector>

#include "montecarlo/study/bench/timing.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/kernels/map_product.h"
#include "montecarlo/study/random/philox.h"

namespace insmc::mc {
using bench::keep;
using bench::seconds_since;

MachineDescription describe_machine() {
  MachineDescription m;
  m.cpu = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  for (int lines = 0; lines < 10000 && std::getline(cpuinfo, line); ++lines)  // the first processor's entry
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      m.cpu = line.substr(line.find(':') + 1);
      m.cpu.erase(0, std::min(m.cpu.find_first_not_of(' '), m.cpu.size()));
      break;
    }
  m.hardware_threads = static_cast<int>(std::thread::hardware_concurrency());
  switch (detail::best_kernel()) {
    case detail::PhiloxKernel::Generic: m.generator_kernel = "generic"; break;
    case detail::PhiloxKernel::Avx2: m.generator_kernel = "AVX2"; break;
    case detail::PhiloxKernel::Avx512: m.generator_kernel = "AVX-512 (draw-major), AVX2 (sample-major)"; break;
  }
  m.product_kernel = std::string(product_kernel_name(best_product_kernel()));
  return m;
}

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
    std::vector<double> u(kBlockSize * uncertainty_slot::kDim);
    const auto t0 = std::chrono::steady_clock::now();
    double acc = 0;
    for (std::uint64_t first = 0; first < n; first += kBlockSize) {
      fill_uniform01_draw_major(c.seed, Stream::Uncertainties, first, uncertainty_slot::kDim, kBlockSize, u);
      acc += u[7];
    }
    keep(acc);
    r.generator_variates_per_s = static_cast<double>(n * uncertainty_slot::kDim) / seconds_since(t0);
  }

  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(c.threads > 0 ? c.threads : 2));
  {  // the vectorised floor: generator + map + sums, no aggregator, no layout, no framework
    // Uncompensated: z = [x; 0], so the map acting on x is the top of each
    // system's; both systems' columns in one product. The generator and the
    // product are the fastest kernels of this CPU (random/philox.h,
    // kernels/map_product.h), and the sums run in 8 independent lanes, so
    // nothing here waits on a scalar chain.
    Eigen::MatrixXd mt(uncertainty_slot::kDim, map.transposed(0).cols() * static_cast<Eigen::Index>(c.systems.size()));
    for (size_t j = 0; j < c.systems.size(); ++j)
      mt.middleCols(static_cast<Eigen::Index>(j) * map.transposed(0).cols(), map.transposed(0).cols()) =
          map.transposed(static_cast<int>(j)).topRows<uncertainty_slot::kDim>();
    const UncertaintyVector bounds = [&] {
      UncertaintyVector b;
      for (int j = 0; j < uncertainty_slot::kDim; ++j) b[j] = c.uncertainties.at(j).bound_si;
      return b;
    }();
    const std::uint64_t blocks = block_count(c.samples);
    const auto one_block = [&](std::uint64_t b) {
      thread_local std::vector<double> u(kBlockSize * uncertainty_slot::kDim), x(kBlockSize * uncertainty_slot::kDim);
      thread_local Eigen::MatrixXd y(kBlockSize, mt.cols());
      fill_uniform01_draw_major(c.seed, Stream::Uncertainties, b * kBlockSize, uncertainty_slot::kDim, kBlockSize, u);
      for (int j = 0; j < uncertainty_slot::kDim; ++j)
        for (std::size_t s = 0; s < kBlockSize; ++s)
          x[j * kBlockSize + s] = (2 * u[j * kBlockSize + s] - 1) * bounds[j];
      map_product({kBlockSize, uncertainty_slot::kDim, static_cast<int>(mt.cols())}, x.data(), kBlockSize, mt.data(), uncertainty_slot::kDim,
                  y.data(), kBlockSize);
      keep(bench::lane_sums(y.data(), kBlockSize, static_cast<std::size_t>(y.cols()), kBlockSize));
    };
    // Untimed first, so that no worker's first touch of its buffers is timed.
    tbb::parallel_for(std::uint64_t{0}, std::uint64_t{4} * tbb::this_task_arena::max_concurrency(), one_block);
    const auto t0 = std::chrono::steady_clock::now();
    tbb::parallel_for(std::uint64_t{0}, blocks, one_block);
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
