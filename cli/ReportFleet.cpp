// The fleet's sections of report.md, from routes/<fleet>.json, drives/<fleet>/fleet.json and
// eval/<fleet>/ (each vehicle's metrics.json and the merge's fleet_metrics.json).
#include "ReportFleet.hpp"

#include "ReportFleetTables.hpp"
#include "slamroute/core/FleetRoute.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

namespace {

void fleetRouteMap(std::ostringstream& md, const ReportData& data, const FleetRoute& f) {
  std::vector<std::vector<int>> edges;
  for (const Route& r : f.vehicles) edges.push_back(r.edges);
  const std::string png = "route_" + data.in.fleet + ".png";
  renderFleetRoutesPng(data.pictures / png, data.graph, edges);
  md << "![fleet routes, one colour per vehicle](report/" << png << ")\n\n";
}

}  // namespace

void writeFleetPlanSection(std::ostringstream& md, const ReportData& data) {
  if (data.in.fleet.empty()) return;
  const fs::path rj = data.in.out / "routes" / (data.in.fleet + ".json");
  if (!fs::exists(rj)) return;
  const FleetRoute f = FleetRoute::readJson(rj);
  md << "## Fleet: " << f.vehicles.size() << " vehicles share the streets\n\n"
     << "Each vehicle leaves its depot and returns; every directed street is driven by at least "
        "one of them. The makespan, the longest route, is how long the campaign takes.\n\n";
  fleetRouteMap(md, data, f);
  md << markdownTable(fleetMakespanTable(data.in, f));
}

void writeFleetResultsSection(std::ostringstream& md, const ReportData& data) {
  if (data.in.fleet.empty()) return;
  const fs::path rj = data.in.out / "routes" / (data.in.fleet + ".json");
  if (!fs::exists(rj)) return;
  const FleetRoute f = FleetRoute::readJson(rj);
  md << "### Fleet: SLAM per vehicle and the merged map\n\n"
     << "All vehicles drove at once in one SUMO session. ATE alone: each vehicle's SLAM aligned "
        "to its ground truth by itself; one alignment for all: the fleet's trajectories under "
        "one rigid alignment, before and after the pose graph that joins them by inter-vehicle "
        "closures. Facades covered: street facades within 30 m of a driven street with a map "
        "point within 0.5 m.\n\n";
  if (const std::string time = fleetCampaignTimeText(data.in); !time.empty()) md << time << "\n\n";
  md << markdownTable(fleetVehicleTable(data.in, f));
  const FleetTable merged = fleetMergedMapTable(data.in);
  if (merged.rows.empty()) return;
  md << markdownTable(merged);
  const fs::path png = data.in.out / "eval" / data.in.fleet / "merged_map_error_top.png";
  if (fs::exists(png))
    md << "![merged map from above](eval/" << data.in.fleet << "/merged_map_error_top.png)\n\n";
}

}  // namespace slamroute::cli
