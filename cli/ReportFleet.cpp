// The fleet's sections of report.md, from routes/<fleet>.json, drives/<fleet>/fleet.json and
// eval/<fleet>/ (each vehicle's metrics.json and the merge's fleet_metrics.json).
#include "ReportFleet.hpp"

#include <cmath>
#include <optional>

#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/pipeline/FleetSteps.hpp"
#include "slamroute/pipeline/JsonFile.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The single-vehicle postman route of the same run, when it planned one.
double singlePostmanM(const ReportData& data) {
  const json r = pipeline::readJsonIfPresent(data.in.out / "routes" / "postman.json");
  return r.is_object() ? r.value("length_m", std::nan("")) : std::nan("");
}

/// Seconds the single postman route took in SUMO, when the run drove it.
double singlePostmanS(const ReportData& data) {
  const json d = pipeline::readJsonIfPresent(data.in.out / "drives" / "postman" / "drive.json");
  if (!d.is_object() || !d.contains("arrive_s")) return std::nan("");
  return d.value("arrive_s", 0.0) - d.value("depart_s", 0.0);
}

void fleetRouteMap(std::ostringstream& md, const ReportData& data, const FleetRoute& f) {
  std::vector<std::vector<int>> edges;
  for (const Route& r : f.vehicles) edges.push_back(r.edges);
  const std::string png = "route_" + data.in.fleet + ".png";
  renderFleetRoutesPng(data.pictures / png, data.graph, edges);
  md << "![fleet routes, one colour per vehicle](report/" << png << ")\n\n";
}

void makespanTable(std::ostringstream& md, const ReportData& data, const FleetRoute& f) {
  const double l1_run = singlePostmanM(data);
  md << "| figure | value |\n|---|---|\n"
     << "| vehicles | " << f.vehicles.size() << " (" << f.strategy << ") |\n"
     << "| makespan: longest vehicle route [km] | " << reportNumber(f.makespan_m / 1000.0, 2)
     << " |\n| lower bound max(L1 / K, longest depot round trip) [km] | "
     << reportNumber(f.lower_bound_m / 1000.0, 2) << " |\n| makespan / bound | "
     << reportNumber(f.lower_bound_m > 0 ? f.makespan_m / f.lower_bound_m : std::nan(""), 2)
     << " |\n| single postman route from the depot, L1 [km] | "
     << reportNumber(f.single_route_m / 1000.0, 2) << " |\n| makespan / L1 | "
     << reportNumber(f.single_route_m > 0 ? f.makespan_m / f.single_route_m : std::nan(""), 2)
     << " |\n| total of the vehicles / L1 | "
     << reportNumber(f.single_route_m > 0 ? f.total_length_m / f.single_route_m : std::nan(""), 2)
     << " |\n| balance (makespan / mean) | " << reportNumber(f.balance, 2) << " |\n";
  if (std::isfinite(l1_run))
    md << "| this run's postman route (after the legal repair) [km] | "
       << reportNumber(l1_run / 1000.0, 2) << " |\n";
  md << "| directed graph edges covered [%] | " << reportNumber(f.edge_coverage_pct, 1)
     << " |\n| planning [s] | " << reportNumber(f.planning_seconds, 2) << " |\n\n";
}

/// "a / b" of a vehicle's drive: length driven [km] and time [s] in SUMO.
std::string driveCells(const FleetDriveInfo* info, std::size_t k) {
  if (!info || k >= info->vehicles.size()) return "– | –";
  const FleetDriveVehicle& v = info->vehicles[k];
  return reportNumber(v.driven_m / 1000.0, 2) + " | " + reportNumber(v.arrive_s - v.depart_s, 0);
}

void vehicleTable(std::ostringstream& md, const ReportData& data, const FleetRoute& f,
                  const FleetDriveInfo* info, const json& fm) {
  md << "| vehicle | route [km] | driven [km] | time in SUMO [s] | ATE alone [m] | ATE, one "
        "alignment for all, before the merge [m] | after the merge [m] | facades covered [%] |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  const json vs = fm.value("vehicles", json::array());
  for (std::size_t k = 0; k < f.vehicles.size(); ++k) {
    const json v = k < vs.size() ? vs[k] : json::object();
    md << "| " << FleetRoute::vehicleId(k) << " | "
       << reportNumber(f.vehicles[k].length_m / 1000.0, 2) << " | " << driveCells(info, k) << " | "
       << reportNumber(v, "own_ate_rmse_m", 3) << " | " << reportNumber(v, "common_ate_before_m", 3)
       << " | " << reportNumber(v, "common_ate_after_m", 3) << " | "
       << reportNumber(v, "completeness_pct", 1) << " |\n";
  }
  md << "| merged map | " << reportNumber(f.total_length_m / 1000.0, 2) << " | – | "
     << (info ? reportNumber(info->makespanSeconds(), 0) : "–") << " | – | "
     << reportNumber(fm, "common_ate_before_m", 3) << " | "
     << reportNumber(fm, "common_ate_after_m", 3) << " | "
     << reportNumber(fm, "completeness_pct", 1) << " |\n\n";
}

/// The merged map's accuracy as built and aligned, the closures that joined it, its picture.
void mergedMapPart(std::ostringstream& md, const ReportData& data, const json& fm) {
  const std::string clamp = reportNumber(fm, "map_accuracy_max_m", 1);
  md << "| merged map | value |\n|---|---|\n"
     << "| inter-vehicle closures in the pose graph (candidates, dropped as inconsistent) | "
     << reportNumber(fm, "closures", 0) << " (" << reportNumber(fm, "closure_candidates", 0) << ", "
     << reportNumber(fm, "closures_inconsistent", 0) << ") |\n"
     << "| ATE of all vehicles, one alignment, after the merge [m] | "
     << reportNumber(fm, "common_ate_after_m", 3) << " |\n"
     << "| map points to the world: median as built / aligned [m] | "
     << reportNumber(fm, "map_median_dist_m", 2) << " / "
     << reportNumber(fm, "map_aligned_median_dist_m", 2) << " |\n"
     << "| share farther than the clamp (" << clamp << " m) as built / aligned [%] | "
     << reportNumber(fm, "map_far_share", 1, 100.0) << " / "
     << reportNumber(fm, "map_aligned_far_share", 1, 100.0) << " |\n"
     << "| street facades covered by the merged map [%] | "
     << reportNumber(fm, "completeness_pct", 1) << " |\n| map points | "
     << reportNumber(fm, "map_points", 0) << " |\n\n";
  const fs::path png = data.in.out / "eval" / data.in.fleet / "merged_map_error_top.png";
  if (fs::exists(png))
    md << "![merged map from above](eval/" << data.in.fleet << "/merged_map_error_top.png)\n\n";
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
  makespanTable(md, data, f);
}

void writeFleetResultsSection(std::ostringstream& md, const ReportData& data) {
  if (data.in.fleet.empty()) return;
  const fs::path rj = data.in.out / "routes" / (data.in.fleet + ".json");
  if (!fs::exists(rj)) return;
  const FleetRoute f = FleetRoute::readJson(rj);
  const fs::path drive = data.in.out / "drives" / data.in.fleet;
  std::optional<FleetDriveInfo> info;
  if (FleetDriveInfo::isFleetFolder(drive)) info = FleetDriveInfo::read(drive);
  const json fm =
      pipeline::readJsonIfPresent(data.in.out / "eval" / data.in.fleet / pipeline::kFleetMetrics);
  md << "### Fleet: SLAM per vehicle and the merged map\n\n"
     << "All vehicles drove at once in one SUMO session. ATE alone: each vehicle's SLAM aligned "
        "to its ground truth by itself; one alignment for all: the fleet's trajectories under "
        "one rigid alignment, before and after the pose graph that joins them by inter-vehicle "
        "closures. Facades covered: street facades within 30 m of a driven street with a map "
        "point within 0.5 m.\n\n";
  const double single_s = singlePostmanS(data);
  if (std::isfinite(single_s) && info)
    md << "Campaign time in SUMO: " << reportNumber(info->makespanSeconds(), 0)
       << " s for the fleet against " << reportNumber(single_s, 0)
       << " s for the single postman route.\n\n";
  vehicleTable(md, data, f, info ? &*info : nullptr, fm);
  if (fm.is_object() && !fm.empty()) mergedMapPart(md, data, fm);
}

}  // namespace slamroute::cli
