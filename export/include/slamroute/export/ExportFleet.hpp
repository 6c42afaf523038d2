#pragma once
// The crew files of a fleet: one set per vehicle beside the fleet's route.json, named so that
// the crews can tell them apart (ROUTE.vehicle_0.gpx, ROUTE.vehicle_0_instructions.md, ...).
#include <filesystem>
#include <vector>

#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/export/ExportRoute.hpp"

namespace slamroute::exports {

/// "x/fleet.json", 2 -> "x/fleet.vehicle_2.json": the name vehicle k's crew files derive from.
std::filesystem::path vehicleRoutePath(const std::filesystem::path& route_json, std::size_t k);

/// Every vehicle's crew files (instructions always, GPX / KML on a net on the globe), titled with
/// the vehicle's number and SUMO id; the note about a missing geo-reference comes once. Throws
/// std::invalid_argument naming the vehicle when its route has no SUMO edges.
RouteFileTexts fleetFileTexts(const SumoNet& net, const FleetRoute& fleet,
                              const std::filesystem::path& route_json,
                              const RouteExportOptions& opt);

/// The vehicle crew files now beside `route_json` (any vehicle number), so that a new plan
/// removes those it does not write again (a former plan had more vehicles, or a GPX).
std::vector<std::filesystem::path> existingVehicleFiles(const std::filesystem::path& route_json);

}  // namespace slamroute::exports
