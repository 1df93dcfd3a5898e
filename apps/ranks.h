#pragma once
/// The processes of one `insmc run`: a single process, or the ranks of an
/// MPI job (only in a build with -DINSMC_MPI=ON, and only when launched by
/// mpirun/srun). Everything MPI stays behind this interface
/// (apps/mpi_ranks.cpp); the default build needs no MPI.
///
/// Every method except rank(), size() and distributed() is collective: all
/// ranks call it, in the same order.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "montecarlo/engine/engine.h"

namespace insmc::app {

class Ranks {
 public:
  virtual ~Ranks() = default;
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
  virtual mc::StudyAccumulator merge(const mc::StudyAccumulator& local, bool everywhere) {
    (void)everywhere;
    return local;
  }
  virtual void barrier() {}
  /// Ends every rank at once after an unexpected error on one of them (the
  /// others may be waiting in a collective). A single process just returns.
  virtual void abort(int exit_code) { (void)exit_code; }
};

/// MPI ranks when this is an MPI build launched by an MPI launcher (Open
/// MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK in the environment),
/// a single process otherwise. MPI is finalized when the object is destroyed.
std::unique_ptr<Ranks> join_ranks();

#ifdef INSMC_MPI
/// apps/mpi_ranks.cpp: MPI_Init_thread (funneled) now, MPI_Finalize at destruction.
std::unique_ptr<Ranks> make_mpi_ranks();
#endif

}  // namespace insmc::app
