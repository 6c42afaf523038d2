// The `postman` fleet strategy (tour splitting, after Frederickson, Hecht & Kim 1978): the
// single-vehicle postman circuit is cut into at most K consecutive legs; a leg costs the legal
// trip from the depot to its first edge, the leg, and the legal trip back. The smallest
// makespan for which a greedy cut needs at most K legs is found by bisection, for several starts
// of the closed circuit.
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "FleetParts.hpp"
#include "RuralPostman.hpp"

namespace slamroute::rl::fleet {
namespace {

std::size_t sz(int i) { return static_cast<std::size_t>(i); }

struct Leg {
  int first = 0, last = 0;  ///< circuit positions, inclusive
};

/// Leg costs along one circuit, for the cheapest depot of each leg.
struct LegCosts {
  std::vector<double> prefix;   ///< prefix[i] = length of circuit[0..i)
  std::vector<double> in, out;  ///< per position: min over depots (approach / return)
  double cost(int a, int b) const {
    return in[sz(a)] + prefix[sz(b + 1)] - prefix[sz(a + 1)] + out[sz(b)];
  }
};

LegCosts legCosts(const FleetContext& ctx, const std::vector<int>& circuit) {
  const double inf = std::numeric_limits<double>::infinity();
  LegCosts c{
      {0.0}, std::vector<double>(circuit.size(), inf), std::vector<double>(circuit.size(), inf)};
  for (std::size_t i = 0; i < circuit.size(); ++i) {
    const int e = circuit[i];
    c.prefix.push_back(c.prefix.back() + ctx.pg.len[sz(e)]);
    for (int v = 0; v < ctx.vehicles(); ++v) {
      c.in[i] = std::min(c.in[i], ctx.from_depot[sz(v)][sz(e)]);
      c.out[i] = std::min(c.out[i], ctx.to_depot[sz(v)][sz(e)]);
    }
  }
  return c;
}

/// Greedy cut with every leg costing at most `limit`: each leg ends at its last position
/// within the limit before the leg's own length alone exceeds it. Empty when impossible.
std::vector<Leg> greedyLegs(const LegCosts& c, double limit) {
  const int n = static_cast<int>(c.in.size());
  std::vector<Leg> legs;
  for (int a = 0; a < n;) {
    int end = -1;
    for (int b = a; b < n && c.prefix[sz(b + 1)] - c.prefix[sz(a + 1)] <= limit; ++b)
      if (c.cost(a, b) <= limit) end = b;
    if (end < 0) return {};
    legs.push_back({a, end});
    a = end + 1;
  }
  return legs;
}

std::vector<Leg> cheapestLegs(const LegCosts& c, int k) {
  double lo = 0.0, hi = c.cost(0, static_cast<int>(c.in.size()) - 1);
  std::vector<Leg> best = greedyLegs(c, hi);
  for (int it = 0; it < 60 && hi - lo > 1e-3; ++it) {
    const double mid = 0.5 * (lo + hi);
    std::vector<Leg> legs = greedyLegs(c, mid);
    if (!legs.empty() && static_cast<int>(legs.size()) <= k)
      best = std::move(legs), hi = mid;
    else
      lo = mid;
  }
  while (static_cast<int>(best.size()) < k) {  // idle vehicles take half of the longest leg
    auto longest = std::max_element(best.begin(), best.end(), [&](const Leg& x, const Leg& y) {
      return c.cost(x.first, x.last) < c.cost(y.first, y.last);
    });
    if (longest->first == longest->last) break;
    const Leg whole = *longest;
    const int mid = (whole.first + whole.last) / 2;
    *longest = {whole.first, mid};
    best.insert(longest + 1, Leg{mid + 1, whole.last});
  }
  return best;
}

std::vector<int> legRoute(const FleetContext& ctx, const std::vector<int>& circuit, Leg leg,
                          int vehicle) {
  const int depot = ctx.depot[sz(vehicle)], first = circuit[sz(leg.first)];
  const auto to = ctx.paths.toNearest(-1, depot, [first](int e) { return e == first; });
  const int last = circuit[sz(leg.last)];
  if (!to) throw std::runtime_error("fleet: a leg cannot be reached from its depot");
  std::vector<int> route = to->edges;
  route.insert(route.end(), circuit.begin() + leg.first + 1, circuit.begin() + leg.last + 1);
  if (ctx.pg.v[sz(last)] != depot) {
    const auto back =
        ctx.paths.toNearest(last, -1, [&](int e) { return ctx.pg.v[sz(e)] == depot; });
    if (!back) throw std::runtime_error("fleet: a leg cannot return to its depot");
    route.insert(route.end(), back->edges.begin(), back->edges.end());
  }
  return route;
}

/// The circuit as cut (rotated to its best start), its legs and, per vehicle, the index of its
/// leg (-1: none).
struct AssignedLegs {
  std::vector<int> circuit;
  std::vector<Leg> legs;
  std::vector<int> leg_of_vehicle;
};

double longestLeg(const LegCosts& c, const std::vector<Leg>& legs) {
  double longest = 0.0;
  for (const Leg& leg : legs) longest = std::max(longest, c.cost(leg.first, leg.last));
  return longest;
}

/// The circuit is closed, so its legs may start anywhere: the cut of kRotations evenly spaced
/// starts with the shortest longest leg (the first of equals: deterministic).
std::vector<int> bestRotation(const FleetContext& ctx, const std::vector<int>& circuit) {
  constexpr std::size_t kRotations = 32;
  const std::size_t n = circuit.size(), tries = std::min(n, kRotations);
  std::vector<int> best = circuit;
  double best_longest = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < tries; ++t) {
    std::vector<int> rotated = circuit;
    std::rotate(rotated.begin(), rotated.begin() + static_cast<long>(t * n / tries), rotated.end());
    const LegCosts costs = legCosts(ctx, rotated);
    const double longest = longestLeg(costs, cheapestLegs(costs, ctx.vehicles()));
    if (longest < best_longest - 1e-6) best_longest = longest, best = std::move(rotated);
  }
  return best;
}

AssignedLegs assignLegs(const FleetContext& ctx, const std::vector<int>& circuit) {
  AssignedLegs a{bestRotation(ctx, circuit), {}, {}};
  const LegCosts costs = legCosts(ctx, a.circuit);
  a.legs = cheapestLegs(costs, ctx.vehicles());
  std::vector<std::vector<double>> cost(sz(ctx.vehicles()));
  for (int v = 0; v < ctx.vehicles(); ++v)
    for (const Leg& leg : a.legs)
      cost[sz(v)].push_back(ctx.from_depot[sz(v)][sz(a.circuit[sz(leg.first)])] +
                            costs.prefix[sz(leg.last + 1)] - costs.prefix[sz(leg.first + 1)] +
                            ctx.to_depot[sz(v)][sz(a.circuit[sz(leg.last)])]);
  a.leg_of_vehicle = assignToVehicles(cost);
  return a;
}

}  // namespace

std::vector<std::vector<int>> splitCircuitRoutes(const FleetContext& ctx,
                                                 const std::vector<int>& circuit,
                                                 StrategyStats& stats) {
  const AssignedLegs a = assignLegs(ctx, circuit);
  stats.legs = static_cast<int>(a.legs.size());
  std::vector<std::vector<int>> routes(sz(ctx.vehicles()));
  for (int v = 0; v < ctx.vehicles(); ++v)
    if (a.leg_of_vehicle[sz(v)] >= 0)
      routes[sz(v)] = legRoute(ctx, a.circuit, a.legs[sz(a.leg_of_vehicle[sz(v)])], v);
  return routes;
}

std::vector<int> circuitLegParts(const FleetContext& ctx, const std::vector<int>& circuit) {
  const AssignedLegs a = assignLegs(ctx, circuit);
  std::vector<int> vehicle_of_leg(a.legs.size(), -1);
  for (int v = 0; v < ctx.vehicles(); ++v)
    if (a.leg_of_vehicle[sz(v)] >= 0) vehicle_of_leg[sz(a.leg_of_vehicle[sz(v)])] = v;
  std::vector<int> part_of_edge(sz(ctx.pg.m), -1);
  for (std::size_t l = 0; l < a.legs.size(); ++l)
    for (int i = a.legs[l].first; i <= a.legs[l].last; ++i) {
      int& part = part_of_edge[sz(a.circuit[sz(i)])];
      if (part < 0) part = vehicle_of_leg[l];
    }
  return part_of_edge;
}

}  // namespace slamroute::rl::fleet
