#pragma once
// The street step alone (clearing, clusters, attachment: roadgraph/src/StreetClusters.cpp) on
// hand-made traces with the intersection nodes given, so a test's known answer does not depend on
// where the hollow cylinder votes.
#include <numeric>
#include <vector>

#include "Streets.hpp"
#include "SyntheticTraces.hpp"

namespace slamroute::roadgraph::testing {

struct BuiltStreets {
  detail::GraphNodes nodes;
  std::vector<detail::Street> streets;
};

/// Streets of the traces of `roads` (two passes each way, no noise) with the intersection
/// nodes `nodes`.
inline BuiltStreets streetsOf(const std::vector<Road>& roads, const std::vector<Point3>& nodes,
                              const EdgeConfig& ec = {}) {
  const Traces tr = makeTraces(roads, 0.0, 7, 1.0, /*passes=*/2);
  const double half_h = 5.0;
  BuiltStreets b;
  b.nodes.pos = nodes;
  b.nodes.is_end.assign(b.nodes.pos.size(), 0);
  b.nodes.n_inter = b.nodes.pos.size();
  std::vector<Point3> voxels;
  for (const auto& p : tr.points) voxels.push_back(p.pos);
  std::vector<int> voxel_of(voxels.size());
  std::iota(voxel_of.begin(), voxel_of.end(), 0);
  const detail::StreetPoints spts =
      detail::clearNodeNeighbourhoods(voxels, b.nodes.pos, ec, half_h);
  GraphBuildStats st;
  b.streets =
      detail::attachStreets(spts, tr, byVehicleThenTime(tr), voxel_of, b.nodes, ec, half_h, st);
  return b;
}

/// The street from node u to node v (either way), or nullptr.
inline const detail::Street* streetBetween(const BuiltStreets& b, int u, int v) {
  for (const auto& s : b.streets)
    if ((s.u == u && s.v == v) || (s.u == v && s.v == u)) return &s;
  return nullptr;
}

}  // namespace slamroute::roadgraph::testing
