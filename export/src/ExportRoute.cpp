#include "slamroute/export/ExportRoute.hpp"

#include <cstdio>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/export/DrivenPath.hpp"
#include "slamroute/export/RouteFiles.hpp"

namespace slamroute::exports {
namespace fs = std::filesystem;

namespace {

std::string routeDescription(const Route& route, const DrivenPath& path, const SumoNet& net) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%.2f km over %zu SUMO edges", path.length_m / 1000.0,
                route.sumo_edges.size());
  return "slamroute " + route.planner + " route, seed " + std::to_string(route.seed) + ": " + buf +
         " of " + net.source.filename().string();
}

}  // namespace

fs::path besideRoute(const fs::path& route_json, const std::string& suffix) {
  fs::path p = route_json;
  return p.replace_filename(route_json.stem().string() + suffix);
}

std::vector<fs::path> crewFilePaths(const fs::path& route_json) {
  return {besideRoute(route_json, "_instructions.md"), besideRoute(route_json, "_instructions.csv"),
          besideRoute(route_json, ".gpx"), besideRoute(route_json, ".kml")};
}

RouteFileTexts routeFileTexts(const SumoNet& net, const Route& route, const fs::path& route_json,
                              const std::string& title, const RouteExportOptions& opt) {
  if (route.sumo_edges.empty())
    throw std::invalid_argument(route_json.string() +
                                ": the route has no SUMO edges (plan it with --net)");
  const DrivenPath path = drivenPath(net, route.sumo_edges);
  const std::vector<Instruction> steps = turnByTurn(net, route.sumo_edges, opt.instructions);
  const std::optional<GeoProjection> proj = GeoProjection::forNet(net, opt.geo_origin);
  RouteFileTexts out;
  out.files.emplace_back(besideRoute(route_json, "_instructions.md"),
                         instructionsMarkdown(title + ": turn by turn", steps, path.length_m,
                                              proj ? &*proj : nullptr));
  out.files.emplace_back(besideRoute(route_json, "_instructions.csv"),
                         instructionsCsv(steps, proj ? &*proj : nullptr));
  if (!proj) {
    out.note = net.source.string() +
               " has no geo-reference (projParameter \"!\"): no GPX/KML written; "
               "--geo-origin LAT,LON places the net's centre there";
    return out;
  }
  const GeoRoute geo = geoRoute(title, routeDescription(route, path, net), path, steps, *proj);
  out.files.emplace_back(besideRoute(route_json, ".gpx"), gpxText(geo));
  out.files.emplace_back(besideRoute(route_json, ".kml"), kmlText(geo));
  return out;
}

RouteExportResult exportRoute(const SumoNet& net, const Route& route, const fs::path& route_json,
                              const RouteExportOptions& opt) {
  const RouteFileTexts texts =
      routeFileTexts(net, route, route_json, route.planner + " route", opt);
  RouteExportResult res;
  for (const auto& [p, text] : texts.files) {
    writeFileAtomic(p, text);
    res.written.push_back(p);
  }
  res.note = texts.note;
  return res;
}

}  // namespace slamroute::exports
