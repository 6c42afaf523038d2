// route.json and SUMO .rou.xml I/O.
#include "slamroute/core/Route.hpp"

#include <nlohmann/json.hpp>

#include <sstream>
#include <stdexcept>

#include "JsonFile.hpp"
#include "RouteJson.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
using nlohmann::json;

namespace detail {

Route routeFromJsonObject(const json& j) {
  Route r;
  r.planner = j.value("planner", std::string("manual"));
  r.seed = j.value("seed", std::uint64_t{0});
  if (j.contains("nodes")) r.nodes = j.at("nodes").get<std::vector<int>>();
  if (j.contains("edges")) r.edges = j.at("edges").get<std::vector<int>>();
  if (j.contains("sumo_edges")) r.sumo_edges = j.at("sumo_edges").get<std::vector<std::string>>();
  r.length_m = j.value("length_m", 0.0);
  r.node_coverage_pct = j.value("node_coverage_pct", 0.0);
  r.edge_coverage_pct = j.value("edge_coverage_pct", 0.0);
  r.revisits = j.value("revisits", 0);
  r.loop_closures = j.value("loop_closures", 0);
  r.mean_edge_weight = j.value("mean_edge_weight", 0.0);
  r.final_logdet_cov = j.value("final_logdet_cov", 0.0);
  r.max_logdet_cov = j.value("max_logdet_cov", 0.0);
  if (j.contains("logdet_cov_along"))
    r.logdet_cov_along = j.at("logdet_cov_along").get<std::vector<double>>();
  r.planning_seconds = j.value("planning_seconds", 0.0);
  r.heuristic = j.value("heuristic", false);
  r.completed_by_shortest_paths = j.value("completed_by_shortest_paths", false);
  r.notes = j.value("notes", std::string());
  if (j.contains("extra")) r.extra_json = j.at("extra").dump();
  r.sumo_coverage = sumoCoverageFromJson(j);
  return r;
}

json routeToJson(const Route& r) {
  json j = {{"planner", r.planner},
            {"seed", r.seed},
            {"length_m", r.length_m},
            {"node_coverage_pct", r.node_coverage_pct},
            {"edge_coverage_pct", r.edge_coverage_pct},
            {"revisits", r.revisits},
            {"loop_closures", r.loop_closures},
            {"mean_edge_weight", r.mean_edge_weight},
            {"final_logdet_cov", r.final_logdet_cov},
            {"max_logdet_cov", r.max_logdet_cov},
            {"planning_seconds", r.planning_seconds},
            {"heuristic", r.heuristic},
            {"completed_by_shortest_paths", r.completed_by_shortest_paths},
            {"notes", r.notes},
            {"nodes", r.nodes},
            {"edges", r.edges},
            {"sumo_edges", r.sumo_edges},
            {"logdet_cov_along", r.logdet_cov_along},
            {"extra", json::parse(r.extra_json.empty() ? "{}" : r.extra_json)}};
  if (r.sumo_coverage) sumoCoverageToJson(*r.sumo_coverage, j);
  return j;
}

}  // namespace detail

Route Route::readJson(const std::filesystem::path& path) {
  const std::string name = path.string();
  const json j = detail::readJsonFile(path);
  Route r;
  try {
    if (j.is_array()) {  // plain list of SUMO edge ids
      r.planner = "manual";
      r.sumo_edges = j.get<std::vector<std::string>>();
    } else if (j.is_object()) {
      r = detail::routeFromJsonObject(j);
    } else {
      throw std::invalid_argument(name + ": a route must be a JSON object or a list of SUMO edges");
    }
  } catch (const json::exception& e) {
    throw std::invalid_argument(name + ": malformed route (" + detail::jsonErrorText(e) + ")");
  }
  if (r.sumo_edges.empty() && r.edges.empty())
    throw std::invalid_argument(name + ": the route is empty");
  return r;
}

void Route::writeJson(const std::filesystem::path& path) const {
  const json j = detail::routeToJson(*this);
  detail::requireFiniteNumbers(j, path.string());
  writeFileAtomic(path, j.dump(1) + "\n");
}

void Route::writeRouXml(const std::filesystem::path& path, const std::string& vehicle_id) const {
  if (sumo_edges.empty())
    throw std::invalid_argument(path.string() + ": route has no SUMO edges to write");
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<!-- slamroute " << planner << " route, seed " << seed << " -->\n"
     << "<routes>\n"
     << detail::kMappingCarType << detail::vehicleXml(*this, vehicle_id) << "</routes>\n";
  writeFileAtomic(path, os.str());
}

namespace detail {

std::string vehicleXml(const Route& r, const std::string& vehicle_id) {
  std::ostringstream os;
  os << "  <vehicle id=\"" << vehicle_id
     << "\" type=\"mapping_car\" depart=\"0\" departLane=\"best\" departSpeed=\"max\">\n"
     << "    <route edges=\"";
  for (std::size_t i = 0; i < r.sumo_edges.size(); ++i) os << (i ? " " : "") << r.sumo_edges[i];
  os << "\"/>\n  </vehicle>\n";
  return os.str();
}

}  // namespace detail

}  // namespace slamroute
