#pragma once
// Running the steps of a pipeline run stage by stage on this machine: each stage's steps run as
// child processes, several at once; with resume, steps done before from the same inputs are
// kept (Resume.hpp). The step times are collected for the report.
#include <string>
#include <utility>
#include <vector>

#include "slamroute/pipeline/Steps.hpp"

namespace slamroute::pipeline {

class StageRunner {
 public:
  StageRunner(bool resume, double status_every_s)
      : resume_(resume), status_every_s_(status_every_s) {}

  /// Runs the steps not kept, `jobs` at once; throws like runSteps.
  void run(const std::vector<Step>& steps, int jobs);

  /// Seconds per step label in the order run; NaN for a step kept from an earlier run.
  const std::vector<std::pair<std::string, double>>& times() const { return times_; }

 private:
  bool resume_;
  double status_every_s_;
  std::vector<std::pair<std::string, double>> times_;
};

/// Survey of `net` and the road graph built from it (one step each).
void surveyAndGraph(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                    const std::string& net);

/// Plans every request, `jobs` at once: first those without a budget, then the budgeted ones
/// with the length of the route they are budgeted from.
void planRoutes(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                const std::vector<PlanRequest>& requests, int jobs);

/// Drives of the routes `ids` (`seeds[i]` the child seed of ids[i]; empty: the options' seed).
void driveRoutes(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                 const std::string& net, const std::vector<std::string>& ids,
                 const std::vector<long long>& seeds, bool save_scans, int jobs);

/// SLAM evaluation of the drives `ids`, longest route first, as many at once as `slam_jobs`
/// (0: as many of `max_auto` as the memory holds; slamJobsToUse).
void evaluateDrives(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                    const std::vector<std::string>& ids, const std::vector<long long>& seeds,
                    int slam_jobs, int max_auto, bool clouds_on_disk);

}  // namespace slamroute::pipeline
