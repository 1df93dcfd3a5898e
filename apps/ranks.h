#pragma once
/// The processes of one `insmc run`: a single process, or the ranks of an
/// MPI job (only in a build with -DINSMC_MPI=ON, and only when launched by
/// mpirun/srun). The interface the study runner uses is
/// montecarlo/study/run/ranks.h; MPI stays in apps/mpi_ranks.cpp, so the default
/// build needs no MPI.
#include <memory>

#include "montecarlo/study/run/ranks.h"

namespace insmc::app {

using mc::Ranks;

/// MPI ranks when this is an MPI build launched by an MPI launcher (Open
/// MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK in the environment),
/// a single process otherwise. MPI is finalized when the object is destroyed.
std::unique_ptr<Ranks> join_ranks();

#ifdef INSMC_MPI
/// apps/mpi_ranks.cpp: MPI_Init_thread (funneled) now, MPI_Finalize at destruction.
std::unique_ptr<Ranks> make_mpi_ranks();
#endif

}  // namespace insmc::app
