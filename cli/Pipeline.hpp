#pragma once
// Pieces shared by `run` and `experiment`: child steps carrying the global options, and making a
// planned route drivable in SUMO.
#include <filesystem>
#include <string>
#include <vector>

#include "Commands.hpp"
#include "Subprocess.hpp"

namespace slamroute {
struct SumoNet;
}

namespace slamroute::cli {

/// A child step `slamroute [--seed S] [--config C] [--log-level L] ARGS…`; `seed` overrides the
/// context's seed when >= 0.
Step childStep(const Context& ctx, const std::string& label, std::vector<std::string> args,
               const std::filesystem::path& log, long long seed = -1);

/// The steps still to run when resuming: those without an output, or whose output does not exist
/// yet; each step kept from an earlier run is logged.
std::vector<Step> stepsNotDone(std::vector<Step> steps);

/// Length of a planned route [m] (route.json's length_m).
double routeLength(const std::filesystem::path& route_json);

/// Routes planned on a trace-built graph know its turns only loosely: joins consecutive SUMO
/// edges with the shortest legal detour where SUMO forbids the turn (noted in the route), and
/// writes ROUTE.rou.xml beside it. Throws when the route has no SUMO edges.
void makeRouteDrivable(const SumoNet& net, const std::filesystem::path& route_json);

}  // namespace slamroute::cli
