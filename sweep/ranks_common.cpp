#include <cstdlib>
#include <initializer_list>

#include "sweep/ranks.hpp"

namespace sweep {

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace sweep
