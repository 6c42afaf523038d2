#pragma once
// The steps of a fleet in a pipeline run (`run --vehicles K`): its route file holds one route
// per vehicle (core FleetRoute.hpp), its drive folder one folder per vehicle plus fleet.json
// (core FleetDrive.hpp), its evaluation each vehicle's SLAM plus the merge (evaluate/Fleet.hpp).
// Same commands as a single route's steps; what differs is the file each writes last.
#include <filesystem>
#include <string>

#include "slamroute/pipeline/Steps.hpp"

namespace slamroute::pipeline {

/// The fleet evaluation's summary, written last (evaluate/Fleet.hpp writeFleetOutputs).
inline constexpr const char* kFleetMetrics = "fleet_metrics.json";

/// makeRouteDrivable for each vehicle of a fleet's route.json; writes ROUTE.rou.xml with all of
/// them. Throws naming the file and the vehicle when a route has no SUMO edges.
void makeFleetRouteDrivable(const SumoNet& net, const std::filesystem::path& route_json);

/// The drive of the fleet's route `id`: one SUMO session, RunLayout::drive(id)/vehicle_K.
Step fleetDriveStep(const ChildOptions& opts, const RunLayout& run, const std::string& net,
                    const std::string& id, bool save_scans = false);
/// The evaluation of the fleet's drive `id`: every vehicle's SLAM, then the merge.
Step fleetEvaluateStep(const ChildOptions& opts, const RunLayout& run, const std::string& id);

}  // namespace slamroute::pipeline
