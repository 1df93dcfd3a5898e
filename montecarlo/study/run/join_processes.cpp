#include "montecarlo/study/run/join_processes.h"

#include <cstdlib>

namespace insmc::mc {

std::unique_ptr<Processes> join_processes() {
#ifdef INSMC_MPI
  for (const char* launcher_variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(launcher_variable) != nullptr) return make_mpi_processes();
#endif
  return std::make_unique<Processes>();
}

}  // namespace insmc::mc
