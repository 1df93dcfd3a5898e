// MPI ranks for `insmc run` (compiled only with -DINSMC_MPI=ON): the block
// range is split into contiguous rank shares by
// montecarlo/study/run/study_runner.cpp; here the ranks' accumulator states are
// gathered at rank 0 with their sizes (a sparse histogram's state differs in
// size between ranks, so a fixed-size MPI reduction cannot carry them),
// merged there in rank order (exactly: the sums are fixed-point, so any
// order gives the same bits) and broadcast when every rank needs the result.
#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <mpi.h>
#include <string_view>
#include <vector>

#include "montecarlo/study/run/join_processes.h"
#include "lib/common/assert.h"

namespace insmc::mc {
namespace {

class MpiProcesses final : public Processes {
 public:
  MpiProcesses() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);  // only the main thread calls MPI
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiProcesses() override {
    std::fflush(stdout);
    std::fflush(stderr);
    MPI_Finalize();
  }

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  bool distributed() const override { return true; }

  std::vector<std::int64_t> max_all(std::vector<std::int64_t> values) override {
    std::vector<std::int64_t> out(values.size());
    MPI_Allreduce(values.data(), out.data(), static_cast<int>(values.size()), MPI_INT64_T, MPI_MAX, MPI_COMM_WORLD);
    return out;
  }

  std::string broadcast(std::string bytes) override {
    std::uint64_t n = bytes.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    bytes.resize(n);
    constexpr std::uint64_t kChunk = 1ULL << 30;  // MPI counts are int
    for (std::uint64_t at = 0; at < n; at += kChunk)
      MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(kChunk, n - at)), MPI_BYTE, 0, MPI_COMM_WORLD);
    return bytes;
  }

  std::vector<std::uint64_t> gather(std::uint64_t value) override {
    std::vector<std::uint64_t> out(rank_ == 0 ? static_cast<std::size_t>(size_) : 0);
    MPI_Gather(&value, 1, MPI_UINT64_T, out.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    return out;
  }

  StudyAccumulator merge(const StudyAccumulator& local, bool everywhere) override {
    const std::string bytes = local.serialize();
    INSMC_ASSERT(bytes.size() < INT_MAX, "an accumulator state of {} bytes exceeds one MPI message (2 GiB)", bytes.size());
    int count = static_cast<int>(bytes.size());
    std::vector<int> counts(rank_ == 0 ? static_cast<std::size_t>(size_) : 0), starts(counts.size());
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank_ == 0) {
      std::int64_t total = 0;
      for (std::size_t r = 0; r < counts.size(); ++r) starts[r] = static_cast<int>(total), total += counts[r];
      INSMC_ASSERT(total < INT_MAX, "the ranks' accumulator states, {} bytes, exceed one MPI message (2 GiB)", total);
      all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(bytes.data(), count, MPI_BYTE, all.data(), counts.data(), starts.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
    std::string merged;
    if (rank_ == 0) {
      const auto state_of = [&](std::size_t r) {
        return std::string_view(all).substr(static_cast<std::size_t>(starts[r]), static_cast<std::size_t>(counts[r]));
      };
      StudyAccumulator acc = StudyAccumulator::deserialize(state_of(0));
      for (std::size_t r = 1; r < counts.size(); ++r) acc.merge(StudyAccumulator::deserialize(state_of(r)));
      merged = acc.serialize();
    }
    if (everywhere) merged = broadcast(std::move(merged));
    else if (rank_ != 0) return {};
    return StudyAccumulator::deserialize(merged);
  }

  void barrier() override { MPI_Barrier(MPI_COMM_WORLD); }

  void abort(int exit_code) override {
    std::fflush(stdout);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, exit_code);
  }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace

std::unique_ptr<Processes> make_mpi_processes() { return std::make_unique<MpiProcesses>(); }

}  // namespace insmc::mc
