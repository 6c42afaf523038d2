// The header, road-graph, results, uncertainty, per-planner and step-time sections of report.md.
#include "ReportSections.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

#include "EvaluateCompleteness.hpp"
#include "ReportFigures.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/pipeline/JsonFile.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

std::string reportNumber(double v, int prec) {
  if (!std::isfinite(v)) return "–";
  std::ostringstream o;
  o << std::fixed << std::setprecision(prec) << v;
  return o.str();
}

std::string reportNumber(const json& j, const std::string& key, int prec, double scale) {
  if (!j.contains(key) || !j[key].is_number()) return "–";
  return reportNumber(j[key].get<double>() * scale, prec);
}

namespace {

json routeJson(const ReportData& data, const std::string& planner) {
  return pipeline::readJsonIfPresent(data.in.out / "routes" / (planner + ".json"));
}

/// The median and the share beyond the clamp (map_accuracy_max_m): a mean or a p95 of clamped
/// distances says more about the clamp than about the map. `prefix` "map_": as built (in the
/// frame the estimate starts in); "map_aligned_": the map's own deformation. With half the points
/// or more beyond the clamp the median is the clamp, not a measurement: it is written "> clamp".
std::string mapCell(const json& m, const std::string& prefix) {
  if (!m.contains(prefix + "median_dist_m") || !m.contains(prefix + "far_share")) return "–";
  const bool saturated = m[prefix + "far_share"].is_number() &&
                         m[prefix + "far_share"].get<double>() >= 0.5 &&
                         m.contains("map_accuracy_max_m");
  const std::string median = saturated ? "> " + reportNumber(m, "map_accuracy_max_m", 1)
                                       : reportNumber(m, prefix + "median_dist_m", 2);
  return median + " / " + reportNumber(m, prefix + "far_share", 1, 100.0) +
         (m.contains("map_accuracy_max_m")
              ? " (> " + reportNumber(m, "map_accuracy_max_m", 1) + " m)"
              : "");
}

/// Times each graph edge is driven by `route` (NaN: never), for the route picture's colours.
std::vector<double> timesDriven(const RoadGraph& graph, const Route& route) {
  std::vector<double> times(graph.edges.size(), std::numeric_limits<double>::quiet_NaN());
  for (int e : route.edges) {
    if (e < 0 || static_cast<std::size_t>(e) >= times.size()) continue;
    double& t = times[static_cast<std::size_t>(e)];
    t = std::isfinite(t) ? t + 1 : 1;
  }
  return times;
}

/// The simulated city's top view, when a drive left its world.
void writeWorldPicture(std::ostringstream& md, const ReportData& data) {
  if (!data.world) return;
  data.world->renderTopDownPng(data.pictures / "world.png", 0.5);
  md << "The simulated city (top view, coloured by height): buildings, walls, poles and trees "
        "along the streets; feature-poor (open, long uniform walls) and feature-rich streets.\n\n"
     << "![simulated world](report/world.png)\n\n";
}

/// "a / b" from two numbers of `j`'s object `obj`, or "–".
std::string drivenOf(const json& j, const char* obj, const char* a, const char* b) {
  if (!j.contains(obj)) return "–";
  return reportNumber(j[obj], a, 0) + " / " + reportNumber(j[obj], b, 0);
}

/// "pct (n)": the junction-level part's directed figure and its edges without a legal route.
std::string junctionPart(const json& d) {
  if (!d.contains("junction_part")) return "–";
  return reportNumber(d["junction_part"], "edges_pct", 1) + " (" +
         reportNumber(d["junction_part"], "edges_without_legal_route", 0) + ")";
}

/// The primary coverage figures: directed SUMO edges of the drivable part (count and length),
/// planned (route.json) and as driven (metrics.json), beside the two-way figure on the extracted
/// graph; the route's length on the graph, in SUMO (edges + junction lanes) and as driven.
void coverageTable(std::ostringstream& md, const ReportData& data) {
  md << "Coverage counts each direction of a street (a two-way street driven one way is half "
        "covered) over the SUMO edges a passenger car can drive round legally (the net's largest "
        "part strongly connected under its turn permissions; junction-internal edges excluded). "
        "The junction-level part (strongly connected over junctions, turns ignored) also holds "
        "edges no legal drive enters and leaves again, e.g. streets to the map border where cars "
        "may not turn round: its figure and how many such edges it has are beside. The two-way "
        "figure counts a street once, on the graph built from the survey.\n\n"
     << "| planner | directed SUMO edges [%] | edges driven / drivable | directed length [%] | "
        "directed edges as driven [%] | junction-level part [%] (no legal route) | two-way graph "
        "coverage [%] | length on the graph [km] | length in SUMO [km] (of it in junctions) | "
        "driven [km] |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : data.in.planners) {
    const json r = routeJson(data, p);
    const json m = pipeline::readJsonIfPresent(data.in.out / "eval" / p / "metrics.json");
    const json d = r.value("directed_coverage", json::object());
    const json l = r.value("sumo_length", json::object());
    const json md_cov = m.value("directed_coverage", json::object());
    const json ml = m.value("sumo_length", json::object());
    md << "| " << p << " | " << reportNumber(d, "edges_pct", 1) << " | "
       << drivenOf(r, "directed_coverage", "edges_driven", "edges_total") << " | "
       << reportNumber(d, "length_pct", 1) << " | " << reportNumber(md_cov, "edges_pct", 1) << " | "
       << junctionPart(d) << " | " << reportNumber(r, "edge_coverage_pct", 1) << " | "
       << reportNumber(r, "length_m", 2, 1e-3) << " | " << reportNumber(l, "total_m", 2, 1e-3)
       << " (" << reportNumber(l, "in_junctions_m", 2, 1e-3) << ") | "
       << reportNumber(ml, "total_m", 2, 1e-3) << " |\n";
  }
  md << "\n";
}

}  // namespace

void writeHeaderSection(std::ostringstream& md, const ReportData& data) {
  const ReportInputs& in = data.in;
  md << "# slamroute report\n\n"
     << "Net: `" << in.net << "`  \nCommand: `" << in.command
     << "`  \nTotal time: " << reportNumber(in.total_seconds, 1) << " s";
  const auto kept = std::count_if(in.step_seconds.begin(), in.step_seconds.end(),
                                  [](const auto& st) { return std::isnan(st.second); });
  if (kept > 0)
    md << " (this run; " << kept << " of " << in.step_seconds.size()
       << " steps kept from an earlier one)";
  md << "\n\n";
}

void writeRoadGraphSection(std::ostringstream& md, const ReportData& data) {
  md << "## Road graph (paper §3.1)\n\n";
  if (data.survey.is_object() && !data.survey.empty())
    md << figureTable("survey", data.survey, surveyFigures(), "survey.json");
  md << "Extracted graph: " << data.graph.nodes.size() << " nodes, " << data.graph.edges.size()
     << " directed edges, " << reportNumber(data.graph.totalLength() / 1000.0, 2) << " km.\n\n";
  // The graph's metadata sections: validation against the net, extraction statistics, depth
  // weights, and how the graph maps onto the net's edges and turns.
  for (const char* section : {"validation", "stats", "weights", "sumo_mapping"})
    if (data.graph_meta.contains(section) && data.graph_meta[section].is_object())
      md << figureTable(section, data.graph_meta[section], graphFigures(section),
                        "graph.json, metadata." + std::string(section));
  writeWorldPicture(md, data);
  data.graph.renderPng(data.pictures / "graph_weights.png",
                       "edge weight (depth-normal spread score)");
  md << "![graph with edge weights](report/graph_weights.png)\n\n";
}

void writeResultsSection(std::ostringstream& md, const ReportData& data) {
  md << "## Routes and SLAM results (paper §3.2, §3.3)\n\n";
  coverageTable(md, data);
  md << "| planner | route length [km] | two-way graph coverage [%] | node coverage [%] | "
        "predicted loop "
        "closures | predicted final log-det cov | planning [s] | ATE RMSE [m] | ATE mean [m] | RPE "
        "[%] | loop closures found | map points: median distance to the world [m] / share farther "
        "than the clamp [%] | the same, map aligned like the ATE |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : data.in.planners) {
    const json r = routeJson(data, p);
    const json m = pipeline::readJsonIfPresent(data.in.out / "eval" / p / "metrics.json");
    md << "| " << p << " | " << reportNumber(r, "length_m", 2, 1e-3) << " | "
       << reportNumber(r, "edge_coverage_pct", 1) << " | "
       << reportNumber(r, "node_coverage_pct", 1) << " | " << reportNumber(r, "loop_closures", 0)
       << " | " << reportNumber(r, "final_logdet_cov", 2) << " | "
       << reportNumber(r, "planning_seconds", 3) << " | " << reportNumber(m, "ate_rmse_m", 3)
       << " | " << reportNumber(m, "ate_mean_m", 3) << " | " << reportNumber(m, "rpe_trans_pct", 2)
       << " | " << reportNumber(m, "loop_closures", 0) << " | " << mapCell(m, "map_") << " | "
       << mapCell(m, "map_aligned_") << " |\n";
  }
  md << "\n";
}

/// C_k (rl/Uncertainty.hpp) along each planned route against the bound the coverage planners
/// keep: peak, mean, whether it held, and the revisits aco-ga / switching / ER inserted.
void writeUncertaintySection(std::ostringstream& md, const ReportData& data) {
  md << "Predicted pose uncertainty C_k = sqrt(det EIF position covariance) along each route "
        "(the bound aco-ga, switching and exhaustive-revisit keep when they can):\n\n"
     << "| planner | C_max [m^2] | C_average [m^2] | C_threshold [m^2] | bound kept | loop-closure "
        "revisits |\n|---|---|---|---|---|---|\n";
  for (const auto& p : data.in.planners) {
    const json x = routeJson(data, p).value("extra", json::object());
    const json u = x.value("uncertainty", json::object());
    md << "| " << p << " | " << reportNumber(u, "c_max_m2", 1) << " | "
       << reportNumber(u, "c_average_m2", 1) << " | " << reportNumber(u, "c_threshold_m2", 1)
       << " | "
       << (u.contains("bound_satisfied") ? (u["bound_satisfied"].get<bool>() ? "yes" : "no") : "–")
       << " | " << reportNumber(x, "loop_closure_revisits", 0) << " |\n";
  }
  md << "\n";
}

/// Per planner: its route coloured by how often each edge is driven, its notes, and the
/// evaluation's pictures.
void writePlannerPicturesSection(std::ostringstream& md, const ReportData& data) {
  for (const auto& p : data.in.planners) {
    md << "### " << p << "\n\n";
    const fs::path rj = data.in.out / "routes" / (p + ".json");
    if (fs::exists(rj)) {
      const Route route = Route::readJson(rj);
      data.graph.renderPng(data.pictures / ("route_" + p + ".png"),
                           p + ": times each edge is driven (grey: never)",
                           timesDriven(data.graph, route));
      md << "![" << p << " route](report/route_" << p << ".png)\n\n";
      if (!route.notes.empty()) md << "Planner notes: " << route.notes << "\n\n";
    }
    const fs::path ev = data.in.out / "eval" / p;
    if (!fs::exists(ev)) continue;
    for (const auto& f : fs::directory_iterator(ev))
      if (f.path().extension() == ".png" && f.path().filename() != kFrontierPng)  // own section
        md << "![" << p << " " << f.path().stem().string() << "](eval/" << p << "/"
           << f.path().filename().string() << ")\n\n";
  }
}

void writeStepTimesSection(std::ostringstream& md, const ReportData& data) {
  md << "## Step times\n\n| step | seconds |\n|---|---|\n";
  for (const auto& [name, s] : data.in.step_seconds)
    md << "| " << name << " | "
       << (std::isnan(s) ? std::string("kept from an earlier run") : reportNumber(s, 1)) << " |\n";
}

}  // namespace slamroute::cli
