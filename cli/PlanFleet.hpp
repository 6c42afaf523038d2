#pragma once
// `plan --vehicles K` (several mapping vehicles share the streets), called by CmdPlan.cpp.
#include <filesystem>
#include <string>

#include "Commands.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/rl/Config.hpp"

namespace slamroute::cli {

struct FleetPlanOptions {
  int vehicles = 0;        ///< --vehicles (0: rl.fleet.vehicles)
  std::string depot;       ///< --depot EDGE: one depot for all
  std::string depots;      ///< --depots E1,E2,..: one per vehicle
  std::string geo_origin;  ///< --geo-origin LAT,LON for the vehicles' .gpx / .kml
};

/// True when the request is for a fleet: K > 1, a depot option, or the planner `partition`.
bool isFleetRequest(const rl::Config& cfg, const FleetPlanOptions& o);

/// Plans the fleet and writes OUT (route.json with one route per vehicle) and, when the routes
/// have SUMO edges, OUT.rou.xml with K vehicles; with a `net`, each vehicle's crew files too
/// (OUT.vehicle_K.gpx, ...), all replaced together. Throws std::invalid_argument on bad options.
void planFleetCommand(const Context& ctx, const RoadGraph& g, rl::Config cfg,
                      const FleetPlanOptions& o, const std::string& where,
                      const std::filesystem::path& out, const SumoNet* net);

}  // namespace slamroute::cli
