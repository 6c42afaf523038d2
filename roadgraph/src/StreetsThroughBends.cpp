// Streets joined through turning places, for the validation (StreetsThroughBends.hpp): a street
// of the graph that a turning place splits is still one street between two intersections, as
// the net's chain through that bend is.
#include "StreetsThroughBends.hpp"

#include <map>

#include "slamroute/roadgraph/GraphBuilder.hpp"

namespace slamroute::roadgraph::detail {
namespace {

struct StreetEnds {
  int u = -1, v = -1;
  double length_m = 0.0;
};

/// One entry per street (edges sharing `street`, or an edge without one), with its end nodes.
std::vector<StreetEnds> undirectedStreets(const RoadGraph& graph) {
  std::vector<StreetEnds> out;
  std::map<int, std::size_t> index;
  for (const auto& e : graph.edges) {
    if (e.street >= 0 && !index.emplace(e.street, out.size()).second) continue;
    out.push_back({e.u, e.v, e.length_m});
  }
  return out;
}

}  // namespace

RoadGraph streetsThroughBends(const RoadGraph& graph, const std::vector<char>& node_kind) {
  const std::vector<StreetEnds> streets = undirectedStreets(graph);
  std::vector<std::vector<std::size_t>> at(graph.nodes.size());
  for (std::size_t k = 0; k < streets.size(); ++k) {
    at[static_cast<std::size_t>(streets[k].u)].push_back(k);
    at[static_cast<std::size_t>(streets[k].v)].push_back(k);
  }
  auto passes = [&](int n) {
    const auto i = static_cast<std::size_t>(n);
    return i < node_kind.size() && node_kind[i] == kTurningPlace && at[i].size() == 2 &&
           at[i][0] != at[i][1];
  };
  std::vector<char> done(streets.size(), 0);
  // From street k's end `x` on through the bends: the node where the joined street ends.
  auto walk = [&](std::size_t k, int x, double& length_m) {
    while (passes(x)) {
      const auto& two = at[static_cast<std::size_t>(x)];
      const std::size_t next = two[0] == k ? two[1] : two[0];
      if (done[next]) break;  // a ring of bends
      done[next] = 1;
      length_m += streets[next].length_m;
      x = streets[next].u == x ? streets[next].v : streets[next].u;
      k = next;
    }
    return x;
  };
  RoadGraph view;
  view.nodes = graph.nodes;
  for (std::size_t k = 0; k < streets.size(); ++k) {
    if (done[k]) continue;
    done[k] = 1;
    RoadEdge e;
    e.id = e.street = static_cast<int>(view.edges.size());
    e.length_m = streets[k].length_m;
    e.u = walk(k, streets[k].u, e.length_m);
    e.v = walk(k, streets[k].v, e.length_m);
    view.edges.push_back(e);
  }
  return view;
}

}  // namespace slamroute::roadgraph::detail
