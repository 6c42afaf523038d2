#include "slamroute/pipeline/SweepResults.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <set>
#include <sstream>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/evaluate/EvaluationResult.hpp"
#include "slamroute/pipeline/JsonFile.hpp"
#include "slamroute/pipeline/Plot.hpp"
#include "slamroute/pipeline/Statistics.hpp"

namespace slamroute::pipeline {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool isTiming(const std::string& key) {
  return key.find("seconds") != std::string::npos || key.find("timing") != std::string::npos ||
         key.find("per_s") != std::string::npos;
}

void flatten(const json& j, const std::string& prefix, std::map<std::string, double>& out) {
  for (const auto& [k, v] : j.items()) {
    const std::string key = prefix + k;
    if (isTiming(key)) continue;
    if (v.is_object())
      flatten(v, key + ".", out);
    else if (v.is_number())
      out[key] = v.get<double>();
    else if (v.is_boolean())
      out[key] = v.get<bool>() ? 1.0 : 0.0;
  }
}

/// "ok", or the name of the row's first task that did not succeed.
std::string rowStatus(const SweepRow& row, const SweepOutcome& o, const fs::path& out) {
  const fs::path dir = rowLayout(out, row).out;
  for (std::size_t i = 0; i < o.tasks.size(); ++i) {
    const SweepTask& t = o.tasks[i];
    const bool of_row = t.run.out == dir && (t.kind == TaskKind::Survey ||
                                             t.kind == TaskKind::Graph || t.plan.id == row.planner);
    if (of_row && o.status[i].state != TaskState::Done) return "failed: " + t.name;
  }
  return "ok";
}

/// The evaluation's figures as "eval.<key>" columns (none when the evaluation did not finish).
void addEvaluationFigures(const fs::path& metrics, std::map<std::string, double>& out) {
  if (!fs::exists(metrics)) return;
  for (const auto& [k, v] : evaluate::evaluationFigures(evaluate::readEvaluationJson(metrics)))
    out["eval." + k] = v;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string groupName(const SweepRow& r) {
  return netStem(r.net) + " / " + r.variant + " / " + r.planner;
}

}  // namespace

std::vector<RowResult> collectResults(const std::vector<SweepRow>& rows,
                                      const SweepOutcome& outcome, const fs::path& out) {
  std::vector<RowResult> res;
  for (const auto& row : rows) {
    RowResult r{row, rowStatus(row, outcome, out), {}};
    const RunLayout run = rowLayout(out, row);
    json route = readJsonIfPresent(run.route(row.planner));
    route.erase("extra");  // the planners' own statistics: names differ between planners
    flatten(route, "route.", r.metrics);
    addEvaluationFigures(run.metrics(row.planner), r.metrics);
    res.push_back(std::move(r));
  }
  return res;
}

namespace {

std::string resultsCsv(const std::vector<RowResult>& results) {
  std::set<std::string> keys;
  for (const auto& r : results)
    for (const auto& [k, v] : r.metrics) keys.insert(k);
  std::ostringstream csv;
  csv << "net,variant,planner,seed,status";
  for (const auto& k : keys) csv << "," << k;
  csv << "\n";
  for (const auto& r : results) {
    csv << netStem(r.row.net) << "," << r.row.variant << "," << r.row.planner << "," << r.row.seed
        << "," << r.status;
    for (const auto& k : keys) {
      const auto it = r.metrics.find(k);
      csv << "," << (it == r.metrics.end() ? std::string() : num(it->second));
    }
    csv << "\n";
  }
  return csv.str();
}

struct Headline {
  const char* key;
  const char* name;
  int decimals;
};
const std::vector<Headline> kHeadlines = {
    {"eval.ate_rmse_m", "ATE RMSE [m]", 3},
    {"eval.ate_mean_m", "ATE mean [m]", 3},
    {"eval.rpe_trans_pct", "RPE [%]", 2},
    {"eval.loop_closures", "loop closures", 1},
    {"eval.map_aligned_median_dist_m", "map error, aligned, median [m]", 3},
    {"route.length_m", "route length [m]", 0},
    {"route.edge_coverage_pct", "edge coverage [%]", 1}};

/// The groups (net / variant / planner) in the order of the rows, with their successful rows.
std::vector<std::pair<std::string, std::vector<const RowResult*>>> groups(
    const std::vector<RowResult>& results) {
  std::vector<std::pair<std::string, std::vector<const RowResult*>>> g;
  for (const auto& r : results) {
    const std::string name = groupName(r.row);
    auto it = std::find_if(g.begin(), g.end(), [&](const auto& x) { return x.first == name; });
    if (it == g.end()) it = g.insert(g.end(), {name, {}});
    if (r.status == "ok") it->second.push_back(&r);
  }
  return g;
}

std::vector<double> values(const std::vector<const RowResult*>& rows, const std::string& key) {
  std::vector<double> v;
  for (const auto* r : rows)
    if (auto it = r->metrics.find(key); it != r->metrics.end()) v.push_back(it->second);
  return v;
}

std::string summaryTable(const std::vector<RowResult>& results) {
  std::ostringstream md;
  md << "| net / variant / planner | runs |";
  for (const auto& h : kHeadlines) md << " " << h.name << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < kHeadlines.size(); ++i) md << "---|";
  md << "\n";
  for (const auto& [name, rows] : groups(results)) {
    md << "| " << name << " | " << rows.size() << " |";
    for (const auto& h : kHeadlines)
      md << " " << formatMeanSd(meanSd(values(rows, h.key)), h.decimals) << " |";
    md << "\n";
  }
  return md.str();
}

/// One plot per headline metric: every successful run's value over its group.
std::string summaryPlots(const std::vector<RowResult>& results, const fs::path& out) {
  const auto g = groups(results);
  std::vector<std::string> ticks;
  for (std::size_t i = 0; i < g.size(); ++i) ticks.push_back(std::to_string(i + 1));
  std::ostringstream md;
  md << "Groups in the plots: ";
  for (std::size_t i = 0; i < g.size(); ++i) md << (i ? ", " : "") << i + 1 << " = " << g[i].first;
  md << ".\n\n";
  fs::create_directories(out / "summary");
  for (const auto& h : kHeadlines) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < g.size(); ++i)
      for (double v : values(g[i].second, h.key)) {
        x.push_back(static_cast<double>(i));
        y.push_back(v);
      }
    if (x.empty()) continue;
    const std::string png = std::string(h.key).substr(std::string(h.key).find('.') + 1) + ".png";
    scatterPng(out / "summary" / png, x, y, "group (one dot per seed)", h.name, ticks);
    md << "![" << h.name << "](summary/" << png << ")\n\n";
  }
  return md.str();
}

const char* stateName(TaskState s) {
  switch (s) {
    case TaskState::Waiting:
      return "waiting";
    case TaskState::Ready:
      return "ready";
    case TaskState::Running:
      return "running";
    case TaskState::Done:
      return "done";
    case TaskState::Failed:
      return "failed";
    case TaskState::Skipped:
      return "skipped";
  }
  return "?";
}

/// One line per task: how it ended, its starts and the run time of its successful start.
std::string tasksCsv(const SweepOutcome& o) {
  std::ostringstream csv;
  csv << "task,state,attempts,kept,seconds\n";
  for (std::size_t i = 0; i < o.tasks.size(); ++i) {
    const TaskStatus& s = o.status[i];
    csv << o.tasks[i].name << "," << stateName(s.state) << "," << s.attempts << ","
        << (s.kept ? 1 : 0) << "," << num(s.seconds) << "\n";
  }
  return csv.str();
}

std::string failedList(const SweepOutcome& o) {
  std::ostringstream txt;
  for (std::size_t i = 0; i < o.tasks.size(); ++i) {
    const TaskStatus& s = o.status[i];
    if (s.state == TaskState::Failed)
      txt << o.tasks[i].name << ": failed after " << s.attempts << " attempts: " << s.error << "\n";
    else if (s.state == TaskState::Skipped)
      txt << o.tasks[i].name << ": " << s.error << "\n";
    else if (s.state != TaskState::Done)
      txt << o.tasks[i].name << ": not finished (the sweep was stopped by "
          << strsignal(o.interrupted_by) << ")\n";
  }
  return txt.str();
}

/// How the tasks went: run, kept, retried, failed.
std::string taskCounts(const SweepOutcome& o) {
  int ran = 0, kept = 0, retried = 0, failed = 0;
  for (const auto& s : o.status) {
    if (s.state == TaskState::Done) ++(s.kept ? kept : ran);
    if (s.state == TaskState::Done && s.attempts > 1) ++retried;
    if (s.state != TaskState::Done) ++failed;
  }
  char buf[256];
  std::snprintf(
      buf, sizeof buf,
      "%zu tasks on %d rank(s) in %.0f s: %d done (%d kept from an earlier sweep, %d after a "
      "retry), %d failed or not run (failed_tasks.txt)",
      o.tasks.size(), o.ranks, o.seconds, ran + kept, kept, retried, failed);
  return buf;
}

}  // namespace

void writeSweepResults(const std::vector<RowResult>& results, const SweepOutcome& outcome,
                       const fs::path& out, const std::string& command) {
  writeFileAtomic(out / "results.csv", resultsCsv(results));
  writeFileAtomic(out / "failed_tasks.txt", failedList(outcome));
  writeFileAtomic(out / "tasks.csv", tasksCsv(outcome));
  std::ostringstream md;
  md << "# Sweep summary\n\nCommand: `" << command << "`  \n"
     << taskCounts(outcome)
     << ".\n\nMean ± sample standard deviation over the seeds of each net, config variant and "
        "planner (runs: rows whose every task succeeded; every metric of every row is in "
        "results.csv).\n\n"
     << summaryTable(results) << "\n"
     << summaryPlots(results, out);
  writeFileAtomic(out / "summary.md", md.str());
}

}  // namespace slamroute::pipeline
