// A fleet's route.json and .rou.xml.
#include "slamroute/core/FleetRoute.hpp"

#include <nlohmann/json.hpp>

#include <sstream>
#include <stdexcept>

#include "JsonFile.hpp"
#include "RouteJson.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
using nlohmann::json;

namespace {

json summaryJson(const FleetRoute& f) {
  return {{"strategy", f.strategy},
          {"vehicles", f.vehicles.size()},
          {"seed", f.seed},
          {"depot_nodes", f.depot_nodes},
          {"makespan_m", f.makespan_m},
          {"total_length_m", f.total_length_m},
          {"balance", f.balance},
          {"single_route_m", f.single_route_m},
          {"longest_round_trip_m", f.longest_round_trip_m},
          {"lower_bound_m", f.lower_bound_m},
          {"makespan_over_bound", f.lower_bound_m > 0 ? f.makespan_m / f.lower_bound_m : 0.0},
          {"depot_bound_m", f.depot_bound_m},
          {"makespan_over_depot_bound", f.depot_bound_m > 0 ? f.makespan_m / f.depot_bound_m : 0.0},
          {"total_over_single", f.single_route_m > 0 ? f.total_length_m / f.single_route_m : 0.0},
          {"edge_coverage_pct", f.edge_coverage_pct},
          {"sumo_edge_coverage_pct", f.sumo_edge_coverage_pct},
          {"planning_seconds", f.planning_seconds},
          {"extra", json::parse(f.extra_json.empty() ? "{}" : f.extra_json)}};
}

void readSummary(const json& s, FleetRoute& f) {
  f.strategy = s.value("strategy", std::string());
  f.seed = s.value("seed", std::uint64_t{0});
  if (s.contains("depot_nodes")) f.depot_nodes = s.at("depot_nodes").get<std::vector<int>>();
  f.makespan_m = s.value("makespan_m", 0.0);
  f.total_length_m = s.value("total_length_m", 0.0);
  f.balance = s.value("balance", 0.0);
  f.single_route_m = s.value("single_route_m", 0.0);
  f.longest_round_trip_m = s.value("longest_round_trip_m", 0.0);
  f.lower_bound_m = s.value("lower_bound_m", 0.0);
  f.depot_bound_m = s.value("depot_bound_m", 0.0);
  f.edge_coverage_pct = s.value("edge_coverage_pct", 0.0);
  f.sumo_edge_coverage_pct = s.value("sumo_edge_coverage_pct", 0.0);
  f.planning_seconds = s.value("planning_seconds", 0.0);
  if (s.contains("extra")) f.extra_json = s.at("extra").dump();
}

}  // namespace

bool FleetRoute::isFleetFile(const std::filesystem::path& path) {
  const json j = detail::readJsonFile(path);
  return j.is_object() && j.contains("vehicles") && j.at("vehicles").is_array();
}

FleetRoute FleetRoute::readJson(const std::filesystem::path& path) {
  const std::string name = path.string();
  const json j = detail::readJsonFile(path);
  FleetRoute f;
  try {
    if (!j.is_object() || !j.contains("vehicles") || !j.at("vehicles").is_array())
      throw std::invalid_argument(name + ": a fleet route needs a \"vehicles\" list");
    if (j.contains("fleet")) readSummary(j.at("fleet"), f);
    for (const json& v : j.at("vehicles")) f.vehicles.push_back(detail::routeFromJsonObject(v));
  } catch (const json::exception& e) {
    throw std::invalid_argument(name + ": malformed fleet route (" + detail::jsonErrorText(e) +
                                ")");
  }
  if (f.vehicles.empty()) throw std::invalid_argument(name + ": the fleet has no vehicle");
  for (std::size_t i = 0; i < f.vehicles.size(); ++i)
    if (f.vehicles[i].sumo_edges.empty() && f.vehicles[i].edges.empty())
      throw std::invalid_argument(name + ": vehicle " + std::to_string(i) + " has an empty route");
  return f;
}

void FleetRoute::writeJson(const std::filesystem::path& path) const {
  json j = {{"fleet", summaryJson(*this)}, {"vehicles", json::array()}};
  for (const Route& r : vehicles) j["vehicles"].push_back(detail::routeToJson(r));
  detail::requireFiniteNumbers(j, path.string());
  writeFileAtomic(path, j.dump(1) + "\n");
}

void FleetRoute::writeRouXml(const std::filesystem::path& path) const {
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<!-- slamroute fleet (" << strategy << ", " << vehicles.size() << " vehicles), seed "
     << seed << " -->\n"
     << "<routes>\n"
     << detail::kMappingCarType;
  for (std::size_t i = 0; i < vehicles.size(); ++i) {
    if (vehicles[i].sumo_edges.empty())
      throw std::invalid_argument(path.string() + ": vehicle " + std::to_string(i) +
                                  " has no SUMO edges to write");
    os << detail::vehicleXml(vehicles[i], vehicleId(i));
  }
  os << "</routes>\n";
  writeFileAtomic(path, os.str());
}

}  // namespace slamroute
