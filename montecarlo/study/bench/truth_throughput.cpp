#include "montecarlo/study/bench/truth_throughput.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <vector>

#include "montecarlo/study/bench/timing.h"
#include "montecarlo/study/bench/truth_reference.h"
#include "montecarlo/study/engine/engine.h"
#include "montecarlo/study/bench/throughput.h"
#include "montecarlo/study/random/philox.h"
#include "montecarlo/study/sampler/sampler.h"

namespace insmc::mc {

StudyConfig truth_study(std::uint64_t samples, int threads) { return benchmark_study(samples, threads, Fidelity::kTruth); }

TruthThroughput measure_truth_throughput(const StudyConfig& c) {
  const StudyLayout layout = make_layout(c);
  const StudyMap map(c, layout);
  const std::vector<double>& times = layout.times_s;
  std::vector<TruthReference> references;
  for (System s : c.systems)
    references.emplace_back(c.model, s, c.test.dv_pulse_mps, c.test.filter_interval_s, times);
  const Sampler sampler(c.uncertainties);
  // The reference on the engine's samples: x and the pulse phases from the same streams.
  const auto time_reference = [&](std::uint64_t first_block, std::uint64_t end_block) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(c.threads > 0 ? c.threads : 2));
    const auto t0 = std::chrono::steady_clock::now();
    tbb::parallel_for(first_block, end_block, [&](std::uint64_t b) {
      const std::uint64_t first = b * kBlockSize;
      const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(kBlockSize, c.samples - first));
      thread_local std::vector<double> u(kBlockSize * uncertainty_slot::kDim);
      thread_local Eigen::MatrixXd x(uncertainty_slot::kDim, kBlockSize);
      thread_local std::vector<Vec3> error;
      error.resize(times.size());
      fill_uniform01(c.seed, Stream::Uncertainties, first, uncertainty_slot::kDim, n, std::span<double>(u.data(), n * uncertainty_slot::kDim));
      sampler.transform(u.data(), n, x.data());
      double sum_squares_m2 = 0.0;
      for (std::size_t s = 0; s < n; ++s) {
        double phase[3];
        fill_uniform01(c.seed, Stream::PulsePhase, first + s, 3, 1, phase);
        for (const TruthReference& ref : references) {
          ref.run(x.col(static_cast<Eigen::Index>(s)), Vec3(phase[0] - 0.5, phase[1] - 0.5, phase[2] - 0.5),
                  error.data());
          for (const Vec3& e : error) sum_squares_m2 += e.squaredNorm();
        }
      }
      bench::keep(sum_squares_m2);
    });
    return bench::seconds_since(t0);
  };
  const auto time_engine = [&](std::uint64_t first_block, std::uint64_t end_block) {
    const auto t0 = std::chrono::steady_clock::now();
    const StudyAccumulator acc = run_blocks(c, map, first_block, end_block);
    const double seconds = bench::seconds_since(t0);
    bench::keep(acc.outputs()[0].sum_squares());
    return seconds;
  };
  // The two alternate in a few chunks of blocks, so that a change of the
  // machine's load during the measurement hits both alike. A truth block is
  // about a second of work: few chunks, so each still spreads over the threads.
  constexpr std::uint64_t kChunks = 2;
  const std::uint64_t blocks = block_count(c.samples);
  double reference_s = 0.0, truth_s = 0.0;
  for (std::uint64_t chunk = 0; chunk < kChunks; ++chunk) {
    const std::uint64_t first = blocks * chunk / kChunks, end = blocks * (chunk + 1) / kChunks;
    if (first == end) continue;
    reference_s += time_reference(first, end);
    truth_s += time_engine(first, end);
  }
  return {static_cast<double>(c.samples) / reference_s, static_cast<double>(c.samples) / truth_s};
}

}  // namespace insmc::mc
