#pragma once
// Internal: one route as a JSON object and as a .rou.xml vehicle, shared by the single route's
// files and the fleet's.
#include <nlohmann/json.hpp>

#include <string>

#include "slamroute/core/Route.hpp"

namespace slamroute::detail {

/// Throws nlohmann::json::exception on wrong types (the callers name the file).
Route routeFromJsonObject(const nlohmann::json& j);
nlohmann::json routeToJson(const Route& r);

/// The vehicle type every mapping vehicle of a .rou.xml uses, and one vehicle driving `r`.
inline constexpr const char* kMappingCarType =
    "  <vType id=\"mapping_car\" vClass=\"passenger\" length=\"4.5\" maxSpeed=\"13.89\"/>\n";
std::string vehicleXml(const Route& r, const std::string& vehicle_id);

}  // namespace slamroute::detail
