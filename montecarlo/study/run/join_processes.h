#pragma once
/// The processes of one `insmc run`: a single process, or the ranks of an
/// MPI job (only in a build with -DINSMC_MPI=ON, and only when launched by
/// mpirun/srun). The interface the study runner uses is
/// montecarlo/study/run/processes.h; MPI stays in mpi_processes.cpp, which
/// only the MPI build compiles, so the default build needs no MPI.
#include <memory>

#include "montecarlo/study/run/processes.h"

namespace insmc::mc {

/// MPI ranks when this is an MPI build launched by an MPI launcher (Open
/// MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK in the environment),
/// a single process otherwise. MPI is finalized when the object is destroyed.
std::unique_ptr<Processes> join_processes();

#ifdef INSMC_MPI
/// mpi_processes.cpp: MPI_Init_thread (funneled) now, MPI_Finalize at destruction.
std::unique_ptr<Processes> make_mpi_processes();
#endif

}  // namespace insmc::mc
