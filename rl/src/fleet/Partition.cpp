// The `partition` fleet strategy (seed paper: K-means segments, Hungarian assignment of
// segments to groups), on streets: parts by K-means on street midpoints, parts to vehicles by
// the Hungarian algorithm, a rural postman route per part, then moves of boundary streets from
// the longest route to a neighbouring part while each move shortens the longest route. A
// second start, the postman circuit's legs (routes and the edges each drives first), is
// balanced the same way and kept when its makespan is shorter (K-means parts ignore how far
// the depot is; the legs do not), so partition is never longer than the postman strategy.
// Parts hold directed edges: a street starts with both directions in one part, a move takes
// the directions of the street that the longest route's part holds.
#include <algorithm>
#include <limits>
#include <set>

#include "FleetParts.hpp"
#include "RuralPostman.hpp"
#include "slamroute/core/KMeans.hpp"

namespace slamroute::rl::fleet {
namespace {

std::size_t sz(int i) { return static_cast<std::size_t>(i); }

struct Partition {
  std::vector<int> part_of_edge;        ///< per directed edge: the vehicle driving it
  std::vector<std::vector<int>> route;  ///< per vehicle
  std::vector<double> length;           ///< per vehicle [m]
};

/// Street midpoints (what K-means clusters) and the edges meeting at each node.
struct Layout {
  std::vector<Point2> street_midpoint, edge_midpoint;
  std::vector<std::vector<int>> edges_at_node;
  std::vector<std::vector<int>> edges_of_street;  ///< its one or two directed edges
};

Layout layoutOf(const FleetContext& ctx) {
  const PlanGraph& pg = ctx.pg;
  Layout s{std::vector<Point2>(sz(pg.num_streets), Point2::Zero()), std::vector<Point2>(sz(pg.m)),
           std::vector<std::vector<int>>(sz(pg.n)),
           std::vector<std::vector<int>>(sz(pg.num_streets))};
  std::vector<int> count(sz(pg.num_streets), 0);
  for (int e = 0; e < pg.m; ++e) {
    const auto pos = [&](int node) {
      return ctx.g.nodes[sz(pg.node_orig[sz(node)])].pos.head<2>();
    };
    s.edge_midpoint[sz(e)] = 0.5 * (pos(pg.u[sz(e)]) + pos(pg.v[sz(e)]));
    s.street_midpoint[sz(pg.street[sz(e)])] += s.edge_midpoint[sz(e)];
    ++count[sz(pg.street[sz(e)])];
    s.edges_at_node[sz(pg.u[sz(e)])].push_back(e);
    s.edges_at_node[sz(pg.v[sz(e)])].push_back(e);
    s.edges_of_street[sz(pg.street[sz(e)])].push_back(e);
  }
  for (int st = 0; st < pg.num_streets; ++st) s.street_midpoint[sz(st)] /= count[sz(st)];
  return s;
}

std::vector<int> solvePart(const FleetContext& ctx, const std::vector<int>& part_of_edge,
                           int vehicle) {
  std::vector<char> required(sz(ctx.pg.m));
  for (int e = 0; e < ctx.pg.m; ++e) required[sz(e)] = part_of_edge[sz(e)] == vehicle;
  return ruralPostmanRoute(ctx.pg, ctx.paths, required, ctx.depot[sz(vehicle)]);
}

/// Row vehicle, column cluster: from the depot to the cluster's nearest edge and back.
std::vector<std::vector<double>> approachCosts(const FleetContext& ctx,
                                               const std::vector<int>& cluster_of_edge) {
  const double inf = std::numeric_limits<double>::infinity();
  const int k = ctx.vehicles();
  std::vector<std::vector<double>> cost(sz(k), std::vector<double>(sz(k)));
  for (int i = 0; i < k; ++i) {
    std::vector<double> in(sz(k), inf), out(sz(k), inf);
    for (int e = 0; e < ctx.pg.m; ++e) {
      const int c = cluster_of_edge[sz(e)];
      in[sz(c)] = std::min(in[sz(c)], ctx.from_depot[sz(i)][sz(e)]);
      out[sz(c)] = std::min(out[sz(c)], ctx.to_depot[sz(i)][sz(e)]);
    }
    for (int c = 0; c < k; ++c) cost[sz(i)][sz(c)] = in[sz(c)] + out[sz(c)];
  }
  return cost;
}

/// Per edge: its street's K-means cluster, clusters given to vehicles by the Hungarian algorithm.
std::vector<int> kMeansParts(const FleetContext& ctx, const FleetConfig& cfg, std::uint64_t seed,
                             const Layout& layout) {
  std::vector<double> weight(ctx.pg.street_len.begin(), ctx.pg.street_len.end());
  for (double& w : weight) w = std::max(w, 1e-3);
  const KMeansResult km =
      kMeans(layout.street_midpoint, ctx.vehicles(),
             {.seed = seed, .maxIterations = cfg.kmeans_iterations, .weight = weight});
  std::vector<int> cluster_of_edge;
  for (int e = 0; e < ctx.pg.m; ++e) cluster_of_edge.push_back(km.label[sz(ctx.pg.street[sz(e)])]);
  const std::vector<int> cluster_of_vehicle = assignToVehicles(approachCosts(ctx, cluster_of_edge));
  std::vector<int> vehicle_of_cluster(sz(ctx.vehicles()));
  for (int i = 0; i < ctx.vehicles(); ++i) vehicle_of_cluster[sz(cluster_of_vehicle[sz(i)])] = i;
  for (int& c : cluster_of_edge) c = vehicle_of_cluster[sz(c)];
  return cluster_of_edge;
}

/// Every vehicle has an edge, and every edge a vehicle.
bool usable(const std::vector<int>& part_of_edge, int vehicles) {
  std::vector<char> has(sz(vehicles), 0);
  for (int p : part_of_edge) {
    if (p < 0) return false;
    has[sz(p)] = 1;
  }
  return std::find(has.begin(), has.end(), 0) == has.end();
}

Partition routesOf(const FleetContext& ctx, std::vector<int> part_of_edge) {
  Partition p{std::move(part_of_edge), {}, {}};
  for (int i = 0; i < ctx.vehicles(); ++i) {
    p.route.push_back(solvePart(ctx, p.part_of_edge, i));
    p.length.push_back(routeLength(ctx.pg, p.route.back()));
  }
  return p;
}

/// (edge of part p, neighbouring part) pairs, the edges nearest the other part's centre
/// relative to their own first.
std::vector<std::pair<int, int>> boundaryMoves(const Layout& layout, const PlanGraph& pg,
                                               const Partition& part, int p) {
  const std::size_t k = part.route.size();
  std::vector<Point2> centre(k, Point2::Zero());
  std::vector<double> mass(k, 0.0);
  for (int e = 0; e < pg.m; ++e) {
    const int q = part.part_of_edge[sz(e)];
    centre[sz(q)] += pg.len[sz(e)] * layout.edge_midpoint[sz(e)];
    mass[sz(q)] += pg.len[sz(e)];
  }
  for (std::size_t q = 0; q < k; ++q) centre[q] /= std::max(mass[q], 1e-9);
  std::set<std::pair<int, int>> seen;
  std::vector<std::pair<double, std::pair<int, int>>> scored;
  for (int e = 0; e < pg.m; ++e) {
    if (part.part_of_edge[sz(e)] != p) continue;
    for (int node : {pg.u[sz(e)], pg.v[sz(e)]})
      for (int other : layout.edges_at_node[sz(node)]) {
        const int q = part.part_of_edge[sz(other)];
        if (q == p || !seen.insert({e, q}).second) continue;
        const Point2& mid = layout.edge_midpoint[sz(e)];
        scored.push_back({(mid - centre[sz(q)]).norm() - (mid - centre[sz(p)]).norm(), {e, q}});
      }
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<int, int>> moves;
  for (const auto& s : scored) moves.push_back(s.second);
  return moves;
}

/// The parts with edge e's street moved from e's part to q: both directions when e's part
/// holds both. Moving one direction alone seldom shortens a route: it still drives the street
/// the other way, and mostly the moved direction too, as the leg back.
std::vector<int> movedStreet(const Layout& layout, const PlanGraph& pg,
                             const std::vector<int>& part_of_edge, int e, int q) {
  std::vector<int> trial = part_of_edge;
  for (int d : layout.edges_of_street[sz(pg.street[sz(e)])])
    if (trial[sz(d)] == part_of_edge[sz(e)]) trial[sz(d)] = q;
  return trial;
}

/// One improving move of a boundary street off the longest route; false when none is found.
bool improveOnce(const FleetContext& ctx, const FleetConfig& cfg, const Layout& layout,
                 Partition& part) {
  const int p = static_cast<int>(std::max_element(part.length.begin(), part.length.end()) -
                                 part.length.begin());
  if (std::count(part.part_of_edge.begin(), part.part_of_edge.end(), p) <= 1) return false;
  const auto moves = boundaryMoves(layout, ctx.pg, part, p);
  for (std::size_t i = 0; i < moves.size() && static_cast<int>(i) < cfg.candidates_per_move; ++i) {
    const auto [e, q] = moves[i];
    std::vector<int> trial = movedStreet(layout, ctx.pg, part.part_of_edge, e, q);
    if (std::find(trial.begin(), trial.end(), p) == trial.end()) continue;  // p keeps an edge
    std::vector<int> route_p = solvePart(ctx, trial, p), route_q = solvePart(ctx, trial, q);
    const double lp = routeLength(ctx.pg, route_p), lq = routeLength(ctx.pg, route_q);
    if (std::max(lp, lq) >= part.length[sz(p)] - 1e-6) continue;
    part.part_of_edge = std::move(trial);
    part.route[sz(p)] = std::move(route_p), part.length[sz(p)] = lp;
    part.route[sz(q)] = std::move(route_q), part.length[sz(q)] = lq;
    return true;
  }
  return false;
}

}  // namespace

std::vector<std::vector<int>> partitionRoutes(const FleetContext& ctx, const FleetConfig& cfg,
                                              std::uint64_t seed, const std::vector<int>& circuit,
                                              StrategyStats& stats) {
  const Layout layout = layoutOf(ctx);
  StrategyStats legs;
  std::vector<std::pair<const char*, Partition>> starts;
  if (auto parts = kMeansParts(ctx, cfg, seed, layout); usable(parts, ctx.vehicles()))
    starts.emplace_back("kmeans", routesOf(ctx, std::move(parts)));
  if (auto parts = circuitLegParts(ctx, circuit); usable(parts, ctx.vehicles())) {
    // The legs themselves are routes for these parts: moves re-plan only the parts they change.
    Partition p{std::move(parts), splitCircuitRoutes(ctx, circuit, legs), {}};
    for (const auto& r : p.route) p.length.push_back(routeLength(ctx.pg, r));
    starts.emplace_back("circuit legs", std::move(p));
  }
  std::vector<std::vector<int>> best;
  double best_makespan = std::numeric_limits<double>::infinity();
  for (auto& [name, part] : starts) {
    const double before = *std::max_element(part.length.begin(), part.length.end());
    int moves = 0;
    while (moves < cfg.balance_moves && improveOnce(ctx, cfg, layout, part)) ++moves;
    const double makespan = *std::max_element(part.length.begin(), part.length.end());
    if (makespan >= best_makespan) continue;
    best_makespan = makespan;
    best = std::move(part.route);
    stats.start = name, stats.makespan_before_moves_m = before, stats.balance_moves = moves;
  }
  return best;
}

}  // namespace slamroute::rl::fleet
