#include "Report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

#include "ReportFigures.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Drive.hpp"
#include "slamroute/pipeline/JsonFile.hpp"
#include "slamroute/pipeline/Plot.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string fmt(double v, int prec = 2) {
  if (!std::isfinite(v)) return "–";
  std::ostringstream o;
  o << std::fixed << std::setprecision(prec) << v;
  return o.str();
}

std::string num(const json& j, const char* key, int prec = 2, double scale = 1.0) {
  if (!j.contains(key) || !j[key].is_number()) return "–";
  return fmt(j[key].get<double>() * scale, prec);
}

/// C_k (rl/Uncertainty.hpp) along each planned route against the bound the coverage planners
/// keep: peak, mean, whether it held, and the revisits aco-ga / switching / ER inserted.
void uncertaintyTable(std::ostringstream& md, const ReportInputs& in) {
  md << "Predicted pose uncertainty C_k = sqrt(det EIF position covariance) along each route "
        "(the bound aco-ga, switching and exhaustive-revisit keep when they can):\n\n"
     << "| planner | C_max [m^2] | C_average [m^2] | C_threshold [m^2] | bound kept | loop-closure "
        "revisits |\n|---|---|---|---|---|---|\n";
  for (const auto& p : in.planners) {
    const json r = pipeline::readJsonIfPresent(in.out / "routes" / (p + ".json"));
    const json x = r.value("extra", json::object());
    const json u = x.value("uncertainty", json::object());
    md << "| " << p << " | " << num(u, "c_max_m2", 1) << " | " << num(u, "c_average_m2", 1) << " | "
       << num(u, "c_threshold_m2", 1) << " | "
       << (u.contains("bound_satisfied") ? (u["bound_satisfied"].get<bool>() ? "yes" : "no") : "–")
       << " | " << num(x, "loop_closure_revisits", 0) << " |\n";
  }
  md << "\n";
}

/// "a / b" from two numbers of `j`'s object `obj`, or "–".
std::string drivenOf(const json& j, const char* obj, const char* a, const char* b) {
  if (!j.contains(obj)) return "–";
  return num(j[obj], a, 0) + " / " + num(j[obj], b, 0);
}

/// The primary coverage figures: directed SUMO edges of the drivable part (count and length),
/// planned (route.json) and as driven (metrics.json), beside the two-way figure on the extracted
/// graph; the route's length on the graph, in SUMO (edges + junction lanes) and as driven.
void coverageTable(std::ostringstream& md, const ReportInputs& in) {
  md << "Coverage counts each direction of a street (a two-way street driven one way is half "
        "covered) over the SUMO edges a passenger car can drive round (the net's largest strongly "
        "connected part; junction-internal edges excluded). The two-way figure counts a street "
        "once, on the graph built from the survey.\n\n"
     << "| planner | directed SUMO edges [%] | edges driven / drivable | directed length [%] | "
        "directed edges as driven [%] | two-way graph coverage [%] | length on the graph [km] | "
        "length in SUMO [km] (of it in junctions) | driven [km] |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : in.planners) {
    const json r = pipeline::readJsonIfPresent(in.out / "routes" / (p + ".json"));
    const json m = pipeline::readJsonIfPresent(in.out / "eval" / p / "metrics.json");
    const json d = r.value("directed_coverage", json::object());
    const json l = r.value("sumo_length", json::object());
    const json md_cov = m.value("directed_coverage", json::object());
    const json ml = m.value("sumo_length", json::object());
    md << "| " << p << " | " << num(d, "edges_pct", 1) << " | "
       << drivenOf(r, "directed_coverage", "edges_driven", "edges_total") << " | "
       << num(d, "length_pct", 1) << " | " << num(md_cov, "edges_pct", 1) << " | "
       << num(r, "edge_coverage_pct", 1) << " | " << num(r, "length_m", 2, 1e-3) << " | "
       << num(l, "total_m", 2, 1e-3) << " (" << num(l, "in_junctions_m", 2, 1e-3) << ") | "
       << num(ml, "total_m", 2, 1e-3) << " |\n";
  }
  md << "\n";
}

/// Per SUMO edge: length-weighted mean drift [%] over every planner's drive.
std::map<std::string, std::pair<double, double>> pooledDrift(const fs::path& out,
                                                             const std::vector<std::string>& planners) {
  std::map<std::string, std::pair<double, double>> acc;  // edge -> (sum drift*len, sum len)
  for (const auto& p : planners) {
    std::ifstream in(out / "eval" / p / "per_edge.csv");
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::vector<std::string> c;
      std::stringstream ss(line);
      std::string f;
      while (std::getline(ss, f, ',')) c.push_back(f);
      if (c.size() < 7) continue;
      try {
        const double len = std::stod(c[3]), drift = std::stod(c[6]);
        if (!std::isfinite(drift) || len < 20.0) continue;  // short pieces: drift is noise
        acc[c[0]].first += drift * len;
        acc[c[0]].second += len;
      } catch (const std::exception&) {
      }
    }
  }
  return acc;
}

/// Length-weighted mean drift per kind of street the simulated world lined the edge with: the
/// ground truth behind the depth-image weight (rich streets should drift least).
std::string driftByStreetKind(const simulate::World& world,
                              const std::map<std::string, std::pair<double, double>>& drift) {
  std::map<std::string, std::pair<double, double>> by_kind;  // kind -> (sum drift*len, sum len)
  for (const auto& [edge, dl] : drift) {
    std::string kind;
    try {
      kind = simulate::streetKindName(world.streetKind(edge));
    } catch (const std::exception&) {
      continue;  // not a street of this world
    }
    by_kind[kind].first += dl.first;
    by_kind[kind].second += dl.second;
  }
  std::ostringstream md;
  md << "Drift by the kind of street the simulated city lines it with (all drives pooled, "
        "length-weighted):\n\n| street kind | driven [km] | drift [%] |\n|---|---|---|\n";
  for (const auto& [kind, dl] : by_kind)
    md << "| " << kind << " | " << fmt(dl.second / 1000.0, 2) << " | " << fmt(dl.first / dl.second, 2) << " |\n";
  md << "\n";
  return md.str();
}

}  // namespace

void writeReport(const ReportInputs& in) {
  const fs::path rep = in.out / "report";
  fs::create_directories(rep);
  const RoadGraph graph = RoadGraph::readJson(in.graph_json);
  const json gmeta = json::parse(graph.metadata_json.empty() ? "{}" : graph.metadata_json);
  const json survey = pipeline::readJsonIfPresent(in.survey_dir / "survey.json");

  std::ostringstream md;
  md << "# slamroute report\n\n"
     << "Net: `" << in.net << "`  \nCommand: `" << in.command << "`  \nTotal time: "
     << fmt(in.total_seconds, 1) << " s";
  const auto kept = std::count_if(in.step_seconds.begin(), in.step_seconds.end(),
                                  [](const auto& st) { return std::isnan(st.second); });
  if (kept > 0) md << " (this run; " << kept << " of " << in.step_seconds.size() << " steps kept from an earlier one)";
  md << "\n\n";

  // --- survey and graph
  md << "## Road graph (paper §3.1)\n\n";
  if (survey.is_object() && !survey.empty())
    md << figureTable("survey", survey, surveyFigures(), "survey.json");
  md << "Extracted graph: " << graph.nodes.size() << " nodes, " << graph.edges.size()
     << " directed edges, " << fmt(graph.totalLength() / 1000.0, 2) << " km.\n\n";
  // The graph's metadata sections: validation against the net, extraction statistics, depth
  // weights, and how the graph maps onto the net's edges and turns.
  for (const char* section : {"validation", "stats", "weights", "sumo_mapping"})
    if (gmeta.contains(section) && gmeta[section].is_object())
      md << figureTable(section, gmeta[section], graphFigures(section),
                        "graph.json, metadata." + std::string(section));
  // The simulated 3D city the drives saw (rebuilt from the first drive's world.yaml: same net,
  // world config and seed for every drive of the run).
  std::optional<simulate::World> world;
  for (const auto& p : in.planners) {
    const fs::path drive = in.out / "drives" / p;
    if (!fs::exists(drive / "world.yaml")) continue;
    const simulate::DriveWorldFile wf = simulate::readDriveWorldFile(drive);
    world.emplace(simulate::World::build(SumoNet::read(wf.net), wf.world, wf.seed));
    world->renderTopDownPng(rep / "world.png", 0.5);
    md << "The simulated city (top view, coloured by height): buildings, walls, poles and trees "
          "along the streets; feature-poor (open, long uniform walls) and feature-rich streets.\n\n"
       << "![simulated world](report/world.png)\n\n";
    break;
  }
  graph.renderPng(rep / "graph_weights.png", "edge weight (depth-normal spread score)");
  md << "![graph with edge weights](report/graph_weights.png)\n\n";

  // --- routes and SLAM results
  md << "## Routes and SLAM results (paper §3.2, §3.3)\n\n";
  coverageTable(md, in);
  md << "| planner | route length [km] | two-way graph coverage [%] | node coverage [%] | predicted loop "
        "closures | predicted final log-det cov | planning [s] | ATE RMSE [m] | ATE mean [m] | RPE "
        "[%] | loop closures found | map points: median distance to the world [m] / share farther "
        "than the clamp [%] | the same, map aligned like the ATE |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : in.planners) {
    const json r = pipeline::readJsonIfPresent(in.out / "routes" / (p + ".json"));
    const json m = pipeline::readJsonIfPresent(in.out / "eval" / p / "metrics.json");
    // The median and the share beyond the clamp (map_accuracy_max_m, 2 m): a mean or a p95 of
    // clamped distances says more about the clamp than about the map. As built (in the frame the
    // estimate starts in) and aligned (evaluate's map_aligned_*: the map's own deformation).
    // With half the points or more beyond the clamp the median is the clamp, not a measurement:
    // it is written as "> clamp".
    const auto mapCell = [&](const std::string& prefix) -> std::string {
      if (!m.contains(prefix + "median_dist_m") || !m.contains(prefix + "far_share")) return "–";
      const bool saturated = m[prefix + "far_share"].is_number() &&
                             m[prefix + "far_share"].get<double>() >= 0.5 &&
                             m.contains("map_accuracy_max_m");
      const std::string median = saturated ? "> " + num(m, "map_accuracy_max_m", 1)
                                           : num(m, (prefix + "median_dist_m").c_str(), 2);
      return median + " / " + num(m, (prefix + "far_share").c_str(), 1, 100.0) +
             (m.contains("map_accuracy_max_m") ? " (> " + num(m, "map_accuracy_max_m", 1) + " m)" : "");
    };
    const std::string map_err = mapCell("map_"), map_aligned = mapCell("map_aligned_");
    md << "| " << p << " | " << num(r, "length_m", 2, 1e-3) << " | " << num(r, "edge_coverage_pct", 1)
       << " | " << num(r, "node_coverage_pct", 1) << " | " << num(r, "loop_closures", 0) << " | "
       << num(r, "final_logdet_cov", 2) << " | " << num(r, "planning_seconds", 3) << " | "
       << num(m, "ate_rmse_m", 3) << " | " << num(m, "ate_mean_m", 3) << " | "
       << num(m, "rpe_trans_pct", 2) << " | " << num(m, "loop_closures", 0) << " | " << map_err << " | "
       << map_aligned << " |\n";
  }
  md << "\n";
  uncertaintyTable(md, in);
  for (const auto& p : in.planners) {
    md << "### " << p << "\n\n";
    const fs::path rj = in.out / "routes" / (p + ".json");
    if (fs::exists(rj)) {
      const Route route = Route::readJson(rj);
      std::vector<double> times(graph.edges.size(), std::numeric_limits<double>::quiet_NaN());
      for (int e : route.edges)
        if (e >= 0 && static_cast<std::size_t>(e) < times.size())
          times[static_cast<std::size_t>(e)] = std::isfinite(times[static_cast<std::size_t>(e)])
                                                   ? times[static_cast<std::size_t>(e)] + 1
                                                   : 1;
      graph.renderPng(rep / ("route_" + p + ".png"), p + ": times each edge is driven (grey: never)", times);
      md << "![" << p << " route](report/route_" << p << ".png)\n\n";
      if (!route.notes.empty()) md << "Planner notes: " << route.notes << "\n\n";
    }
    const fs::path ev = in.out / "eval" / p;
    if (fs::exists(ev))
      for (const auto& f : fs::directory_iterator(ev))
        if (f.path().extension() == ".png")
          md << "![" << p << " " << f.path().stem().string() << "](eval/" << p << "/"
             << f.path().filename().string() << ")\n\n";
  }

  // --- the paper's premise: does the depth-image weight predict LiDAR drift?
  md << "## Does the edge weight predict LiDAR drift?\n\n";
  const auto drift = pooledDrift(in.out, in.planners);
  std::vector<double> w, d;
  for (const auto& e : graph.edges)
    for (const auto& se : e.sumo_edges) {
      auto it = drift.find(se);
      if (it == drift.end() || it->second.second <= 0) continue;
      w.push_back(e.weight);
      d.push_back(it->second.first / it->second.second);
    }
  const double rho = spearman(w, d);
  md << "Spearman rank correlation between an edge's depth-image weight and the measured "
        "translational drift on it (pooled over all drives, pieces >= 20 m): **rho = "
     << fmt(rho, 3) << "** over n = " << w.size()
     << " SUMO edges. The paper's premise predicts rho < 0 (a higher weight, i.e. more varied "
        "surface normals, should mean less drift).\n\n";
  if (!w.empty()) {
    pipeline::scatterPng(rep / "weight_vs_drift.png", w, d, "edge weight", "drift [%]");
    md << "![weight vs drift](report/weight_vs_drift.png)\n\n";
  }

  if (world) md << driftByStreetKind(*world, drift);

  md << "## Step times\n\n| step | seconds |\n|---|---|\n";
  for (const auto& [name, s] : in.step_seconds)
    md << "| " << name << " | " << (std::isnan(s) ? std::string("kept from an earlier run") : fmt(s, 1)) << " |\n";
  writeFileAtomic(in.out / "report.md", md.str());
}

}  // namespace slamroute::cli
