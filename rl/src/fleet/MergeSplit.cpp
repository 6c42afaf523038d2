// Merge-split of two routes (Ahr & Reinelt's tabu search for the min-max k-Chinese postman
// uses it): the streets of two parts are driven as one rural postman tour from the first part's
// depot, and that tour is cut into two legs as the `postman` strategy cuts the single circuit
// (cheapest longest leg with the trips from and back to a depot, over several starts). Unlike
// moving streets one by one, it moves whole runs of streets at once, so it escapes the balance
// where any single street moved lengthens the receiving route as much as it shortens the other.
#include <stdexcept>

#include "FleetParts.hpp"
#include "RuralPostman.hpp"

namespace slamroute::rl::fleet {
namespace {
std::size_t sz(int i) { return static_cast<std::size_t>(i); }
}  // namespace

std::vector<int> splitTourParts(const FleetContext& ctx, const std::vector<int>& part_of_edge,
                                int p, int q, const std::vector<int>& tour) {
  const PlanGraph& pg = ctx.pg;
  // The two vehicles alone, with their depots and distances: leg 0 is p's, leg 1 q's.
  const FleetContext pair{ctx.g,
                          pg,
                          ctx.paths,
                          {ctx.depot[sz(p)], ctx.depot[sz(q)]},
                          {ctx.from_depot[sz(p)], ctx.from_depot[sz(q)]},
                          {ctx.to_depot[sz(p)], ctx.to_depot[sz(q)]}};
  const std::vector<int> leg_of_edge = circuitLegParts(pair, tour);
  std::vector<int> out = part_of_edge;
  for (int e = 0; e < pg.m; ++e) {
    if (out[sz(e)] != p && out[sz(e)] != q) continue;
    if (leg_of_edge[sz(e)] < 0) throw std::logic_error("merge-split: the tour missed a street");
    out[sz(e)] = leg_of_edge[sz(e)] == 0 ? p : q;
  }
  return out;
}

std::vector<int> mergeSplitParts(const FleetContext& ctx, const std::vector<int>& part_of_edge,
                                 int p, int q, int* solves) {
  std::vector<char> merged(sz(ctx.pg.m), 0);
  for (int e = 0; e < ctx.pg.m; ++e)
    merged[sz(e)] = part_of_edge[sz(e)] == p || part_of_edge[sz(e)] == q;
  return splitTourParts(ctx, part_of_edge, p, q,
                        ruralPostmanRoute(ctx.pg, ctx.paths, merged, ctx.depot[sz(p)], solves));
}

}  // namespace slamroute::rl::fleet
