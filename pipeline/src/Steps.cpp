#include "slamroute/pipeline/Steps.hpp"

#include <algorithm>
#include <sstream>

#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoCoverage.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/SumoRoute.hpp"

namespace slamroute::pipeline {
namespace fs = std::filesystem;

Step childStep(const ChildOptions& opts, const std::string& label, std::vector<std::string> args,
               const fs::path& log, long long seed) {
  std::vector<std::string> full{
      "--seed", std::to_string(seed >= 0 ? static_cast<std::uint64_t>(seed) : opts.seed),
      "--log-level", opts.debug_log ? "debug" : "info"};
  if (!opts.config_file.empty()) {
    full.push_back("--config");
    full.push_back(opts.config_file);
  }
  full.insert(full.end(), args.begin(), args.end());
  return {label, full, log};
}

Step surveyStep(const ChildOptions& opts, const RunLayout& run, const std::string& net) {
  Step s = childStep(opts, "survey", {"survey", "--net", net, "--out", run.survey().string()},
                     run.logs() / "survey.log");
  s.output = run.survey() / "survey.json";  // the folder appears complete
  return s;
}

Step buildGraphStep(const ChildOptions& opts, const RunLayout& run, const std::string& net) {
  Step s = childStep(opts, "build-graph",
                     {"build-graph", "--survey", run.survey().string(), "--net", net, "--out",
                      run.graph().string()},
                     run.logs() / "build-graph.log");
  s.output = fs::path(run.graph()).replace_extension(".png");  // the last of graph.json's siblings
  return s;
}

Step planStep(const ChildOptions& opts, const RunLayout& run, const PlanRequest& req,
              std::optional<double> max_length_m) {
  std::vector<std::string> a{"plan", "--graph", run.graph().string(), "--planner", req.planner};
  if (!req.reward.empty()) a.insert(a.end(), {"--reward", req.reward});
  a.insert(a.end(), {"--out", run.route(req.id).string()});
  if (max_length_m) a.insert(a.end(), {"--max-length", std::to_string(*max_length_m)});
  if (req.vehicles > 1) a.insert(a.end(), {"--vehicles", std::to_string(req.vehicles)});
  Step s = childStep(opts, "plan " + req.id, a, run.logs() / ("plan-" + req.id + ".log"), req.seed);
  s.output = run.route(req.id);
  return s;
}

Step budgetedPlanStep(const ChildOptions& opts, const RunLayout& run, const PlanRequest& req) {
  if (req.budget_from.empty()) return planStep(opts, run, req);
  return planStep(opts, run, req, routeLength(run.route(req.budget_from)));
}

Step driveStep(const ChildOptions& opts, const RunLayout& run, const std::string& net,
               const std::string& id, bool save_scans, long long seed) {
  std::vector<std::string> a{
      "drive", "--net", net, "--route", run.route(id).string(), "--out", run.drive(id).string()};
  if (save_scans) a.push_back("--save-scans");
  Step s = childStep(opts, "drive " + id, a, run.logs() / ("drive-" + id + ".log"), seed);
  s.output = run.drive(id) / "drive.json";  // the folder appears complete
  return s;
}

Step evaluateStep(const ChildOptions& opts, const RunLayout& run, const std::string& id,
                  long long seed) {
  Step s =
      childStep(opts, "evaluate " + id,
                {"evaluate", "--drive", run.drive(id).string(), "--out", run.eval(id).string()},
                run.logs() / ("evaluate-" + id + ".log"), seed);
  s.output = run.metrics(id);  // written last
  return s;
}

double routeLength(const fs::path& route_json) { return Route::readJson(route_json).length_m; }

void makeRouteDrivable(const SumoNet& net, const fs::path& route_json) {
  Route r = Route::readJson(route_json);
  repairSumoTurns(net, r, route_json.string());
  r.writeJson(route_json);
  fs::path rou = route_json;
  rou.replace_extension(".rou.xml");
  r.writeRouXml(rou);
}

void repairSumoTurns(const SumoNet& net, Route& r, const std::string& where) {
  if (r.sumo_edges.empty())
    throw std::runtime_error(where + ": route has no SUMO edges (graph not matched to the net?)");
  const LegalRoute legal = legalizeSumoRoute(net, r.sumo_edges);
  if (legal.repaired_transitions > 0 || legal.dropped_edges > 0) {
    std::ostringstream note;
    note << (r.notes.empty() ? "" : r.notes + "; ") << "SUMO route: " << legal.repaired_transitions
         << " transitions joined by legal detours (+" << static_cast<int>(legal.added_length_m)
         << " m)";
    if (legal.dropped_edges > 0)
      note << ", " << legal.dropped_edges << " edges no legal path passes dropped";
    r.notes = note.str();
    r.sumo_edges = legal.edges;
  }
  r.sumo_coverage = sumoCoverage(net, r.sumo_edges);  // of the route SUMO drives
}

std::vector<std::string> longestRouteFirst(const RunLayout& run,
                                           const std::vector<std::string>& ids) {
  std::vector<std::pair<double, std::string>> by_length;
  for (const auto& id : ids) by_length.emplace_back(-routeLength(run.route(id)), id);
  std::stable_sort(by_length.begin(), by_length.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (const auto& [neg, id] : by_length) out.push_back(id);
  return out;
}

}  // namespace slamroute::pipeline
