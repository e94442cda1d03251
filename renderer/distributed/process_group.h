// The processes that render one job together: MPI's world when a launcher (mpirun, srun)
// started this process, else a group of one that never calls MPI. MPI costs nothing unless
// asked for: a process that no launcher started does not call MPI_Init.
#pragma once

#include <string>

namespace verity {

class ProcessGroup {
 public:
  // A group of this process alone; MPI is not touched.
  ProcessGroup();
  // Joins the launcher's job (MPI_Init; MPI_Finalize on destruction) when launchedByMpi(),
  // else a group of one.
  ProcessGroup(int& argc, char**& argv);
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  // The group of one, for callers that run alone (tests, single-process paths).
  static const ProcessGroup& solo();
  // Whether a launcher started this process. Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE in
  // every process; Slurm's srun sets PMIX_RANK (--mpi=pmix) or PMI_SIZE (--mpi=pmi2).
  // SLURM_PROCID is not enough: a batch script's own step has it too.
  static bool launchedByMpi();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }
  bool distributed() const { return size_ > 1; }
  const std::string& hostName() const { return hostName_; }
  // Ranks of this job on this host (MPI_COMM_TYPE_SHARED), this one included.
  int ranksOnThisHost() const { return ranksOnHost_; }
  // Worker threads for a rank asked for `asked` (0: all cores): as asked, else the host's
  // cores shared among the job's ranks on it.
  int threadsPerRank(int asked) const;
  // Ends every process of the job with `code` (MPI_Abort), or this one alone.
  [[noreturn]] void abort(int code) const;

 private:
  bool initialized_ = false;
  int rank_ = 0, size_ = 1, ranksOnHost_ = 1;
  std::string hostName_;
};

}  // namespace verity
