#include "slamroute/pipeline/Stages.hpp"

#include <algorithm>
#include <cmath>

#include "slamroute/pipeline/Memory.hpp"
#include "slamroute/pipeline/Resume.hpp"

namespace slamroute::pipeline {

void StageRunner::run(const std::vector<Step>& steps, int jobs) {
  const std::vector<Step> todo = stepsToRun(steps, resume_);
  const std::vector<StepResult> res = runSteps(todo, jobs, status_every_s_);
  for (const auto& st : steps) {
    double sec = std::nan("");
    for (std::size_t i = 0; i < todo.size(); ++i)
      if (todo[i].label == st.label) sec = res[i].seconds;
    times_.emplace_back(st.label, sec);
  }
}

void surveyAndGraph(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                    const std::string& net) {
  stages.run({surveyStep(opts, run, net)}, 1);
  stages.run({buildGraphStep(opts, run, net)}, 1);
}

void planRoutes(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                const std::vector<PlanRequest>& requests, int jobs) {
  std::vector<Step> free;
  for (const auto& r : requests)
    if (r.budget_from.empty()) free.push_back(planStep(opts, run, r));
  stages.run(free, jobs);
  std::vector<Step> budgeted;
  for (const auto& r : requests)
    if (!r.budget_from.empty()) budgeted.push_back(budgetedPlanStep(opts, run, r));
  if (!budgeted.empty()) stages.run(budgeted, jobs);
}

namespace {

long long seedOf(const std::vector<long long>& seeds, std::size_t i) {
  return i < seeds.size() ? seeds[i] : -1;
}

}  // namespace

void driveRoutes(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                 const std::string& net, const std::vector<std::string>& ids,
                 const std::vector<long long>& seeds, bool save_scans, int jobs) {
  std::vector<Step> steps;
  for (std::size_t i = 0; i < ids.size(); ++i)
    steps.push_back(driveStep(opts, run, net, ids[i], save_scans, seedOf(seeds, i)));
  stages.run(steps, jobs);
}

void evaluateDrives(StageRunner& stages, const ChildOptions& opts, const RunLayout& run,
                    const std::vector<std::string>& ids, const std::vector<long long>& seeds,
                    int slam_jobs, int max_auto, bool clouds_on_disk) {
  std::vector<Step> steps;
  std::vector<double> lengths;
  for (const auto& id : longestRouteFirst(run, ids)) {
    const auto at = static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
    steps.push_back(evaluateStep(opts, run, id, seedOf(seeds, at)));
    lengths.push_back(routeLength(run.route(id)));
  }
  stages.run(steps, slamJobsToUse(lengths, slam_jobs, max_auto, clouds_on_disk));
}

}  // namespace slamroute::pipeline
