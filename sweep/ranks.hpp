// The processes a sweep is spread over. Built with MPI (CMake found it:
// ranks_mpi.cpp), a sweep started by an MPI launcher (mpirun, srun) has one
// rank per process; started without one, or built without MPI
// (ranks_serial.cpp), it is one process of rank 0. Only `landslide sweep`
// makes one, so no other command starts MPI.
#pragma once

namespace sweep {

class Ranks {
 public:
  Ranks();   // MPI_Init when launched by mpirun or srun (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK)
  ~Ranks();  // MPI_Finalize
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  void barrier();
  // The largest of `value` over all ranks, on every rank.
  int max_over_ranks(int value);

 private:
  int rank_ = 0, size_ = 1;
  bool mpi_ = false;
};

// Whether an MPI launcher started this process (its environment says so).
bool launched_by_mpi();

}  // namespace sweep
