#include "HtmlFleet.hpp"

#include <cstdio>

#include "HtmlFleetDrives.hpp"
#include "ReportFleet.hpp"
#include "ReportFleetTables.hpp"
#include "slamroute/core/FleetRoute.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// Vehicle k's colour as CSS "#rrggbb" (vehicleColour gives B, G, R).
std::string cssColour(std::size_t k) {
  const auto c = vehicleColour(k);
  char buf[8];
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", c[2], c[1], c[0]);
  return buf;
}

json tableData(const FleetTable& t) {
  return {{"title", t.title}, {"head", t.head}, {"rows", t.rows}};
}

}  // namespace

void addFleetData(json& data, const ReportInputs& in, const SumoNet& net, const MapFrame& frame) {
  const fs::path rj = in.out / "routes" / (in.fleet + ".json");
  if (!fs::exists(rj)) return;
  const FleetRoute f = FleetRoute::readJson(rj);
  json vehicles = json::array();
  for (std::size_t k = 0; k < f.vehicles.size(); ++k)
    vehicles.push_back({{"id", FleetRoute::vehicleId(k)},
                        {"colour", cssColour(k)},
                        {"length_km", htmlRounded(f.vehicles[k].length_m / 1000.0, 0.01)},
                        {"route", routeLayer(net, f.vehicles[k], frame)}});
  // Each vehicle's merged trajectory for the slider (none before the fleet is evaluated).
  for (const json& d :
       fleetDriveLayers(in.out / "drives" / in.fleet, in.out / "eval" / in.fleet, frame))
    for (json& v : vehicles)
      if (v["id"] == d["id"]) v["drive"] = d["drive"];
  json fleet = {{"name", in.fleet},
                {"vehicles", vehicles},
                {"makespan_km", htmlRounded(f.makespan_m / 1000.0, 0.01)},
                {"campaign", fleetCampaignTimeText(in)}};
  if (const fs::path png = in.out / "eval" / in.fleet / "merged_map_error_top.png"; fs::exists(png))
    fleet["merged_map_png"] = pngDataUri(png);
  data["fleet"] = fleet;
  data["tables"].push_back(tableData(fleetMakespanTable(in, f)));
  data["tables"].push_back(tableData(fleetVehicleTable(in, f)));
  if (const FleetTable merged = fleetMergedMapTable(in); !merged.rows.empty())
    data["tables"].push_back(tableData(merged));
}

}  // namespace slamroute::cli
