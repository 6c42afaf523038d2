#pragma once
// Writes a planned route's crew files beside its route.json: ROUTE_instructions.md / .csv
// always, ROUTE.gpx / ROUTE.kml when the net is on the globe (its own projection, or a
// --geo-origin for a net without one).
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/export/GeoProjection.hpp"
#include "slamroute/export/Instructions.hpp"

namespace slamroute::exports {

struct RouteExportOptions {
  std::optional<GeoOrigin> geo_origin;  ///< places a net without geo-reference
  InstructionConfig instructions;
};

struct RouteExportResult {
  std::vector<std::filesystem::path> written;
  /// One line for the user when no GPX / KML could be written (empty otherwise).
  std::string note;
};

/// The crew files of one route, not yet written: each target path with its full text.
struct RouteFileTexts {
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  /// One line for the user when no GPX / KML can be written (empty otherwise).
  std::string note;
};

/// The texts exportRoute writes, named after `route_json`, the GPX / KML titled `title`. Throws
/// like exportRoute.
RouteFileTexts routeFileTexts(const SumoNet& net, const Route& route,
                              const std::filesystem::path& route_json, const std::string& title,
                              const RouteExportOptions& opt);

/// ROUTE.json -> ROUTE.gpx, ROUTE.kml, ROUTE_instructions.md, ROUTE_instructions.csv. Throws
/// std::invalid_argument when the route has no SUMO edges or names one the net lacks.
RouteExportResult exportRoute(const SumoNet& net, const Route& route,
                              const std::filesystem::path& route_json,
                              const RouteExportOptions& opt);

/// `route_json` with its extension replaced by `suffix` ("x/qlearning.json", "_instructions.md"
/// -> "x/qlearning_instructions.md").
std::filesystem::path besideRoute(const std::filesystem::path& route_json,
                                  const std::string& suffix);
/// Every crew file exportRoute may write beside `route_json` (instructions, GPX, KML), so that a
/// route replaced by one without them does not keep an older route's files beside it.
std::vector<std::filesystem::path> crewFilePaths(const std::filesystem::path& route_json);

}  // namespace slamroute::exports
