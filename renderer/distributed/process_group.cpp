#include "distributed/process_group.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace verity {

namespace {
std::string localHostName() {
  char host[256] = {};
  return gethostname(host, sizeof host - 1) == 0 ? host : "unknown";
}
}  // namespace

ProcessGroup::ProcessGroup() : hostName_(localHostName()) {}

ProcessGroup::ProcessGroup(int& argc, char**& argv) : hostName_(localHostName()) {
  if (!launchedByMpi()) return;
  // Only the main thread calls MPI; TBB's workers never do.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialized_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm host;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &host);
  MPI_Comm_size(host, &ranksOnHost_);
  MPI_Comm_free(&host);
}

ProcessGroup::~ProcessGroup() {
  if (initialized_) MPI_Finalize();
}

const ProcessGroup& ProcessGroup::solo() {
  static const ProcessGroup group;
  return group;
}

bool ProcessGroup::launchedByMpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(variable)) return true;
  return false;
}

int ProcessGroup::threadsPerRank(int asked) const {
  if (asked > 0 || !distributed()) return asked;
  return std::max(1, int(std::thread::hardware_concurrency()) / ranksOnHost_);
}

void ProcessGroup::abort(int code) const {
  if (initialized_) MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

}  // namespace verity
