// The fleet's tables from routes/<fleet>.json, drives/<fleet>/fleet.json and eval/<fleet>/ (each
// vehicle's figures and the merge's fleet_metrics.json).
#include "ReportFleetTables.hpp"

#include <cmath>
#include <optional>

#include "ReportSections.hpp"
#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/pipeline/FleetSteps.hpp"
#include "slamroute/pipeline/JsonFile.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The single-vehicle postman route of the same run, when it planned one.
double singlePostmanM(const ReportInputs& in) {
  const json r = pipeline::readJsonIfPresent(in.out / "routes" / "postman.json");
  return r.is_object() ? r.value("length_m", std::nan("")) : std::nan("");
}

/// Seconds the single postman route took in SUMO, when the run drove it.
double singlePostmanS(const ReportInputs& in) {
  const json d = pipeline::readJsonIfPresent(in.out / "drives" / "postman" / "drive.json");
  if (!d.is_object() || !d.contains("arrive_s")) return std::nan("");
  return d.value("arrive_s", 0.0) - d.value("depart_s", 0.0);
}

double ratio(double a, double b) { return b > 0 ? a / b : std::nan(""); }

std::optional<FleetDriveInfo> fleetDrive(const ReportInputs& in) {
  const fs::path drive = in.out / "drives" / in.fleet;
  if (!FleetDriveInfo::isFleetFolder(drive)) return std::nullopt;
  return FleetDriveInfo::read(drive);
}

json fleetMetrics(const ReportInputs& in) {
  return pipeline::readJsonIfPresent(in.out / "eval" / in.fleet / pipeline::kFleetMetrics);
}

/// Length driven [km] and time [s] of vehicle k in SUMO.
std::vector<std::string> driveCells(const std::optional<FleetDriveInfo>& info, std::size_t k) {
  if (!info || k >= info->vehicles.size()) return {"–", "–"};
  const FleetDriveVehicle& v = info->vehicles[k];
  return {reportNumber(v.driven_m / 1000.0, 2), reportNumber(v.arrive_s - v.depart_s, 0)};
}

}  // namespace

FleetTable fleetMakespanTable(const ReportInputs& in, const FleetRoute& f) {
  FleetTable t{"Fleet: makespan", {"figure", "value"}, {}};
  auto row = [&t](const std::string& a, const std::string& b) { t.rows.push_back({a, b}); };
  row("vehicles", std::to_string(f.vehicles.size()) + " (" + f.strategy + ")");
  row("makespan: longest vehicle route [km]", reportNumber(f.makespan_m / 1000.0, 2));
  row("lower bound max(L1 / K, longest depot round trip) [km]",
      reportNumber(f.lower_bound_m / 1000.0, 2));
  row("makespan / bound", reportNumber(ratio(f.makespan_m, f.lower_bound_m), 2));
  row("single postman route from the depot, L1 [km]", reportNumber(f.single_route_m / 1000.0, 2));
  row("makespan / L1", reportNumber(ratio(f.makespan_m, f.single_route_m), 2));
  row("total of the vehicles / L1", reportNumber(ratio(f.total_length_m, f.single_route_m), 2));
  row("balance (makespan / mean)", reportNumber(f.balance, 2));
  if (const double l1_run = singlePostmanM(in); std::isfinite(l1_run))
    row("this run's postman route (after the legal repair) [km]", reportNumber(l1_run / 1000.0, 2));
  row("directed graph edges covered [%]", reportNumber(f.edge_coverage_pct, 1));
  row("planning [s]", reportNumber(f.planning_seconds, 2));
  return t;
}

FleetTable fleetVehicleTable(const ReportInputs& in, const FleetRoute& f) {
  FleetTable t{"Fleet: per vehicle",
               {"vehicle", "route [km]", "driven [km]", "time in SUMO [s]", "ATE alone [m]",
                "ATE, one alignment for all, before the merge [m]", "after the merge [m]",
                "facades covered [%]"},
               {}};
  const std::optional<FleetDriveInfo> info = fleetDrive(in);
  const json fm = fleetMetrics(in);
  const json vs = fm.is_object() ? fm.value("vehicles", json::array()) : json::array();
  for (std::size_t k = 0; k < f.vehicles.size(); ++k) {
    const json v = k < vs.size() ? vs[k] : json::object();
    const auto drive = driveCells(info, k);
    t.rows.push_back(
        {FleetRoute::vehicleId(k), reportNumber(f.vehicles[k].length_m / 1000.0, 2), drive[0],
         drive[1], reportNumber(v, "own_ate_rmse_m", 3), reportNumber(v, "common_ate_before_m", 3),
         reportNumber(v, "common_ate_after_m", 3), reportNumber(v, "completeness_pct", 1)});
  }
  t.rows.push_back({"merged map", reportNumber(f.total_length_m / 1000.0, 2), "–",
                    info ? reportNumber(info->makespanSeconds(), 0) : "–", "–",
                    reportNumber(fm, "common_ate_before_m", 3),
                    reportNumber(fm, "common_ate_after_m", 3),
                    reportNumber(fm, "completeness_pct", 1)});
  return t;
}

FleetTable fleetMergedMapTable(const ReportInputs& in) {
  FleetTable t{"Fleet: the merged map", {"merged map", "value"}, {}};
  const json fm = fleetMetrics(in);
  if (!fm.is_object() || fm.empty()) return t;
  auto row = [&t](const std::string& a, const std::string& b) { t.rows.push_back({a, b}); };
  row("inter-vehicle closures in the pose graph (candidates, dropped as inconsistent)",
      reportNumber(fm, "closures", 0) + " (" + reportNumber(fm, "closure_candidates", 0) + ", " +
          reportNumber(fm, "closures_inconsistent", 0) + ")");
  row("ATE of all vehicles, one alignment, after the merge [m]",
      reportNumber(fm, "common_ate_after_m", 3));
  row("map points to the world: median as built / aligned [m]",
      reportNumber(fm, "map_median_dist_m", 2) + " / " +
          reportNumber(fm, "map_aligned_median_dist_m", 2));
  row("share farther than the clamp (" + reportNumber(fm, "map_accuracy_max_m", 1) +
          " m) as built / aligned [%]",
      reportNumber(fm, "map_far_share", 1, 100.0) + " / " +
          reportNumber(fm, "map_aligned_far_share", 1, 100.0));
  row("street facades covered by the merged map [%]", reportNumber(fm, "completeness_pct", 1));
  row("map points", reportNumber(fm, "map_points", 0));
  return t;
}

std::string fleetCampaignTimeText(const ReportInputs& in) {
  const double single_s = singlePostmanS(in);
  const std::optional<FleetDriveInfo> info = fleetDrive(in);
  if (!std::isfinite(single_s) || !info) return "";
  return "Campaign time in SUMO: " + reportNumber(info->makespanSeconds(), 0) +
         " s for the fleet against " + reportNumber(single_s, 0) +
         " s for the single postman route.";
}

std::string markdownTable(const FleetTable& t) {
  std::string md = "|";
  for (const auto& h : t.head) md += " " + h + " |";
  md += "\n|";
  for (std::size_t i = 0; i < t.head.size(); ++i) md += "---|";
  md += "\n";
  for (const auto& r : t.rows) {
    md += "|";
    for (const auto& c : r) md += " " + c + " |";
    md += "\n";
  }
  return md + "\n";
}

}  // namespace slamroute::cli
