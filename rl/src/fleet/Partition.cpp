// The `partition` fleet strategy (seed paper: K-means segments, Hungarian assignment of
// segments to groups), on streets: parts by K-means on street midpoints, parts to vehicles by
// the Hungarian algorithm, a rural postman route per part, then moves of boundary streets from
// the longest route to a neighbouring part while each move shortens the longest route.
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
  std::vector<int> part_of_street;      ///< per street: the vehicle driving it
  std::vector<std::vector<int>> route;  ///< per vehicle
  std::vector<double> length;           ///< per vehicle [m]
};

/// Which streets meet at which node, and the midpoint of every street.
struct StreetLayout {
  std::vector<Point2> midpoint;
  std::vector<std::vector<int>> nodes_of_street, streets_at_node;
};

StreetLayout streetLayout(const FleetContext& ctx) {
  const PlanGraph& pg = ctx.pg;
  StreetLayout s{std::vector<Point2>(sz(pg.num_streets), Point2::Zero()),
                 std::vector<std::vector<int>>(sz(pg.num_streets)),
                 std::vector<std::vector<int>>(sz(pg.n))};
  std::vector<int> count(sz(pg.num_streets), 0);
  for (int e = 0; e < pg.m; ++e) {
    const int st = pg.street[sz(e)];
    for (int node : {pg.u[sz(e)], pg.v[sz(e)]}) {
      s.midpoint[sz(st)] += 0.5 * ctx.g.nodes[sz(pg.node_orig[sz(node)])].pos.head<2>();
      s.nodes_of_street[sz(st)].push_back(node);
      s.streets_at_node[sz(node)].push_back(st);
    }
    ++count[sz(st)];
  }
  for (int st = 0; st < pg.num_streets; ++st) s.midpoint[sz(st)] /= count[sz(st)];
  return s;
}

std::vector<int> solvePart(const FleetContext& ctx, const std::vector<int>& part_of_street,
                           int vehicle) {
  std::vector<char> required(sz(ctx.pg.m));
  for (int e = 0; e < ctx.pg.m; ++e)
    required[sz(e)] = part_of_street[sz(ctx.pg.street[sz(e)])] == vehicle;
  return ruralPostmanRoute(ctx.pg, ctx.paths, required, ctx.depot[sz(vehicle)]);
}

/// Row vehicle, column cluster: from the depot to the cluster's nearest edge and back.
std::vector<std::vector<double>> approachCosts(const FleetContext& ctx,
                                               const std::vector<int>& cluster_of_street) {
  const double inf = std::numeric_limits<double>::infinity();
  const int k = ctx.vehicles();
  std::vector<std::vector<double>> cost(sz(k), std::vector<double>(sz(k)));
  for (int i = 0; i < k; ++i) {
    std::vector<double> in(sz(k), inf), out(sz(k), inf);
    for (int e = 0; e < ctx.pg.m; ++e) {
      const int c = cluster_of_street[sz(ctx.pg.street[sz(e)])];
      in[sz(c)] = std::min(in[sz(c)], ctx.from_depot[sz(i)][sz(e)]);
      out[sz(c)] = std::min(out[sz(c)], ctx.to_depot[sz(i)][sz(e)]);
    }
    for (int c = 0; c < k; ++c) cost[sz(i)][sz(c)] = in[sz(c)] + out[sz(c)];
  }
  return cost;
}

Partition initialPartition(const FleetContext& ctx, const FleetConfig& cfg, std::uint64_t seed,
                           const StreetLayout& layout) {
  std::vector<double> weight(ctx.pg.street_len.begin(), ctx.pg.street_len.end());
  for (double& w : weight) w = std::max(w, 1e-3);
  const KMeansResult km = kMeans(layout.midpoint, ctx.vehicles(),
                                 {.seed = seed, .maxIterations = cfg.kmeans_iterations,
                                  .weight = weight});
  const std::vector<int> cluster_of_vehicle = assignToVehicles(approachCosts(ctx, km.label));
  std::vector<int> vehicle_of_cluster(sz(ctx.vehicles()));
  for (int i = 0; i < ctx.vehicles(); ++i) vehicle_of_cluster[sz(cluster_of_vehicle[sz(i)])] = i;
  Partition p;
  for (int c : km.label) p.part_of_street.push_back(vehicle_of_cluster[sz(c)]);
  for (int i = 0; i < ctx.vehicles(); ++i) {
    p.route.push_back(solvePart(ctx, p.part_of_street, i));
    p.length.push_back(routeLength(ctx.pg, p.route.back()));
  }
  return p;
}

/// (street of part p, neighbouring part) pairs, the streets nearest the other part's centre
/// relative to their own first.
std::vector<std::pair<int, int>> boundaryMoves(const StreetLayout& layout, const PlanGraph& pg,
                                               const Partition& part, int p) {
  const std::size_t k = part.route.size();
  std::vector<Point2> centre(k, Point2::Zero());
  std::vector<double> mass(k, 0.0);
  for (int st = 0; st < pg.num_streets; ++st) {
    const int q = part.part_of_street[sz(st)];
    centre[sz(q)] += pg.street_len[sz(st)] * layout.midpoint[sz(st)];
    mass[sz(q)] += pg.street_len[sz(st)];
  }
  for (std::size_t q = 0; q < k; ++q) centre[q] /= std::max(mass[q], 1e-9);
  std::set<std::pair<int, int>> seen;
  std::vector<std::pair<double, std::pair<int, int>>> scored;
  for (int st = 0; st < pg.num_streets; ++st) {
    if (part.part_of_street[sz(st)] != p) continue;
    for (int node : layout.nodes_of_street[sz(st)])
      for (int other : layout.streets_at_node[sz(node)]) {
        const int q = part.part_of_street[sz(other)];
        if (q == p || !seen.insert({st, q}).second) continue;
        const Point2& mid = layout.midpoint[sz(st)];
        scored.push_back({(mid - centre[sz(q)]).norm() - (mid - centre[sz(p)]).norm(), {st, q}});
      }
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<int, int>> moves;
  for (const auto& s : scored) moves.push_back(s.second);
  return moves;
}

/// One improving move of a boundary street off the longest route; false when none is found.
bool improveOnce(const FleetContext& ctx, const FleetConfig& cfg, const StreetLayout& layout,
                 Partition& part) {
  const int p = static_cast<int>(std::max_element(part.length.begin(), part.length.end()) -
                                 part.length.begin());
  if (std::count(part.part_of_street.begin(), part.part_of_street.end(), p) <= 1) return false;
  const auto moves = boundaryMoves(layout, ctx.pg, part, p);
  for (std::size_t i = 0; i < moves.size() && static_cast<int>(i) < cfg.candidates_per_move; ++i) {
    const auto [st, q] = moves[i];
    std::vector<int> trial = part.part_of_street;
    trial[sz(st)] = q;
    std::vector<int> route_p = solvePart(ctx, trial, p), route_q = solvePart(ctx, trial, q);
    const double lp = routeLength(ctx.pg, route_p), lq = routeLength(ctx.pg, route_q);
    if (std::max(lp, lq) >= part.length[sz(p)] - 1e-6) continue;
    part.part_of_street = std::move(trial);
    part.route[sz(p)] = std::move(route_p), part.length[sz(p)] = lp;
    part.route[sz(q)] = std::move(route_q), part.length[sz(q)] = lq;
    return true;
  }
  return false;
}

}  // namespace

std::vector<std::vector<int>> partitionRoutes(const FleetContext& ctx, const FleetConfig& cfg,
                                              std::uint64_t seed, StrategyStats& stats) {
  const StreetLayout layout = streetLayout(ctx);
  Partition part = initialPartition(ctx, cfg, seed, layout);
  stats.makespan_before_moves_m = *std::max_element(part.length.begin(), part.length.end());
  while (stats.balance_moves < cfg.balance_moves && improveOnce(ctx, cfg, layout, part))
    ++stats.balance_moves;
  return part.route;
}

}  // namespace slamroute::rl::fleet
