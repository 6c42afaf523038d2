#include "slamroute/core/SyntheticCity.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

namespace slamroute {

RoadGraph syntheticCity(const SyntheticCityConfig& cfg, std::uint64_t seed) {
  if (cfg.nodes < 4) throw std::invalid_argument("synthetic city needs at least 4 nodes");
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> jitter(0.0, cfg.jitter_m / 2.0);
  std::uniform_real_distribution<double> weight(0.2, 1.0), unit(0.0, 1.0);
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(cfg.nodes))));
  RoadGraph g;
  for (int i = 0; i < cfg.nodes; ++i) {
    const int r = i / cols, c = i % cols;
    g.nodes.push_back({i, Point3(c * cfg.block_m + jitter(rng), r * cfg.block_m + jitter(rng), 0.0), ""});
  }
  // Candidate streets: right and up neighbours in the grid.
  std::vector<std::pair<int, int>> streets;
  for (int i = 0; i < cfg.nodes; ++i) {
    const int c = i % cols;
    if (c + 1 < cols && i + 1 < cfg.nodes) streets.emplace_back(i, i + 1);
    if (i + cols < cfg.nodes) streets.emplace_back(i, i + cols);
  }
  // Remove a share of streets, but never one that would leave a node with fewer than 2 streets
  // (two-way streets keep the graph strongly connected as long as it stays connected; a grid
  // with every node at degree >= 2 after removal of non-adjacent streets stays connected in
  // practice, and we verify below).
  std::vector<int> degree(static_cast<std::size_t>(cfg.nodes), 0);
  for (auto [a, b] : streets) ++degree[static_cast<std::size_t>(a)], ++degree[static_cast<std::size_t>(b)];
  std::vector<bool> keep(streets.size(), true);
  for (std::size_t s = 0; s < streets.size(); ++s) {
    auto [a, b] = streets[s];
    if (unit(rng) < cfg.removed_street_share && degree[static_cast<std::size_t>(a)] > 2 &&
        degree[static_cast<std::size_t>(b)] > 2) {
      keep[s] = false;
      --degree[static_cast<std::size_t>(a)], --degree[static_cast<std::size_t>(b)];
    }
  }
  // Connectivity check (union-find); put back removed streets joining separate parts.
  std::vector<int> parent(static_cast<std::size_t>(cfg.nodes));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[static_cast<std::size_t>(x)] != x)
      x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
  };
  for (std::size_t s = 0; s < streets.size(); ++s)
    if (keep[s]) parent[static_cast<std::size_t>(find(streets[s].first))] = find(streets[s].second);
  for (std::size_t s = 0; s < streets.size(); ++s)
    if (!keep[s] && find(streets[s].first) != find(streets[s].second)) {
      keep[s] = true;
      parent[static_cast<std::size_t>(find(streets[s].first))] = find(streets[s].second);
    }
  int street = 0;
  for (std::size_t s = 0; s < streets.size(); ++s) {
    if (!keep[s]) continue;
    const auto [a, b] = streets[s];
    const Point3 pa = g.nodes[static_cast<std::size_t>(a)].pos, pb = g.nodes[static_cast<std::size_t>(b)].pos;
    const double w = weight(rng), len = (pb - pa).norm();
    g.edges.push_back({static_cast<int>(g.edges.size()), a, b, len, w, {pa, pb}, {}, street});
    g.edges.push_back({static_cast<int>(g.edges.size()), b, a, len, w, {pb, pa}, {}, street});
    ++street;
  }
  g.metadata_json = "{\"source\":\"synthetic\",\"seed\":" + std::to_string(seed) + "}";
  return g;
}

}  // namespace slamroute
