// The ranks of an MPI build. A sweep run without a launcher does not start
// MPI at all: a singleton MPI_Init needs a working runtime where none is
// asked for (a laptop, a CI container).
#include <mpi.h>

#include "sweep/ranks.hpp"

namespace sweep {

Ranks::Ranks() {
  if (!launched_by_mpi()) return;
  MPI_Init(nullptr, nullptr);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Ranks::~Ranks() {
  if (mpi_) MPI_Finalize();
}

void Ranks::barrier() {
  if (mpi_) MPI_Barrier(MPI_COMM_WORLD);
}

int Ranks::max_over_ranks(int value) {
  if (!mpi_) return value;
  int out = value;
  MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out;
}

}  // namespace sweep
