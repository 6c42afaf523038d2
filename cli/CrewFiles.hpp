#pragma once
// `plan --net` and `run` write a route's crew files (GPX, KML, turn-by-turn) beside route.json.
#include <filesystem>
#include <string>

namespace slamroute {
struct SumoNet;
}

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

}  // namespace slamroute::cli
