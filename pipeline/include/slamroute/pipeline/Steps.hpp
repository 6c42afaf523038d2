#pragma once
// The steps of a pipeline run (survey -> build-graph -> plan -> legal repair -> drive ->
// evaluate) as child-process steps with their outputs and stamps, and the files they leave in a
// run folder. `run`, `experiment` and `sweep` build their work from these.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/pipeline/Subprocess.hpp"

namespace slamroute {
struct SumoNet;
struct Route;
}  // namespace slamroute

namespace slamroute::pipeline {

/// The global options every child step carries.
struct ChildOptions {
  std::uint64_t seed = 0;
  std::string config_file;  ///< absolute path of --config; empty: built-in defaults
  bool debug_log = false;   ///< --log-level debug (else info)
};

/// A child step `slamroute --seed S --log-level L [--config C] ARGS…`; `seed` overrides the
/// options' seed when >= 0.
Step childStep(const ChildOptions& opts, const std::string& label, std::vector<std::string> args,
               const std::filesystem::path& log, long long seed = -1);

/// Where the steps of one run put their files. Routes, drives and evaluations are named by an
/// id: the planner in `run`, planner/variant and seed in `experiment`.
struct RunLayout {
  std::filesystem::path out;  ///< the run folder (absolute)

  std::filesystem::path logs() const { return out / "logs"; }
  std::filesystem::path survey() const { return out / "survey"; }
  std::filesystem::path graph() const { return out / "graph" / "graph.json"; }
  std::filesystem::path route(const std::string& id) const {
    return out / "routes" / (id + ".json");
  }
  std::filesystem::path drive(const std::string& id) const { return out / "drives" / id; }
  std::filesystem::path eval(const std::string& id) const { return out / "eval" / id; }
  std::filesystem::path metrics(const std::string& id) const { return eval(id) / "metrics.json"; }
};

Step surveyStep(const ChildOptions& opts, const RunLayout& run, const std::string& net);
Step buildGraphStep(const ChildOptions& opts, const RunLayout& run, const std::string& net);

/// One route to plan on the run's graph.
struct PlanRequest {
  std::string id;  ///< names the route file (RunLayout::route)
  std::string planner;
  std::string reward;   ///< --reward; empty: the config's
  long long seed = -1;  ///< child seed; < 0: the options' seed
  /// The route whose length is this one's --max-length (the random walk drives as far as the
  /// same seed's Q-learning route: paper Table 1 compares routes for the same crew time). Empty:
  /// no budget.
  std::string budget_from;
  int vehicles = 1;  ///< > 1: a fleet sharing the streets (plan --vehicles; FleetSteps.hpp)
};

/// The plan step of `req`; `max_length_m` is the budget when the request has one.
Step planStep(const ChildOptions& opts, const RunLayout& run, const PlanRequest& req,
              std::optional<double> max_length_m = std::nullopt);
Step driveStep(const ChildOptions& opts, const RunLayout& run, const std::string& net,
               const std::string& id, bool save_scans = false, long long seed = -1);
Step evaluateStep(const ChildOptions& opts, const RunLayout& run, const std::string& id,
                  long long seed = -1);

/// Length of a planned route [m] (route.json's length_m).
double routeLength(const std::filesystem::path& route_json);

/// The plan step of `req` once the route it is budgeted from (if any) exists.
Step budgetedPlanStep(const ChildOptions& opts, const RunLayout& run, const PlanRequest& req);

/// Routes planned on a trace-built graph know its turns only loosely: joins consecutive SUMO
/// edges with the shortest legal detour where SUMO forbids the turn (noted in the route), and
/// writes ROUTE.rou.xml beside it. Throws when the route has no SUMO edges.
void makeRouteDrivable(const SumoNet& net, const std::filesystem::path& route_json);
/// makeRouteDrivable's repair of one route in memory (`where` names it in the error).
void repairSumoTurns(const SumoNet& net, Route& route, const std::string& where);

/// `ids` ordered by their planned route length, longest first (ties keep their order): with
/// several SLAM runs at a time the last one to start is the shortest, and the stage ends soonest.
std::vector<std::string> longestRouteFirst(const RunLayout& run,
                                           const std::vector<std::string>& ids);

}  // namespace slamroute::pipeline
