// The ranks of a build without MPI: one process. Under a launcher with more
// than one process each would run every member into the same folders, so
// that is refused.
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "sweep/ranks.hpp"

namespace sweep {

Ranks::Ranks() {
  const char* n = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (!n) n = std::getenv("PMI_SIZE");
  if (n && std::atoi(n) > 1)
    throw std::runtime_error(std::string("started as one of ") + n +
                             " MPI processes, but this landslide was built without MPI "
                             "(install libopenmpi-dev and rebuild)");
}

Ranks::~Ranks() = default;
void Ranks::barrier() {}
int Ranks::max_over_ranks(int value) { return value; }

}  // namespace sweep
