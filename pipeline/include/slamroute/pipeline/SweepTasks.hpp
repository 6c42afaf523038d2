#pragma once
// A sweep's work as a task graph: per net, variant and seed one survey and one road graph,
// shared by the planners; per planner a plan (the random walk after the same group's Q-learning
// plan: its budget), a drive and a SLAM evaluation. Each task is a pipeline step run as a child
// process; its files go to OUT/<net>/<variant>/s<seed>/ laid out like a `run` folder.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/pipeline/Steps.hpp"
#include "slamroute/pipeline/SweepSpec.hpp"

namespace slamroute::pipeline {

enum class TaskKind { Survey, Graph, Plan, Drive, Evaluate };

struct SweepTask {
  std::string name;  ///< unique and readable: "<net>/<variant>/s<seed>/plan qlearning"
  TaskKind kind = TaskKind::Survey;
  std::vector<std::size_t> deps;  ///< tasks that must have succeeded first
  RunLayout run;                  ///< the group's folder
  ChildOptions opts;              ///< seed and variant config of the group
  std::string net;                ///< absolute path of the net
  PlanRequest plan;               ///< the route (plan, drive, evaluate tasks)
  double net_mb = 0.0;            ///< size of the net file: scales the time estimate
};

/// The tasks of `rows` under `out`, dependencies before dependents. `global` carries the sweep
/// command's log level and config file (used where a variant names none); seeds are the rows'.
std::vector<SweepTask> sweepTasks(const SweepSpec& spec, const std::vector<SweepRow>& rows,
                                  const std::filesystem::path& out, const ChildOptions& global);

/// The group folder of a row (OUT/<net>/<variant>/s<seed>).
RunLayout rowLayout(const std::filesystem::path& out, const SweepRow& row);

/// The step of a task whose dependencies have succeeded (a budgeted plan reads the length of the
/// route it is budgeted from).
Step taskStep(const SweepTask& t);

/// Estimated run time of a task [relative units], for longest-first scheduling: the kind's
/// weight times the net's size; a drive and its SLAM run grow with the planned route's length
/// once it is known.
double taskCost(const SweepTask& t);

/// Estimated peak memory of a task [GB]: the SLAM estimate (Memory.hpp) for an evaluation of a
/// planned route, 0.3 GB for the other steps.
double taskMemoryGb(const SweepTask& t);

}  // namespace slamroute::pipeline
