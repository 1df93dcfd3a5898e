#pragma once
/// The processes of one study run (montecarlo/study/run/study_runner.h): a
/// single process, as this class is, or the ranks of an MPI job
/// (join_processes.h; mpi_processes.cpp, only in the MPI build). Everything
/// MPI stays behind this interface; the rest of the library needs no MPI.
///
/// Every method except rank(), size() and distributed() is collective: all
/// ranks call it, in the same order.
#include <cstdint>
#include <string>
#include <vector>

#include "montecarlo/study/engine/engine.h"

namespace insmc::mc {

class Processes {
 public:
  virtual ~Processes() = default;
  /// This process's rank, 0 ≤ rank < size; rank 0 prints and writes files.
  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }
  /// True under MPI (even with one rank): run.json then records the ranks.
  virtual bool distributed() const { return false; }
  bool root() const { return rank() == 0; }

  /// Element-wise maximum over the ranks, returned on every rank.
  virtual std::vector<std::int64_t> max_all(std::vector<std::int64_t> values) { return values; }
  /// Rank 0's bytes, on every rank.
  virtual std::string broadcast(std::string bytes) { return bytes; }
  /// `value` of every rank, in rank order, on rank 0 (empty elsewhere).
  virtual std::vector<std::uint64_t> gather(std::uint64_t value) { return {value}; }
  /// The merge of every rank's accumulator (all of the same study), on
  /// rank 0, or on every rank when `everywhere`; an empty accumulator on
  /// the other ranks. The merge is exact, so the result does not depend on
  /// the reduction tree.
  virtual StudyAccumulator merge(const StudyAccumulator& local, bool everywhere) {
    (void)everywhere;
    return local;
  }
  virtual void barrier() {}
  /// Ends every rank at once after an unexpected error on one of them (the
  /// others may be waiting in a collective). A single process just returns.
  virtual void abort(int exit_code) { (void)exit_code; }
};

}  // namespace insmc::mc
