#include "process_group.h"

#include <cstdlib>
#include <initializer_list>

#ifdef CROWDSIM_HAVE_MPI
#include <mpi.h>
#endif

namespace crowdsim::cli {

namespace {

/// Launched by an MPI starter: OpenMPI's mpirun, MPICH's Hydra, or Slurm's srun with PMIx.
bool LaunchedByMpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(var) != nullptr) return true;
  }
  return false;
}

}  // namespace

ProcessGroup::ProcessGroup() {
#ifdef CROWDSIM_HAVE_MPI
  if (!LaunchedByMpi()) return;
  int provided = 0;
  // Worker threads never call MPI: only the main thread does.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
  (void)LaunchedByMpi;
#endif
}

ProcessGroup::~ProcessGroup() {
#ifdef CROWDSIM_HAVE_MPI
  if (mpi_) MPI_Finalize();
#endif
}

bool ProcessGroup::AllOk(bool ok) const {
#ifdef CROWDSIM_HAVE_MPI
  if (mpi_) {
    int mine = ok ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return all == 1;
  }
#endif
  return ok;
}

bool BuiltWithMpi() {
#ifdef CROWDSIM_HAVE_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace crowdsim::cli
