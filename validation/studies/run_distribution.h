// A study as a list of independent runs, and their execution: in this process, or dealt
// round-robin over the ranks of an MPI job (mpirun, srun). Either way the runs already in the
// results file are skipped, and one process, rank 0, appends every record, in list order.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "distributed/process_group.h"
#include "validation/studies/study_records.h"

namespace verity::studies {

struct StudyRun {
  nlohmann::json record;  // the fields its key is drawn from
  // Renders the run, completes `record` and returns the run's line for the log.
  std::function<std::string(nlohmann::json& record)> execute;
};

// Runs what `output` does not hold yet. With several ranks, refuses (VerityError) when the
// ranks on one host would run more threads at once than it has cores (`threadsPerRun`: the
// most a run uses), since timed runs sharing cores would time the sharing. Records made
// elsewhere than rank 0 say so in "mpi_rank"; their "hostname" is where they ran. `log` (rank
// 0 only) gets "[i/total] " and the run's line. Returns what this process did (rank 0: all).
StudyProgress executeRuns(const ProcessGroup& group, int threadsPerRun, StudyOutput& output,
                          std::vector<StudyRun>& runs,
                          const std::function<void(const std::string&)>& log);

}  // namespace verity::studies
