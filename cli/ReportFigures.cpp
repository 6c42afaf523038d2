#include "ReportFigures.hpp"

#include <iomanip>
#include <map>
#include <sstream>

namespace slamroute::cli {
using nlohmann::json;

const std::vector<Figure>& surveyFigures() {
  static const std::vector<Figure> f = {
      {"survey_vehicles", "survey vehicles", "", 0, "cars driving covering routes"},
      {"background_vehicles", "background vehicles", "", 0, "other traffic (random trips)"},
      {"trace_rows", "trace points", "", 0, "rows of traces.csv: one position per car and tick"},
      {"trace_hz", "trace rate", " Hz", 1, "positions recorded per second and car"},
      {"noise_sigma_m", "position noise", " m", 2, "GPS-like error per axis, 1 sigma"},
      {"noise_tau_s", "noise correlation time", " s", 1,
       "how long the position error keeps its direction (0: independent per point)"},
      {"depth_frames", "depth frames", "", 0, "depth images taken along the survey routes"},
      {"depth_spacing_m", "depth frame spacing", " m", 1, "distance a survey car drives per image"},
      {"drivable_edges", "drivable streets", "", 0, "SUMO edges open to passenger cars"},
      {"visited_edges", "streets driven", "", 0, "of those, driven by at least one car"},
      {"coverage_pct", "coverage", " %", 1, "share of the drivable streets driven"},
      {"planned_coverage_pct", "planned coverage", " %", 1,
       "share the covering routes were planned to drive"},
      {"unvisited_edges", "streets never driven", "", 0,
       "missing from the traces, so missing from the graph (ids in survey.json)"},
      {"sim_seconds", "simulated time", " s", 0, "SUMO time until the last survey car arrived"},
  };
  return f;
}

const std::vector<Figure>& graphFigures(const std::string& section) {
  static const std::map<std::string, std::vector<Figure>> f = {
      {"validation",
       {{"true_intersections", "intersections of the net", "", 0, "junctions with >= 3 streets"},
        {"detected_nodes", "intersections found", "", 0, "graph nodes that are not dead ends"},
        {"matched_nodes", "matched", "", 0, "found within the match radius of a true one"},
        {"node_precision", "node precision", "", 3, "share of found intersections that are real"},
        {"node_recall", "node recall", "", 3, "share of real intersections found"},
        {"node_f1", "node F1", "", 3, "harmonic mean of node precision and recall"},
        {"edge_precision", "street precision", "", 3, "share of graph streets that match a street"},
        {"edge_recall", "street recall", "", 3, "share of the net's streets the graph has"},
        {"missed_junctions", "missed intersections", "", 0, "listed in graph.json"},
        {"false_nodes", "false intersections", "", 0, "listed in graph.json"}}},
      {"stats",
       {{"trace_points", "trace points", "", 0, "positions the graph was built from"},
        {"intersection_points", "intersection points", "", 0,
         "points whose hollow cylinder saw >= 3 branches"},
        {"intersections", "intersections", "", 0, "nodes where >= 3 streets meet"},
        {"dead_ends", "dead ends", "", 0, "nodes with one street"},
        {"streets", "streets", "", 0, "both directions of a road count once"},
        {"one_way_streets", "one-way streets", "", 0, "driven in one direction only"},
        {"roundabouts", "roundabouts", "", 0, "rings the cars circled, each one junction"},
        {"seconds", "extraction time", " s", 1, "wall-clock time of the graph extraction"}}},
      {"weights",
       {{"frames", "depth frames", "", 0, "depth images read"},
        {"scored", "frames scored", "", 0, "images that gave a score"},
        {"failed", "frames skipped", "", 0, "unreadable, odd-sized or unusable (see the log)"},
        {"streets_with_frames", "streets with frames", "", 0,
         "others get the mean score of all frames"},
        {"mean_score", "mean score", "", 3,
         "spread of the surface normals seen, 0 (one plane) to 1 (every direction)"}}},
      {"sumo_mapping",
       {{"unmapped_edges", "edges without SUMO edges", "", 0,
         "graph edges no SUMO edge lies along (links inside junctions)"},
        {"candidate_turns", "turns checked", "", 0, "turns of the graph looked up in the net"},
        {"forbidden_turns", "turns forbidden", "", 0, "turns the net does not allow"}}},
  };
  static const std::vector<Figure> none;
  const auto it = f.find(section);
  return it == f.end() ? none : it->second;
}

std::string figureTable(const std::string& title, const json& obj,
                        const std::vector<Figure>& figures, const std::string& source) {
  std::ostringstream md;
  md << "| " << title << " | value | meaning |\n|---|---|---|\n";
  for (const Figure& f : figures) {
    if (!obj.contains(f.key)) continue;
    const json& v = obj.at(f.key);
    std::ostringstream value;
    if (v.is_number_float())
      value << std::fixed << std::setprecision(f.precision) << v.get<double>();
    else if (v.is_number())
      value << v.dump();
    else if (v.is_boolean())
      value << (v.get<bool>() ? "yes" : "no");
    else if (v.is_array())
      value << v.size();
    else
      continue;
    md << "| " << f.name << " | " << value.str() << f.unit << " | " << f.meaning << " |\n";
  }
  md << "\nEvery figure under its key: " << source << ".\n\n";
  return md.str();
}

}  // namespace slamroute::cli
