// MPI ranks for `insmc run` (compiled only with -DINSMC_MPI=ON): the block
// range is split into contiguous rank shares by
// montecarlo/study/study_runner.cpp; here the ranks' accumulator states are
// merged by an MPI reduction whose operation deserializes two states, merges
// them (exactly: the sums are fixed-point, so any reduction tree gives the
// same bits) and serializes the result back.
#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstring>
#include <exception>
#include <mpi.h>
#include <string_view>

#include "apps/ranks.h"
#include "lib/common/assert.h"

namespace insmc::app {
namespace {

extern "C" void merge_serialized_states(void* in, void* inout, int* len, MPI_Datatype* type) {
  int bytes = 0;
  MPI_Type_size(*type, &bytes);
  const auto n = static_cast<std::size_t>(bytes);
  for (int i = 0; i < *len; ++i) {
    const char* a = static_cast<const char*>(in) + static_cast<std::size_t>(i) * n;
    char* b = static_cast<char*>(inout) + static_cast<std::size_t>(i) * n;
    std::string merged;
    try {
      mc::StudyAccumulator acc = mc::StudyAccumulator::deserialize(std::string_view(b, n));
      acc.merge(mc::StudyAccumulator::deserialize(std::string_view(a, n)));
      merged = acc.serialize();
    } catch (const std::exception& e) {
      INSMC_ASSERT(false, "MPI merge of accumulator states: {}", e.what());
    }
    INSMC_ASSERT(merged.size() == n, "merged state of {} bytes, expected {}", merged.size(), n);
    std::memcpy(b, merged.data(), n);
  }
}

class MpiRanks final : public Ranks {
 public:
  MpiRanks() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);  // only the main thread calls MPI
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiRanks() override {
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

  mc::StudyAccumulator merge(const mc::StudyAccumulator& local, bool everywhere) override {
    const std::string bytes = local.serialize();
    const auto n = static_cast<std::int64_t>(bytes.size());
    const std::vector<std::int64_t> extremes = max_all({n, -n});
    INSMC_ASSERT(extremes[0] == n && extremes[1] == -n, "ranks hold states of different sizes ({} to {} bytes)",
                 -extremes[1], extremes[0]);
    INSMC_ASSERT(n < INT_MAX, "an accumulator state of {} bytes exceeds one MPI element (2 GiB)", n);
    MPI_Datatype state;
    MPI_Type_contiguous(static_cast<int>(n), MPI_BYTE, &state);
    MPI_Type_commit(&state);
    MPI_Op op;
    MPI_Op_create(merge_serialized_states, /*commute=*/1, &op);
    std::string out(bytes.size(), '\0');
    if (everywhere)
      MPI_Allreduce(bytes.data(), out.data(), 1, state, op, MPI_COMM_WORLD);
    else
      MPI_Reduce(bytes.data(), out.data(), 1, state, op, 0, MPI_COMM_WORLD);
    MPI_Op_free(&op);
    MPI_Type_free(&state);
    if (!everywhere && rank_ != 0) return {};
    return mc::StudyAccumulator::deserialize(out);
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

std::unique_ptr<Ranks> make_mpi_ranks() { return std::make_unique<MpiRanks>(); }

}  // namespace insmc::app
