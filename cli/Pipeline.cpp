#include "Pipeline.hpp"

#include <sstream>

#include "slamroute/core/Log.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/SumoRoute.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

Step childStep(const Context& ctx, const std::string& label, std::vector<std::string> args,
               const fs::path& log, long long seed) {
  std::vector<std::string> full{"--seed", std::to_string(seed >= 0 ? static_cast<std::uint64_t>(seed) : ctx.cfg.seed),
                                "--log-level", ctx.log_level == "debug" ? "debug" : "info"};
  if (!ctx.config_file.empty()) {
    full.push_back("--config");
    full.push_back(fs::absolute(ctx.config_file).string());
  }
  full.insert(full.end(), args.begin(), args.end());
  return {label, full, log};
}

std::vector<Step> stepsNotDone(std::vector<Step> steps) {
  std::vector<Step> left;
  for (auto& st : steps) {
    if (!st.output.empty() && fs::exists(st.output))
      logInfo("  kept     " + st.label + " (" + st.output.string() + ")");
    else
      left.push_back(std::move(st));
  }
  return left;
}

double routeLength(const fs::path& route_json) { return Route::readJson(route_json).length_m; }

void makeRouteDrivable(const SumoNet& net, const fs::path& route_json) {
  Route r = Route::readJson(route_json);
  if (r.sumo_edges.empty())
    throw std::runtime_error(route_json.string() + ": route has no SUMO edges (graph not matched to the net?)");
  const LegalRoute legal = legalizeSumoRoute(net, r.sumo_edges);
  if (legal.repaired_transitions > 0 || legal.dropped_edges > 0) {
    std::ostringstream note;
    note << (r.notes.empty() ? "" : r.notes + "; ") << "SUMO route: " << legal.repaired_transitions
         << " transitions joined by legal detours (+" << static_cast<int>(legal.added_length_m) << " m)";
    if (legal.dropped_edges > 0) note << ", " << legal.dropped_edges << " edges no legal path passes dropped";
    r.notes = note.str();
    r.sumo_edges = legal.edges;
    r.writeJson(route_json);
  }
  fs::path rou = route_json;
  rou.replace_extension(".rou.xml");
  r.writeRouXml(rou);
}

}  // namespace slamroute::cli
