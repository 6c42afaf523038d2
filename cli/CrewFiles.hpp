#pragma once
// `plan --net` and `run` write a route's crew files (GPX, KML, turn-by-turn) beside route.json.
#include <filesystem>
#include <string>

namespace slamroute {
struct SumoNet;
struct FleetRoute;
class AtomicFileSet;
}  // namespace slamroute

namespace slamroute::cli {

struct Context;

/// CLI11 check of --geo-origin: "" when `text` is LAT,LON, else the one-line error.
std::string checkGeoOrigin(const std::string& text);

/// Writes ROUTE.gpx / .kml (when the net is on the globe or `geo_origin` "LAT,LON" places it)
/// and ROUTE_instructions.md / .csv beside `route_json`; says on stderr what it wrote. Returns a
/// one-line note for a net without geo-reference ("" otherwise). Throws std::invalid_argument on
/// a bad origin.
std::string writeCrewFiles(const Context& ctx, const SumoNet& net,
                           const std::filesystem::path& route_json, const std::string& geo_origin);

/// Stages every vehicle's crew files of `fleet` (ROUTE.vehicle_K.gpx, ...) into `files`, to be
/// committed with route.json, and drops the vehicle files of an older plan it does not rewrite.
/// Returns the one-line note for a net without geo-reference ("" otherwise).
std::string stageFleetCrewFiles(const Context& ctx, const SumoNet& net, const FleetRoute& fleet,
                                const std::filesystem::path& route_json,
                                const std::string& geo_origin, AtomicFileSet& files);

/// The fleet route.json at `route_json` gets its vehicles' crew files (all replaced together);
/// says on stderr what it wrote. Returns like stageFleetCrewFiles.
std::string writeFleetCrewFiles(const Context& ctx, const SumoNet& net,
                                const std::filesystem::path& route_json,
                                const std::string& geo_origin);

}  // namespace slamroute::cli
