// The `partition` fleet strategy (seed paper: K-means segments, Hungarian assignment of
// segments to groups), on streets: parts by K-means on street midpoints, parts to vehicles by
// the Hungarian algorithm, a rural postman route per part, then moves of boundary streets from
// the longest route to another part while each move shortens the longest route: first streets
// the other part's route drives anyway (on its way from the depot, the far parts' routes cross
// the near parts), then streets on the boundary to a neighbouring part. When no single street
// helps, merge-splits (MergeSplit.cpp) re-cut two neighbouring parts at once, kept when the sum
// of the two routes' squared lengths falls without either passing the makespan: that shortens
// the total and lets length flow from long routes to short ones through a chain of neighbours,
// which single-street moves off the longest route cannot. Three more starts are balanced the
// same way and the shortest makespan is kept: sectors of the streets around the depot (the
// sweep of vehicle routing; K-means parts ignore how far the depot is, a sector holds near and
// far streets alike), swept both ways round (the sectors' cuts fall elsewhere), and the postman
// circuit's legs (routes and the edges each drives first), so partition is never longer than
// the postman strategy.
// Parts hold directed edges: a street starts with both directions in one part, a move takes
// the directions of the street that the longest route's part holds.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
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
  std::int64_t work = 0;  ///< the re-plans' work so far (replanWork), the kicks' budget
  int merge_solves = 0;   ///< circulations the merge-splits of this descent solved
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
                           int vehicle, int* solves = nullptr) {
  std::vector<char> required(sz(ctx.pg.m));
  for (int e = 0; e < ctx.pg.m; ++e) required[sz(e)] = part_of_edge[sz(e)] == vehicle;
  return ruralPostmanRoute(ctx.pg, ctx.paths, required, ctx.depot[sz(vehicle)], solves);
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

/// Clusters (per edge) given to vehicles by the Hungarian algorithm on the approach costs.
std::vector<int> clustersToVehicles(const FleetContext& ctx, std::vector<int> cluster_of_edge) {
  const std::vector<int> cluster_of_vehicle = assignToVehicles(approachCosts(ctx, cluster_of_edge));
  std::vector<int> vehicle_of_cluster(sz(ctx.vehicles()));
  for (int i = 0; i < ctx.vehicles(); ++i) vehicle_of_cluster[sz(cluster_of_vehicle[sz(i)])] = i;
  for (int& c : cluster_of_edge) c = vehicle_of_cluster[sz(c)];
  return cluster_of_edge;
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
  return clustersToVehicles(ctx, std::move(cluster_of_edge));
}

/// Per edge: its street's sector around the first depot (the sweep of vehicle routing): streets
/// sorted by their bearing from the depot, starting after the widest empty wedge, cut into K
/// runs of equal street length. Each sector reaches from the depot to the city's edge, so every
/// vehicle has near and far streets and the trips out and back weigh alike on all.
std::vector<int> sweepParts(const FleetContext& ctx, const Layout& layout, bool backwards) {
  const PlanGraph& pg = ctx.pg;
  const Point2 depot = ctx.g.nodes[sz(pg.node_orig[sz(ctx.depot[0])])].pos.head<2>();
  std::vector<std::pair<double, int>> bearing;
  for (int st = 0; st < pg.num_streets; ++st) {
    const Point2 d = layout.street_midpoint[sz(st)] - depot;
    bearing.push_back({std::atan2(d.y(), d.x()), st});
  }
  std::sort(bearing.begin(), bearing.end());
  std::size_t start = 0;
  double widest = -1.0;
  for (std::size_t i = 0; i < bearing.size(); ++i) {
    const double next = i + 1 < bearing.size() ? bearing[i + 1].first : bearing[0].first + 2 * M_PI;
    if (next - bearing[i].first > widest) widest = next - bearing[i].first, start = i + 1;
  }
  std::rotate(bearing.begin(), bearing.begin() + static_cast<long>(start % bearing.size()),
              bearing.end());
  if (backwards) std::reverse(bearing.begin(), bearing.end());
  std::vector<int> sector_of_street(sz(pg.num_streets));
  double done = 0.0;
  for (const auto& [angle, st] : bearing) {
    const int sector = static_cast<int>(done / pg.total_street_len * ctx.vehicles());
    sector_of_street[sz(st)] = std::min(sector, ctx.vehicles() - 1);
    done += pg.street_len[sz(st)];
  }
  std::vector<int> cluster_of_edge;
  for (int e = 0; e < pg.m; ++e) cluster_of_edge.push_back(sector_of_street[sz(pg.street[sz(e)])]);
  return clustersToVehicles(ctx, std::move(cluster_of_edge));
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

/// (edge of part p, other part q) pairs where q's route drives the edge already, on its way to
/// its own streets: q takes it over at little or no extra length. Shortest q routes first.
std::vector<std::pair<int, int>> drivenByOthers(const PlanGraph& pg, const Partition& part, int p) {
  std::vector<int> order;
  for (int q = 0; q < static_cast<int>(part.route.size()); ++q)
    if (q != p) order.push_back(q);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return part.length[sz(a)] < part.length[sz(b)]; });
  std::vector<std::pair<int, int>> moves;
  std::vector<char> taken(sz(pg.m), 0);
  for (int q : order)
    for (int e : part.route[sz(q)])
      if (part.part_of_edge[sz(e)] == p && !taken[sz(e)]) {
        taken[sz(e)] = 1;
        moves.push_back({e, q});
      }
  return moves;
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

/// Candidate moves off part p: up to candidates_per_move of each kind, streets other routes
/// drive anyway, then boundary streets.
std::vector<std::pair<int, int>> candidateMoves(const FleetConfig& cfg, const Layout& layout,
                                                const PlanGraph& pg, const Partition& part, int p) {
  const auto limit = static_cast<std::size_t>(cfg.candidates_per_move);
  std::vector<std::pair<int, int>> moves = drivenByOthers(pg, part, p);
  if (moves.size() > limit) moves.resize(limit);
  const auto boundary = boundaryMoves(layout, pg, part, p);
  moves.insert(moves.end(), boundary.begin(),
               boundary.begin() + static_cast<long>(std::min(limit, boundary.size())));
  return moves;
}

/// What re-planning part v costs, for the kicks' budget: its directed edges squared (the
/// rural postman's matching grows faster than the part).
std::int64_t replanWork(const std::vector<int>& part_of_edge, int v) {
  const auto n = static_cast<std::int64_t>(std::count(part_of_edge.begin(), part_of_edge.end(), v));
  return n * n;
}

double makespanOf(const Partition& part) {
  return *std::max_element(part.length.begin(), part.length.end());
}

/// Parts p and q of `trial` re-planned; applied when p and q both keep an edge and the longer
/// of their routes is shorter than p's route now.
bool applyIfShorter(const FleetContext& ctx, std::vector<int> trial, int p, int q,
                    Partition& part) {
  if (std::find(trial.begin(), trial.end(), p) == trial.end() ||
      std::find(trial.begin(), trial.end(), q) == trial.end())
    return false;
  std::vector<int> route_p = solvePart(ctx, trial, p), route_q = solvePart(ctx, trial, q);
  part.work += replanWork(trial, p) + replanWork(trial, q);
  const double lp = routeLength(ctx.pg, route_p), lq = routeLength(ctx.pg, route_q);
  if (std::max(lp, lq) >= part.length[sz(p)] - 1e-6) return false;
  part.part_of_edge = std::move(trial);
  part.route[sz(p)] = std::move(route_p), part.length[sz(p)] = lp;
  part.route[sz(q)] = std::move(route_q), part.length[sz(q)] = lq;
  return true;
}

/// One move of a street off the longest route p that shortens it without the receiving route
/// reaching p's old length, applied; false when no candidate does.
bool improveOnce(const FleetContext& ctx, const FleetConfig& cfg, const Layout& layout,
                 Partition& part) {
  const int p = static_cast<int>(std::max_element(part.length.begin(), part.length.end()) -
                                 part.length.begin());
  if (std::count(part.part_of_edge.begin(), part.part_of_edge.end(), p) <= 1) return false;
  for (const auto& [e, q] : candidateMoves(cfg, layout, ctx.pg, part, p))
    if (applyIfShorter(ctx, movedStreet(layout, ctx.pg, part.part_of_edge, e, q), p, q, part))
      return true;
  return false;
}

/// A random street on a part's boundary moved to a neighbouring part (seeded `rng`): a kick
/// out of the local optimum the moves stop in. False when the drawn street has no neighbour
/// part or is its part's last.
bool kick(const FleetContext& ctx, const Layout& layout, Partition& part, std::mt19937_64& rng) {
  const PlanGraph& pg = ctx.pg;
  const int e = static_cast<int>(rng() % static_cast<std::uint64_t>(pg.m));
  const int p = part.part_of_edge[sz(e)];
  std::vector<int> neighbours;
  for (int node : {pg.u[sz(e)], pg.v[sz(e)]})
    for (int other : layout.edges_at_node[sz(node)])
      if (const int q = part.part_of_edge[sz(other)];
          q != p && std::find(neighbours.begin(), neighbours.end(), q) == neighbours.end())
        neighbours.push_back(q);
  if (neighbours.empty()) return false;
  const int q = neighbours[rng() % neighbours.size()];
  std::vector<int> trial = movedStreet(layout, pg, part.part_of_edge, e, q);
  if (std::find(trial.begin(), trial.end(), p) == trial.end()) return false;
  part.part_of_edge = std::move(trial);
  for (int v : {p, q}) {
    part.work += replanWork(part.part_of_edge, v);
    part.route[sz(v)] = solvePart(ctx, part.part_of_edge, v);
    part.length[sz(v)] = routeLength(pg, part.route[sz(v)]);
  }
  return true;
}

/// Parts p and q of `trial` re-planned; applied when both keep an edge, neither route gets
/// longer than the makespan now and the sum of their squared lengths falls: the total length
/// falls, or the two get more even, so length flows from long routes to short ones.
bool applyIfSquaresFall(const FleetContext& ctx, std::vector<int> trial, int p, int q,
                        Partition& part) {
  if (std::find(trial.begin(), trial.end(), p) == trial.end() ||
      std::find(trial.begin(), trial.end(), q) == trial.end())
    return false;
  std::vector<int> route_p = solvePart(ctx, trial, p, &part.merge_solves),
                   route_q = solvePart(ctx, trial, q, &part.merge_solves);
  part.work += replanWork(trial, p) + replanWork(trial, q);
  const double lp = routeLength(ctx.pg, route_p), lq = routeLength(ctx.pg, route_q);
  const double makespan = makespanOf(part), was_p = part.length[sz(p)], was_q = part.length[sz(q)];
  // 1 m^2: a fall that small is rounding, and a strict fall ends the descent
  if (std::max(lp, lq) > makespan + 1e-6 ||
      lp * lp + lq * lq >= was_p * was_p + was_q * was_q - 1.0)
    return false;
  part.part_of_edge = std::move(trial);
  part.route[sz(p)] = std::move(route_p), part.length[sz(p)] = lp;
  part.route[sz(q)] = std::move(route_q), part.length[sz(q)] = lq;
  return true;
}

/// Per pair of parts: they meet at a junction.
std::vector<std::vector<char>> neighbouringParts(const FleetContext& ctx, const Layout& layout,
                                                 const std::vector<int>& part_of_edge) {
  const auto k = sz(ctx.vehicles());
  std::vector<std::vector<char>> meet(k, std::vector<char>(k, 0));
  for (const auto& edges : layout.edges_at_node)
    for (int a : edges)
      for (int b : edges) meet[sz(part_of_edge[sz(a)])][sz(part_of_edge[sz(b)])] = 1;
  return meet;
}

/// The first merge-split of two neighbouring parts, the longest routes first, that
/// applyIfSquaresFall applies; none once the descent's merge-splits have solved cfg.merge_budget
/// circulations.
bool mergeSplitOnce(const FleetContext& ctx, const FleetConfig& cfg, const Layout& layout,
                    Partition& part) {
  std::vector<int> order(sz(ctx.vehicles()));
  for (int i = 0; i < ctx.vehicles(); ++i) order[sz(i)] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return part.length[sz(a)] > part.length[sz(b)]; });
  const auto meet = neighbouringParts(ctx, layout, part.part_of_edge);
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const int a = order[i], b = order[j];
      if (!meet[sz(a)][sz(b)]) continue;
      if (part.merge_solves >= cfg.merge_budget) return false;
      // the merged tour: at most twice the work of re-planning both parts
      part.work += 2 * (replanWork(part.part_of_edge, a) + replanWork(part.part_of_edge, b));
      if (applyIfSquaresFall(ctx, mergeSplitParts(ctx, part.part_of_edge, a, b, &part.merge_solves),
                             a, b, part))
        return true;
    }
  return false;
}

/// The balancing moves until none helps (at most balance_moves): single streets off the
/// longest route first, merge-splits when none is left; returns how many were made.
int descend(const FleetContext& ctx, const FleetConfig& cfg, const Layout& layout,
            Partition& part) {
  int moves = 0;
  part.merge_solves = 0;
  while (moves < cfg.balance_moves &&
         (improveOnce(ctx, cfg, layout, part) || mergeSplitOnce(ctx, cfg, layout, part)))
    ++moves;
  return moves;
}

/// Iterated local search: kick_rounds times, a few kicks of the best partition so far, the
/// moves again, kept when the makespan is shorter. The rounds stop early once their re-plans'
/// work reaches kick_budget (large nets: each re-plan costs more); a count, not a time, so the
/// same seed gives the same routes on any machine.
void kickAndDescend(const FleetContext& ctx, const FleetConfig& cfg, const Layout& layout,
                    std::uint64_t seed, Partition& best) {
  std::mt19937_64 rng(seed);
  std::int64_t spent = 0;
  for (int round = 0; round < cfg.kick_rounds && spent < cfg.kick_budget; ++round) {
    Partition trial = best;
    trial.work = 0;
    const int kicks = 1 + static_cast<int>(rng() % 3);
    for (int k = 0, tries = 0; k < kicks && tries < 20; ++tries) k += kick(ctx, layout, trial, rng);
    descend(ctx, cfg, layout, trial);
    spent += trial.work;
    if (makespanOf(trial) < makespanOf(best) - 1e-6) best = std::move(trial);
  }
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
  if (auto parts = sweepParts(ctx, layout, false); usable(parts, ctx.vehicles()))
    starts.emplace_back("sweep", routesOf(ctx, std::move(parts)));
  if (auto parts = sweepParts(ctx, layout, true); usable(parts, ctx.vehicles()))
    starts.emplace_back("sweep back", routesOf(ctx, std::move(parts)));
  if (auto parts = circuitLegParts(ctx, circuit); usable(parts, ctx.vehicles())) {
    // The legs themselves are routes for these parts: moves re-plan only the parts they change.
    Partition p{std::move(parts), splitCircuitRoutes(ctx, circuit, legs), {}};
    for (const auto& r : p.route) p.length.push_back(routeLength(ctx.pg, r));
    starts.emplace_back("circuit legs", std::move(p));
  }
  std::vector<std::vector<int>> best;
  double best_makespan = std::numeric_limits<double>::infinity();
  for (auto& [name, part] : starts) {
    const double before = makespanOf(part);
    const int moves = descend(ctx, cfg, layout, part);
    kickAndDescend(ctx, cfg, layout, seed, part);
    const double makespan = makespanOf(part);
    if (makespan >= best_makespan) continue;
    best_makespan = makespan;
    best = std::move(part.route);
    stats.start = name, stats.makespan_before_moves_m = before, stats.balance_moves = moves;
  }
  return best;
}

}  // namespace slamroute::rl::fleet
