// `tsp`: Held-Karp equals brute force; heuristic above the limit; refusal above max_nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "RlTestUtil.hpp"

namespace slamroute::rl {
namespace {

double bruteForce(const std::vector<std::vector<double>>& d, int start, bool closed) {
  std::vector<int> rest;
  for (int i = 0; i < static_cast<int>(d.size()); ++i)
    if (i != start) rest.push_back(i);
  double best = 1e300;
  do {
    double c = 0.0;
    int cur = start;
    for (int x : rest) c += d[cur][x], cur = x;
    if (closed) c += d[cur][start];
    best = std::min(best, c);
  } while (std::next_permutation(rest.begin(), rest.end()));
  return best;
}

TEST(HeldKarp, EqualsBruteForceOnRandomAsymmetricInstances) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    const int n = 2 + static_cast<int>(seed % 7);  // 2..8 nodes
    std::uniform_real_distribution<double> u(1.0, 100.0);
    std::vector<std::vector<double>> d(n, std::vector<double>(n, 0.0));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j) d[i][j] = u(rng);
    const int start = static_cast<int>(rng() % static_cast<std::uint64_t>(n));
    for (bool closed : {true, false}) {
      double cost = 0.0;
      const std::vector<int> order = heldKarp(d, start, closed, &cost);
      ASSERT_EQ(static_cast<int>(order.size()), n) << "seed " << seed;
      EXPECT_EQ(order.front(), start) << "seed " << seed;
      std::vector<int> sorted = order;
      std::sort(sorted.begin(), sorted.end());
      for (int i = 0; i < n; ++i) EXPECT_EQ(sorted[i], i) << "seed " << seed;
      double recomputed = 0.0;
      for (int k = 1; k < n; ++k) recomputed += d[order[k - 1]][order[k]];
      if (closed) recomputed += d[order.back()][start];
      EXPECT_NEAR(cost, recomputed, 1e-9) << "seed " << seed;
      EXPECT_NEAR(cost, bruteForce(d, start, closed), 1e-9)
          << "seed " << seed << " closed " << closed;
    }
  }
}

TEST(Tsp, ExactOnSmallGridVisitsAllNodes) {
  Config c;
  c.planner = "tsp";
  const Route r = plan(test::grid(3, 3), c, 1);
  EXPECT_FALSE(r.heuristic);
  EXPECT_DOUBLE_EQ(r.node_coverage_pct, 100.0);
  // A closed tour over 9 grid nodes (100 m apart) needs at least 9 legs of 100 m... the 3x3 grid
  // is bipartite with odd node count, so an optimal closed tour has length 1000 m.
  EXPECT_NEAR(r.length_m, 1000.0, 1e-6);
  EXPECT_EQ(test::extra(r)["method"], "held-karp");
}

TEST(Tsp, HeuristicAboveExactLimitIsLabelled) {
  Config c;
  c.planner = "tsp";
  c.tsp.exact_max_nodes = 10;
  const Route r = plan(test::grid(4, 5), c, 1);
  EXPECT_TRUE(r.heuristic);
  EXPECT_DOUBLE_EQ(r.node_coverage_pct, 100.0);
  EXPECT_EQ(test::extra(r)["illegal_turns"].get<int>(), 0);
  EXPECT_NE(r.notes.find("heuristic"), std::string::npos);
}

TEST(Tsp, RouteLengthIsTheReportedTourLength) {
  // No U-turns and one-way streets: a leg that starts on the edge the tour arrived by can be far
  // longer than the node-to-node distance (measured from a standing start). The reported tour
  // length is what the route drives.
  GridCitySpec s;
  s.rows = 5;
  s.cols = 6;
  s.jitter_m = 15.0;
  s.one_way_fraction = 0.3;
  s.forbid_u_turns = true;
  s.seed = 4;
  for (int exact : {22, 10}) {
    Config c;
    c.planner = "tsp";
    c.tsp.exact_max_nodes = exact;
    const Route r = plan(gridCity(s), c, 1);
    EXPECT_NEAR(r.length_m, test::extra(r)["tour_cost_m"].get<double>(), 1e-6);
    EXPECT_DOUBLE_EQ(r.node_coverage_pct, 100.0);
    EXPECT_EQ(test::extra(r)["illegal_turns"].get<int>(), 0);
  }
}

TEST(Tsp, RouteLengthIsTheTourLengthOnBologna) {
  const auto net = test::bolognaNet();
  Config c;
  c.planner = "tsp";
  const Route r = plan(test::netGraph(net), c, 1, net.string());
  EXPECT_NEAR(r.length_m, test::extra(r)["tour_cost_m"].get<double>(), 1e-3);
  EXPECT_DOUBLE_EQ(r.node_coverage_pct, 100.0);
}

TEST(Tsp, RefusesAboveMaxNodes) {
  Config c;
  c.planner = "tsp";
  c.tsp.max_nodes = 10;
  try {
    plan(test::grid(4, 4), c, 1);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_nodes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamroute::rl
