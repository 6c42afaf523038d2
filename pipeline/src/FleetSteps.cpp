#include "slamroute/pipeline/FleetSteps.hpp"

#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/core/FleetRoute.hpp"

namespace slamroute::pipeline {
namespace fs = std::filesystem;

void makeFleetRouteDrivable(const SumoNet& net, const fs::path& route_json) {
  FleetRoute f = FleetRoute::readJson(route_json);
  for (std::size_t k = 0; k < f.vehicles.size(); ++k)
    repairSumoTurns(net, f.vehicles[k],
                    route_json.string() + " (vehicle " + std::to_string(k) + ")");
  f.writeJson(route_json);
  fs::path rou = route_json;
  rou.replace_extension(".rou.xml");
  f.writeRouXml(rou);
}

Step fleetDriveStep(const ChildOptions& opts, const RunLayout& run, const std::string& net,
                    const std::string& id, bool save_scans) {
  Step s = driveStep(opts, run, net, id, save_scans);
  s.output = run.drive(id) / kFleetDriveInfo;  // the folder appears complete
  return s;
}

Step fleetEvaluateStep(const ChildOptions& opts, const RunLayout& run, const std::string& id) {
  Step s = evaluateStep(opts, run, id);
  s.output = run.eval(id) / kFleetMetrics;  // written last
  return s;
}

}  // namespace slamroute::pipeline
