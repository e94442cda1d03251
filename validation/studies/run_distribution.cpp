#include "validation/studies/run_distribution.h"

#include <fmt/format.h>
#include <mpi.h>

#include <deque>
#include <thread>

#include "core/error.h"

namespace verity::studies {

namespace {

constexpr int kRecordTag = 19;

void checkCores(const ProcessGroup& group, int threadsPerRun) {
  const int cores = std::max(1, int(std::thread::hardware_concurrency()));
  const int threads = threadsPerRun > 0 ? threadsPerRun : cores;
  if (group.ranksOnThisHost() * threads > cores)
    throw VerityError(
        "", "--threads",
        fmt::format("{} ranks on {} with runs of up to {} threads would use {} threads at once "
                    "on {} cores, and timed runs sharing cores time the sharing: start at most "
                    "{} rank(s) per host (mpirun --map-by ppr:N:node) or use fewer threads",
                    group.ranksOnThisHost(), group.hostName(), threads,
                    group.ranksOnThisHost() * threads, cores, std::max(1, cores / threads)));
}

// Rank 0 decides what is left to do (the other ranks may not see the results file).
std::vector<int> remainingRuns(const ProcessGroup& group, const StudyOutput& output,
                               const std::vector<StudyRun>& runs) {
  std::vector<int> remaining;
  if (group.isRoot())
    for (size_t i = 0; i < runs.size(); ++i)
      if (!output.has(runs[i].record)) remaining.push_back(int(i));
  if (group.distributed()) {
    int n = int(remaining.size());
    MPI_Bcast(&n, 1, MPI_INT, 0, MPI_COMM_WORLD);
    remaining.resize(n);
    MPI_Bcast(remaining.data(), n, MPI_INT, 0, MPI_COMM_WORLD);
  }
  return remaining;
}

nlohmann::json receiveRecord(int rank) {
  MPI_Status status;
  MPI_Probe(rank, kRecordTag, MPI_COMM_WORLD, &status);
  int size = 0;
  MPI_Get_count(&status, MPI_CHAR, &size);
  std::string text(size_t(size), '\0');
  MPI_Recv(text.data(), size, MPI_CHAR, rank, kRecordTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return nlohmann::json::parse(text);
}

}  // namespace

StudyProgress executeRuns(const ProcessGroup& group, int threadsPerRun, StudyOutput& output,
                          std::vector<StudyRun>& runs,
                          const std::function<void(const std::string&)>& log) {
  if (group.distributed()) checkCores(group, threadsPerRun);
  if (group.isRoot()) output.repairTruncatedLine(log);
  const std::vector<int> remaining = remainingRuns(group, output, runs);
  StudyProgress progress;
  progress.total = int(runs.size());
  progress.skipped = progress.total - int(remaining.size());
  auto record = [&](const nlohmann::json& done, const std::string& line) {
    output.append(done);
    ++progress.done;
    if (log) log(fmt::format("[{}/{}] {}", progress.done + progress.skipped, progress.total, line));
  };

  // Sends in flight, kept until they complete.
  std::deque<std::string> sent;
  std::vector<MPI_Request> requests;
  for (size_t k = 0; k < remaining.size(); ++k) {
    const int owner = int(k % size_t(group.size()));
    if (owner == group.rank()) {
      StudyRun& run = runs[remaining[k]];
      nlohmann::json done = run.record;
      std::string line = run.execute(done);
      if (group.distributed()) {
        done["mpi_rank"] = group.rank();
        line = fmt::format("{} (rank {} on {})", line, group.rank(), group.hostName());
      }
      if (group.isRoot()) {
        record(done, line);
      } else {
        ++progress.done;
        sent.push_back(nlohmann::json{{"record", done}, {"log", line}}.dump());
        requests.emplace_back();
        MPI_Isend(sent.back().data(), int(sent.back().size()), MPI_CHAR, 0, kRecordTag,
                  MPI_COMM_WORLD, &requests.back());
      }
    } else if (group.isRoot()) {
      const nlohmann::json message = receiveRecord(owner);
      record(message.at("record"), message.at("log").get<std::string>());
    }
  }
  if (!requests.empty()) MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  return progress;
}

}  // namespace verity::studies
