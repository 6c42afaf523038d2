// planFleet(): planning graph, depots, the single postman circuit (L1, the anchor of the bound),
// the strategy, then the fleet's figures.
#include <algorithm>
#include <chrono>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "FleetParts.hpp"
#include "MakespanBound.hpp"
#include "RuralPostman.hpp"
#include "slamroute/core/Hungarian.hpp"
#include "slamroute/rl/Fleet.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {
namespace {
std::size_t sz(int i) { return static_cast<std::size_t>(i); }
}  // namespace

namespace fleet {

FleetContext makeContext(const RoadGraph& g, const PlanGraph& pg, const TurnPaths& paths,
                         std::vector<int> depot_local) {
  FleetContext ctx{g, pg, paths, std::move(depot_local), {}, {}};
  for (int d : ctx.depot) {
    ctx.from_depot.push_back(paths.distances(-1, d));
    ctx.to_depot.push_back(distancesToNode(pg, d));
  }
  return ctx;
}

std::vector<int> assignToVehicles(const std::vector<std::vector<double>>& cost) {
  return hungarianAssignment(cost).columnOfRow;
}

}  // namespace fleet

namespace {

using fleet::FleetContext;

std::vector<int> localDepots(const PlanGraph& pg, const Config& cfg, std::vector<int> nodes,
                             const std::string& where) {
  const int k = cfg.fleet.vehicles;
  if (nodes.empty()) nodes.push_back(cfg.start_node >= 0 ? cfg.start_node : pg.node_orig[0]);
  if (nodes.size() == 1) nodes.assign(sz(k), nodes.front());
  if (static_cast<int>(nodes.size()) != k)
    throw std::invalid_argument(where + ": " + std::to_string(nodes.size()) + " depots for " +
                                std::to_string(k) + " vehicles (give one, or one per vehicle)");
  std::vector<int> local;
  for (int node : nodes) {
    const int l =
        node >= 0 && node < static_cast<int>(pg.node_local.size()) ? pg.node_local[sz(node)] : -1;
    if (l < 0)
      throw std::invalid_argument(where + ": depot node " + std::to_string(node) +
                                  " is not in the legally drivable part of the graph");
    local.push_back(l);
  }
  return local;
}

/// max over edges of the shortest round trip from the nearest depot through the edge.
double longestRoundTrip(const FleetContext& ctx) {
  double longest = 0.0;
  for (int e = 0; e < ctx.pg.m; ++e) {
    double best = std::numeric_limits<double>::infinity();
    for (int v = 0; v < ctx.vehicles(); ++v)
      best = std::min(best, ctx.from_depot[sz(v)][sz(e)] + ctx.to_depot[sz(v)][sz(e)]);
    longest = std::max(longest, best);
  }
  return longest;
}

void fillCoverage(const FleetContext& ctx, const std::vector<std::vector<int>>& routes,
                  FleetRoute& f) {
  std::vector<char> driven(sz(ctx.pg.m), 0);
  std::set<std::string> sumo_all, sumo_driven;
  for (const auto& r : routes)
    for (int e : r) driven[sz(e)] = 1;
  for (int e = 0; e < ctx.pg.m; ++e)
    for (const auto& s : ctx.g.edges[sz(ctx.pg.edge_orig[sz(e)])].sumo_edges) {
      sumo_all.insert(s);
      if (driven[sz(e)]) sumo_driven.insert(s);
    }
  f.edge_coverage_pct =
      100.0 * static_cast<double>(std::count(driven.begin(), driven.end(), 1)) / ctx.pg.m;
  f.sumo_edge_coverage_pct =
      sumo_all.empty() ? 0.0 : 100.0 * static_cast<double>(sumo_driven.size()) / sumo_all.size();
}

Route vehicleRoute(const FleetContext& ctx, const Config& cfg, std::uint64_t seed,
                   const std::vector<int>& edges, int vehicle) {
  Route r;
  r.planner = "fleet-" + cfg.fleet.strategy;
  r.seed = seed;
  r.heuristic = true;
  fillRouteMetrics(ctx.pg, ctx.g, ctx.depot[sz(vehicle)], edges, cfg.eif, r);
  r.extra_json = nlohmann::json{{"vehicle", vehicle},
                                {"depot_node", ctx.pg.node_orig[sz(ctx.depot[sz(vehicle)])]},
                                {"illegal_turns", countIllegalTurns(ctx.pg, edges)}}
                     .dump();
  return r;
}

FleetRoute summarise(const FleetContext& ctx, const Config& cfg, std::uint64_t seed,
                     const std::vector<std::vector<int>>& routes, double single_m) {
  FleetRoute f;
  f.strategy = cfg.fleet.strategy;
  f.seed = seed;
  for (int v = 0; v < ctx.vehicles(); ++v) {
    f.vehicles.push_back(vehicleRoute(ctx, cfg, seed, routes[sz(v)], v));
    f.depot_nodes.push_back(ctx.pg.node_orig[sz(ctx.depot[sz(v)])]);
    f.makespan_m = std::max(f.makespan_m, f.vehicles.back().length_m);
    f.total_length_m += f.vehicles.back().length_m;
  }
  f.balance = f.total_length_m > 0 ? f.makespan_m * ctx.vehicles() / f.total_length_m : 0.0;
  f.single_route_m = single_m;
  f.longest_round_trip_m = longestRoundTrip(ctx);
  f.lower_bound_m = std::max(single_m / ctx.vehicles(), f.longest_round_trip_m);
  const std::vector<fleet::EdgeReach> reach = fleet::edgeReaches(ctx);
  f.depot_bound_m = std::max({f.longest_round_trip_m, fleet::depotTripsBound(reach, ctx.vehicles()),
                              fleet::farFlowBound(ctx.pg, reach, ctx.vehicles())});
  fillCoverage(ctx, routes, f);
  return f;
}

}  // namespace

FleetRoute planFleet(const RoadGraph& g, const Config& cfg, const std::vector<int>& depot_nodes,
                     std::uint64_t seed, const std::string& where) {
  cfg.fleet.validate();
  const auto t0 = std::chrono::steady_clock::now();
  const PlanGraph pg = PlanGraph::build(g, where);
  if (cfg.fleet.vehicles > pg.num_streets)
    throw std::invalid_argument(where + ": " + std::to_string(cfg.fleet.vehicles) +
                                " vehicles for " + std::to_string(pg.num_streets) + " streets");
  const TurnPaths paths(pg);
  const FleetContext ctx =
      fleet::makeContext(g, pg, paths, localDepots(pg, cfg, depot_nodes, where));
  Config single = cfg;
  single.postman.closed = true;
  const std::vector<int> circuit = planPostman(pg, paths, single, ctx.depot[0]).edges;
  fleet::StrategyStats stats;
  const auto routes = cfg.fleet.strategy == "partition"
                          ? fleet::partitionRoutes(ctx, cfg.fleet, seed, circuit, stats)
                          : fleet::splitCircuitRoutes(ctx, circuit, stats);
  FleetRoute f = summarise(ctx, cfg, seed, routes, fleet::routeLength(pg, circuit));
  f.planning_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  f.extra_json = nlohmann::json{{"makespan_before_moves_m", stats.makespan_before_moves_m},
                                {"balance_moves", stats.balance_moves},
                                {"legs", stats.legs},
                                {"partition_start", stats.start},
                                {"plan_graph_edges", pg.m},
                                {"dropped_edges", pg.dropped_edges}}
                     .dump();
  return f;
}

}  // namespace slamroute::rl
