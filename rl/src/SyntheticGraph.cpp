// Synthetic grid cities (tests, benchmarks).
#include "slamroute/rl/SyntheticGraph.hpp"

#include <random>
#include <stdexcept>

namespace slamroute::rl {

RoadGraph gridCity(const GridCitySpec& s) {
  if (s.rows < 1 || s.cols < 1 || s.rows * s.cols < 2)
    throw std::invalid_argument("gridCity: need at least 2 junctions");
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  RoadGraph g;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      RoadNode n;
      n.id = static_cast<int>(g.nodes.size());
      n.pos = Point3(c * s.spacing_m + s.jitter_m * (2 * uni(rng) - 1),
                     r * s.spacing_m + s.jitter_m * (2 * uni(rng) - 1), 0.0);
      g.nodes.push_back(n);
    }
  int street = 0;
  auto addEdge = [&](int a, int b, int st) {
    RoadEdge e;
    e.id = static_cast<int>(g.edges.size());
    e.u = a;
    e.v = b;
    e.polyline = {g.nodes[static_cast<std::size_t>(a)].pos,
                  g.nodes[static_cast<std::size_t>(b)].pos};
    e.length_m = (e.polyline[1] - e.polyline[0]).norm();
    e.weight = s.weight_min + (1.0 - s.weight_min) * uni(rng);
    e.street = st;
    g.edges.push_back(std::move(e));
  };
  auto addStreet = [&](int a, int b) {
    const double x = uni(rng);
    if (x < s.one_way_fraction) {
      if (uni(rng) < 0.5)
        addEdge(a, b, street);
      else
        addEdge(b, a, street);
    } else {
      addEdge(a, b, street);
      addEdge(b, a, street);
    }
    ++street;
  };
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const int id = r * s.cols + c;
      if (c + 1 < s.cols) addStreet(id, id + 1);
      if (r + 1 < s.rows) addStreet(id, id + s.cols);
    }
  if (s.forbid_u_turns) {
    g.restricted_turns = true;
    const auto out = g.outEdges();
    g.allowed_next.assign(g.edges.size(), {});
    for (const auto& e : g.edges) {
      auto& nx = g.allowed_next[static_cast<std::size_t>(e.id)];
      for (int f : out[static_cast<std::size_t>(e.v)])
        if (g.edges[static_cast<std::size_t>(f)].v != e.u) nx.push_back(f);
      if (nx.empty())  // dead end: the U-turn is allowed
        for (int f : out[static_cast<std::size_t>(e.v)]) nx.push_back(f);
    }
  }
  return g;
}

}  // namespace slamroute::rl
