#include "slamroute/pipeline/SweepTasks.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "slamroute/pipeline/Memory.hpp"

namespace slamroute::pipeline {
namespace fs = std::filesystem;

RunLayout rowLayout(const fs::path& out, const SweepRow& row) {
  return {out / netStem(row.net) / row.variant / ("s" + std::to_string(row.seed))};
}

namespace {

using GroupKey = std::tuple<std::string, std::string, std::uint64_t>;

struct Builder {
  const SweepSpec& spec;
  fs::path out;
  ChildOptions global;  // the sweep command's own options: config when a variant has none
  std::vector<SweepTask> tasks;
  std::map<GroupKey, std::size_t> graph_of;                         // group -> its graph task
  std::map<std::pair<GroupKey, std::string>, std::size_t> plan_of;  // (group, planner) -> plan task

  std::size_t add(SweepTask t) {
    tasks.push_back(std::move(t));
    return tasks.size() - 1;
  }

  SweepTask base(const SweepRow& row, TaskKind kind, const std::string& what) const {
    SweepTask t;
    t.kind = kind;
    t.run = rowLayout(out, row);
    t.name = fs::relative(t.run.out, out).string() + "/" + what;
    t.opts = global;
    t.opts.seed = row.seed;
    const std::string& config = spec.variant(row.variant).config_file;
    if (!config.empty()) t.opts.config_file = config;
    t.net = row.net;
    std::error_code ec;
    t.net_mb = static_cast<double>(fs::file_size(row.net, ec)) / 1e6;
    return t;
  }

  /// The group's graph task, adding the survey and graph on first use.
  std::size_t graphTask(const SweepRow& row) {
    const GroupKey key{row.net, row.variant, row.seed};
    if (auto it = graph_of.find(key); it != graph_of.end()) return it->second;
    const std::size_t survey = add(base(row, TaskKind::Survey, "survey"));
    SweepTask g = base(row, TaskKind::Graph, "build-graph");
    g.deps = {survey};
    return graph_of[key] = add(std::move(g));
  }

  std::size_t planTask(const SweepRow& row, const std::vector<SweepRow>& rows) {
    const GroupKey key{row.net, row.variant, row.seed};
    if (auto it = plan_of.find({key, row.planner}); it != plan_of.end()) return it->second;
    SweepTask p = base(row, TaskKind::Plan, "plan " + row.planner);
    p.plan.id = p.plan.planner = row.planner;
    p.deps = {graphTask(row)};
    SweepRow q = row;
    q.planner = "qlearning";
    if (row.planner == "random" && std::find(rows.begin(), rows.end(), q) != rows.end()) {
      p.plan.budget_from = "qlearning";
      p.deps.push_back(planTask(q, rows));
    }
    return plan_of[{key, row.planner}] = add(std::move(p));
  }

  void addRow(const SweepRow& row, const std::vector<SweepRow>& rows) {
    const std::size_t plan = planTask(row, rows);
    SweepTask d = base(row, TaskKind::Drive, "drive " + row.planner);
    d.plan = tasks[plan].plan;
    d.deps = {plan};
    const std::size_t drive = add(d);
    SweepTask e = base(row, TaskKind::Evaluate, "evaluate " + row.planner);
    e.plan = d.plan;
    e.deps = {drive};
    add(std::move(e));
  }
};

}  // namespace

std::vector<SweepTask> sweepTasks(const SweepSpec& spec, const std::vector<SweepRow>& rows,
                                  const fs::path& out, const ChildOptions& global) {
  Builder b{spec, out, global, {}, {}, {}};
  for (const auto& row : rows) b.addRow(row, rows);
  return std::move(b.tasks);
}

Step taskStep(const SweepTask& t) {
  switch (t.kind) {
    case TaskKind::Survey:
      return surveyStep(t.opts, t.run, t.net);
    case TaskKind::Graph:
      return buildGraphStep(t.opts, t.run, t.net);
    case TaskKind::Plan:
      return budgetedPlanStep(t.opts, t.run, t.plan);
    case TaskKind::Drive:
      return driveStep(t.opts, t.run, t.net, t.plan.id);
    case TaskKind::Evaluate:
      return evaluateStep(t.opts, t.run, t.plan.id);
  }
  throw std::logic_error("unknown task kind");
}

namespace {

/// The planned route's length [km], 0 before it exists.
double plannedKm(const SweepTask& t) {
  std::error_code ec;
  if (!fs::exists(t.run.route(t.plan.id), ec)) return 0.0;
  return routeLength(t.run.route(t.plan.id)) / 1000.0;
}

}  // namespace

double taskCost(const SweepTask& t) {
  // Weights from the step times of `run` on the default city (report.md, "Step times"): the SLAM
  // run dominates, then the drive, the survey, planning and the graph.
  switch (t.kind) {
    case TaskKind::Survey:
      return 4.0 * t.net_mb;
    case TaskKind::Graph:
      return 1.0 * t.net_mb;
    case TaskKind::Plan:
      return (t.plan.planner == "qlearning" ? 3.0 : 1.0) * t.net_mb;
    case TaskKind::Drive:
      return 5.0 * t.net_mb + 1.0 * plannedKm(t);
    case TaskKind::Evaluate:
      return 10.0 * t.net_mb + 4.0 * plannedKm(t);
  }
  return 0.0;
}

double taskMemoryGb(const SweepTask& t) {
  if (t.kind != TaskKind::Evaluate) return 0.3;
  return slamMemoryGb(plannedKm(t));
}

}  // namespace slamroute::pipeline
