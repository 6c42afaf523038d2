// `plan --vehicles K`: depots from SUMO edge ids, the fleet planner, its two files.
#include "PlanFleet.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>

#include "CrewFiles.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/export/ExportFleet.hpp"
#include "slamroute/export/ExportRoute.hpp"
#include "slamroute/rl/Fleet.hpp"

namespace slamroute::cli {
namespace {

/// The node a depot edge starts at: a SUMO edge id, or else a road-graph edge id.
int depotNode(const RoadGraph& g, const std::string& edge, const std::string& where) {
  for (const auto& e : g.edges)
    for (const auto& s : e.sumo_edges)
      if (s == edge) return e.u;
  const bool numeric = !edge.empty() && edge.find_first_not_of("0123456789") == std::string::npos;
  if (numeric && std::stoull(edge) < g.edges.size()) return g.edges[std::stoul(edge)].u;
  throw std::invalid_argument(where + ": depot edge '" + edge + "' is not in the network");
}

std::vector<int> depotNodes(const RoadGraph& g, const FleetPlanOptions& o,
                            const std::string& where) {
  if (!o.depot.empty() && !o.depots.empty())
    throw std::invalid_argument("plan: give --depot or --depots, not both");
  std::vector<int> nodes;
  std::stringstream list(o.depot.empty() ? o.depots : o.depot);
  for (std::string edge; std::getline(list, edge, ',');) nodes.push_back(depotNode(g, edge, where));
  return nodes;
}

std::string strategyOf(const std::string& planner, int vehicles) {
  if (planner == "partition" || planner == "postman") return planner;
  throw std::invalid_argument("plan: planner '" + planner + "' cannot share the streets among " +
                              std::to_string(vehicles) + " vehicles (use postman or partition)");
}

/// route.json, .rou.xml and the vehicles' crew files replaced together; returns the note on a
/// net without geo-reference.
std::string writeFleetFiles(const Context& ctx, const FleetRoute& f,
                            const std::filesystem::path& out, bool with_rou, const SumoNet* net,
                            const std::string& geo_origin) {
  std::filesystem::path rou = out;
  rou.replace_extension(".rou.xml");
  AtomicFileSet files;
  f.writeJson(files.staged(out));
  if (with_rou)
    f.writeRouXml(files.staged(rou));
  else
    files.dropAtCommit(rou);
  for (const auto& crew : exports::crewFilePaths(out)) files.dropAtCommit(crew);
  std::string note;
  if (net)
    note = stageFleetCrewFiles(ctx, *net, f, out, geo_origin, files);
  else
    for (const auto& old : exports::existingVehicleFiles(out)) files.dropAtCommit(old);
  files.commit();
  return note;
}

void printSummary(const FleetRoute& f, const std::filesystem::path& out, bool with_rou) {
  std::cout << std::fixed << std::setprecision(2) << f.strategy << ": " << f.vehicles.size()
            << " vehicles, makespan " << f.makespan_m / 1000.0 << " km (lower bound "
            << f.lower_bound_m / 1000.0 << " km, x" << f.makespan_m / f.lower_bound_m << "), total "
            << f.total_length_m / 1000.0 << " km (single route " << f.single_route_m / 1000.0
            << " km), balance " << f.balance << ", coverage " << std::setprecision(1)
            << f.edge_coverage_pct << " %, " << std::setprecision(2) << f.planning_seconds
            << " s\nwrote " << out.string()
            << (with_rou
                    ? " and " + std::filesystem::path(out).replace_extension(".rou.xml").string()
                    : "")
            << "\n";
}

}  // namespace

bool isFleetRequest(const rl::Config& cfg, const FleetPlanOptions& o) {
  return o.vehicles > 1 || (o.vehicles == 0 && cfg.fleet.vehicles > 1) || !o.depot.empty() ||
         !o.depots.empty() || cfg.planner == "partition";
}

void planFleetCommand(const Context& ctx, const RoadGraph& g, rl::Config cfg,
                      const FleetPlanOptions& o, const std::string& where,
                      const std::filesystem::path& out, const SumoNet* net) {
  if (o.vehicles > 0) cfg.fleet.vehicles = o.vehicles;
  cfg.fleet.strategy = strategyOf(cfg.planner, cfg.fleet.vehicles);
  const FleetRoute f = rl::planFleet(g, cfg, depotNodes(g, o, where), ctx.cfg.seed, where);
  bool with_rou = true;
  for (const Route& r : f.vehicles) with_rou = with_rou && !r.sumo_edges.empty();
  if (net && !with_rou)
    throw std::runtime_error(
        "plan: a vehicle's route has no SUMO edges; cannot write the .rou.xml");
  const std::string note = writeFleetFiles(ctx, f, out, with_rou, net, o.geo_origin);
  printSummary(f, out, with_rou);
  if (!note.empty()) logInfo("note: " + note);
}

}  // namespace slamroute::cli
