#include "apps/ranks.h"

#include <cstdlib>

namespace insmc::app {

std::unique_ptr<Ranks> join_ranks() {
#ifdef INSMC_MPI
  for (const char* launcher_variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(launcher_variable) != nullptr) return make_mpi_ranks();
#endif
  return std::make_unique<Ranks>();
}

}  // namespace insmc::app
