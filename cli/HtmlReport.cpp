// Gathers a run's results (net, graph, routes, drives, SLAM metrics) into report.html's data.
#include "HtmlReport.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "HtmlFleet.hpp"
#include "HtmlLayers.hpp"
#include "HtmlPage.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/evaluate/Metrics.hpp"
#include "slamroute/export/GeoProjection.hpp"
#include "slamroute/pipeline/JsonFile.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json streetsLayer(const SumoNet& net, const MapFrame& f) {
  json out = json::array();
  for (const auto& e : net.edges)
    if (e.allowsPassenger())
      out.push_back({{"id", e.id}, {"name", e.name}, {"pts", f.line(e.shape)}});
  return out;
}

json weightLayer(const RoadGraph& g, const MapFrame& f) {
  json out = json::array();
  for (const auto& e : g.edges)
    out.push_back({{"id", e.id}, {"w", htmlRounded(e.weight, 1e-4)}, {"pts", f.line(e.polyline)}});
  return out;
}

/// per_edge.csv (evaluate): measured drift on each SUMO edge driven, along the street ("pct",
/// which colours the street; end to end from evaluations older than that figure) and end to end
/// ("end", which the heading in the turn onto the street can decide).
json driftLayer(const SumoNet& net, const fs::path& csv, const MapFrame& f) {
  json out = json::array();
  if (!fs::exists(csv)) return out;
  for (const auto& r : evaluate::readPerEdgeCsv(csv)) {
    const SumoEdge* e = net.findEdge(r.edge);
    if (!e || !std::isfinite(r.drift_pct)) continue;
    const double along = std::isfinite(r.window_drift_pct) ? r.window_drift_pct : r.drift_pct;
    out.push_back({{"edge", r.edge},
                   {"pct", htmlRounded(along, 1e-3)},
                   {"end", htmlRounded(r.drift_pct, 1e-3)},
                   {"len", htmlRounded(r.length_m, 0.1)},
                   {"ate", htmlRounded(r.ate_mean_m, 1e-3)},
                   {"pts", f.line(e->shape)}});
  }
  return out;
}

/// Ground truth, the estimate aligned onto it like the ATE, and the error along the drive.
json singleDriveLayer(const fs::path& drive, const fs::path& eval, const MapFrame& f) {
  if (!fs::exists(drive / "groundtruth.tum") || !fs::exists(eval / "estimate.tum")) return nullptr;
  const auto m = evaluate::compareTrajectories(readTum(eval / "estimate.tum"),
                                               readTum(drive / "groundtruth.tum"), {});
  return driveLayer(m.pairs, m.T_gt_est, m.distance_m, m.errors_m, f);
}

std::string cell(const json& j, const char* key, int prec, double scale = 1.0) {
  if (!j.contains(key) || !j[key].is_number()) return "–";
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(prec);
  o << j[key].get<double>() * scale;
  return o.str();
}

json resultsTable(const ReportInputs& in) {
  json rows = json::array();
  for (const auto& p : in.planners) {
    const json r = pipeline::readJsonIfPresent(in.out / "routes" / (p + ".json"));
    const json m = pipeline::readJsonIfPresent(in.out / "eval" / p / "metrics.json");
    rows.push_back({p, cell(r, "length_m", 2, 1e-3), cell(r, "edge_coverage_pct", 1),
                    cell(r, "node_coverage_pct", 1), cell(r, "loop_closures", 0),
                    cell(m, "ate_rmse_m", 3), cell(m, "ate_mean_m", 3), cell(m, "rpe_trans_pct", 2),
                    cell(m, "loop_closures", 0), cell(m, "map_median_dist_m", 2),
                    cell(m, "map_far_share", 1, 100.0), cell(m, "map_aligned_median_dist_m", 2),
                    cell(m, "map_aligned_far_share", 1, 100.0)});
  }
  return {{"title", "Routes and SLAM results"},
          {"head",
           {"planner", "route [km]", "edge coverage [%]", "node coverage [%]",
            "predicted loop closures", "ATE RMSE [m]", "ATE mean [m]", "RPE [%]",
            "loop closures found", "map median distance [m]", "map farther than clamp [%]",
            "aligned map median [m]", "aligned map farther [%]"}},
          {"rows", rows}};
}

json stepTable(const ReportInputs& in) {
  json rows = json::array();
  for (const auto& [name, s] : in.step_seconds) {
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(1);
    o << s;
    rows.push_back({name, std::isnan(s) ? std::string("kept from an earlier run") : o.str()});
  }
  return {{"title", "Step times"}, {"head", {"step", "seconds"}}, {"rows", rows}};
}

json plannerData(const ReportInputs& in, const std::string& p, const SumoNet& net,
                 const MapFrame& f) {
  json pd = {{"name", p}};
  const fs::path rj = in.out / "routes" / (p + ".json");
  pd["route"] = fs::exists(rj) ? routeLayer(net, Route::readJson(rj), f) : json::array();
  pd["drift"] = driftLayer(net, in.out / "eval" / p / "per_edge.csv", f);
  pd["drive"] = singleDriveLayer(in.out / "drives" / p, in.out / "eval" / p, f);
  // The map from above coloured by its distance to the world surface (evaluate's picture).
  if (const fs::path png = in.out / "eval" / p / "map_error_top.png"; fs::exists(png))
    pd["map_error_png"] = pngDataUri(png);
  const json m = pipeline::readJsonIfPresent(in.out / "eval" / p / "metrics.json");
  pd["metrics"] = json::object();
  for (const char* k : {"ate_rmse_m", "ate_max_m", "rpe_trans_pct", "map_median_dist_m",
                        "map_far_share", "map_aligned_median_dist_m", "loop_closures"})
    if (m.contains(k)) pd["metrics"][k] = m[k];
  return pd;
}

}  // namespace

std::string writeHtmlReport(const ReportInputs& in, const std::string& geo_origin) {
  const HtmlParts parts = HtmlParts::installed();
  if (const std::string why = parts.missing(); !why.empty())
    return "report.html not written: " + why;
  const SumoNet net = SumoNet::read(in.net);
  MapFrame frame;
  std::optional<exports::GeoOrigin> origin;
  if (!geo_origin.empty()) origin = exports::parseGeoOrigin(geo_origin, "--geo-origin");
  frame.proj = exports::GeoProjection::forNet(net, origin);
  json data = {{"title", "slamroute report: " + net.source.filename().string()},
               {"net", in.net},
               {"geo", frame.proj.has_value()},
               {"streets", streetsLayer(net, frame)},
               {"weights", weightLayer(RoadGraph::readJson(in.graph_json), frame)},
               {"planners", json::array()},
               {"tables", json::array({resultsTable(in), stepTable(in)})}};
  for (const auto& p : in.planners) data["planners"].push_back(plannerData(in, p, net, frame));
  if (!in.fleet.empty()) addFleetData(data, in, net, frame);
  writeFileAtomic(in.out / "report.html", selfContainedPage(data["title"], data, parts));
  return "";
}

}  // namespace slamroute::cli
