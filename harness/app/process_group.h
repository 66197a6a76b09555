// The processes of one `crowdsim-bench run`: one, or the ranks of an MPI job when the CLI is
// built with MPI (CROWDSIM_HAVE_MPI) and started by mpirun/srun. Nothing else in the CLI knows
// about MPI.
#pragma once

namespace crowdsim::cli {

class ProcessGroup {
 public:
  /// Joins the MPI job this process was launched in (initialising MPI), or stands alone.
  ProcessGroup();
  ~ProcessGroup();  ///< leaves the job (MPI_Finalize)
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// True when every process passes true (a collective call: every rank must make it).
  bool AllOk(bool ok) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
};

/// Whether this build can run over MPI ranks.
bool BuiltWithMpi();

}  // namespace crowdsim::cli
