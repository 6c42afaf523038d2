#pragma once
// `slamroute sweep`: a study's task graph (SweepTasks.hpp) run on every rank of a Cluster. Rank 0
// schedules: it starts ready tasks longest first on free slots (its own and the other ranks'),
// within the memory each rank reported, keeps the tasks done before (--resume), stamps each
// task that succeeds, retries a failed task once, and re-queues the tasks of a rank that has gone
// silent. The other ranks run the tasks they are sent as child processes and report back.
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/pipeline/Cluster.hpp"
#include "slamroute/pipeline/SweepQueue.hpp"
#include "slamroute/pipeline/SweepTasks.hpp"

namespace slamroute::pipeline {

struct SweepOptions {
  int jobs_per_rank = 1;         ///< tasks a rank runs at once
  bool resume = false;           ///< keep tasks done before from the same inputs
  double worker_timeout_s = 30;  ///< a rank silent this long is taken for dead
  int max_attempts = 2;          ///< a failed task runs once more
};

/// Where each task ended, for the results.
struct SweepOutcome {
  std::vector<SweepTask> tasks;
  std::vector<TaskStatus> status;  ///< per task
  double seconds = 0.0;            ///< wall time of the whole sweep
  int ranks = 1;
  /// The SIGINT / SIGTERM / SIGHUP that stopped the sweep (0: it ran to the end). Its running
  /// tasks were stopped with it and are left unfinished, like the ones not started.
  int interrupted_by = 0;
};

/// Rank 0: runs `tasks` to the end (or until a stop signal) over the cluster's ranks and tells
/// the others to stop.
SweepOutcome scheduleSweep(Cluster& cluster, std::vector<SweepTask> tasks,
                           const SweepOptions& opts);

/// Ranks > 0: runs the tasks rank 0 sends until it says stop (or goes silent for
/// `worker_timeout_s`). Writes its pid to `out`/workers/rank<R>.pid.
void serveSweep(Cluster& cluster, const std::filesystem::path& out, const SweepOptions& opts);

}  // namespace slamroute::pipeline
