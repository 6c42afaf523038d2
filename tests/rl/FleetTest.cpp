// Fleet planning: a grid whose optimal two-vehicle split is known, coverage and legality of
// every vehicle's route, the lower bounds (the default city's K = 2 split is provably optimal),
// depots, same seed same routes.
#include <gtest/gtest.h>

#include <set>

#include "RlTestUtil.hpp"
#include "slamroute/rl/Fleet.hpp"

namespace slamroute::rl {
namespace {

Config fleetConfig(int vehicles, const std::string& strategy) {
  Config cfg;
  cfg.fleet.vehicles = vehicles;
  cfg.fleet.strategy = strategy;
  return cfg;
}

/// Every directed edge of g driven by some vehicle; each route leaves its depot and returns.
void expectCoveringClosedRoutes(const RoadGraph& g, const FleetRoute& f) {
  std::set<int> driven;
  for (std::size_t v = 0; v < f.vehicles.size(); ++v) {
    const Route& r = f.vehicles[v];
    ASSERT_FALSE(r.edges.empty());
    EXPECT_EQ(r.nodes.front(), f.depot_nodes[v]);
    EXPECT_EQ(r.nodes.back(), f.depot_nodes[v]);
    EXPECT_EQ(g.edges[static_cast<std::size_t>(r.edges.front())].u, f.depot_nodes[v]);
    EXPECT_EQ(test::extra(r).at("illegal_turns"), 0);
    driven.insert(r.edges.begin(), r.edges.end());
  }
  const int dropped = nlohmann::json::parse(f.extra_json).at("dropped_edges");
  EXPECT_EQ(driven.size() + dropped, g.edges.size());
  EXPECT_DOUBLE_EQ(f.edge_coverage_pct, 100.0);
  EXPECT_GE(f.makespan_m, f.lower_bound_m - 1e-6);
  EXPECT_GE(f.makespan_m, f.depot_bound_m - 1e-6);
  EXPECT_GE(f.depot_bound_m, f.longest_round_trip_m);
}

TEST(Fleet, TwoVehiclesSplitTheGridIntoHalvesOfExactlyHalfTheLength) {
  // 3 x 5 two-way grid, 100 m blocks, depot at the top middle junction (node 2): 22 streets,
  // 4400 m of directed edges, every node balanced, so L1 = 4400 and the bound is 2200. The two
  // halves (columns 0-2 and 2-4, the middle column's two streets one to each side) are closed
  // walks through the depot of 22 edges each: the optimum is 2200, the bound.
  const RoadGraph g = test::grid(3, 5);
  const FleetRoute f = planFleet(g, fleetConfig(2, "partition"), {2}, 1);
  expectCoveringClosedRoutes(g, f);
  EXPECT_NEAR(f.single_route_m, 4400.0, 1e-6);
  EXPECT_NEAR(f.lower_bound_m, 2200.0, 1e-6);
  EXPECT_NEAR(f.makespan_m, 2200.0, 1e-6);
  EXPECT_NEAR(f.total_length_m, 4400.0, 1e-6);
  EXPECT_NEAR(f.balance, 1.0, 1e-9);
}

TEST(Fleet, OddSplitOfABipartiteGridNeedsTheNextEvenLength) {
  // 2 x 3 grid, depot top middle: 7 streets, 14 directed edges of 100 m, bound 700. A grid is
  // bipartite, so every closed walk has an even number of edges: one route needs >= 8 edges.
  // The optimum 800 is one square with the middle street against the other square.
  const RoadGraph g = test::grid(2, 3);
  const FleetRoute f = planFleet(g, fleetConfig(2, "partition"), {1}, 1);
  expectCoveringClosedRoutes(g, f);
  EXPECT_NEAR(f.lower_bound_m, 700.0, 1e-6);
  EXPECT_NEAR(f.makespan_m, 800.0, 1e-6);
  EXPECT_NEAR(f.total_length_m, 1400.0, 1e-6);
}

class FleetOnRestrictedCity : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(FleetOnRestrictedCity, CoversEveryDirectedStreetLegallyAboveTheBound) {
  const auto [strategy, vehicles] = GetParam();
  GridCitySpec s;
  s.rows = 6, s.cols = 7, s.jitter_m = 20.0, s.one_way_fraction = 0.3, s.forbid_u_turns = true;
  s.seed = 5;
  const RoadGraph g = gridCity(s);
  const FleetRoute f = planFleet(g, fleetConfig(vehicles, strategy), {}, 3);
  ASSERT_EQ(static_cast<int>(f.vehicles.size()), vehicles);
  expectCoveringClosedRoutes(g, f);
  EXPECT_LE(f.makespan_m, 1.6 * f.lower_bound_m);  // loose: the bench records the real ratios
}

INSTANTIATE_TEST_SUITE_P(Strategies, FleetOnRestrictedCity,
                         ::testing::Combine(::testing::Values("partition", "postman"),
                                            ::testing::Values(2, 4)));

TEST(Fleet, OneDepotPerVehicle) {
  const RoadGraph g = test::grid(4, 4);
  const FleetRoute f = planFleet(g, fleetConfig(2, "partition"), {0, 15}, 1);
  expectCoveringClosedRoutes(g, f);
  EXPECT_EQ(f.depot_nodes, (std::vector<int>{0, 15}));
}

TEST(Fleet, SameSeedSameRoutes) {
  GridCitySpec s;
  s.rows = 5, s.cols = 5, s.jitter_m = 15.0, s.forbid_u_turns = true;
  const RoadGraph g = gridCity(s);
  const FleetRoute a = planFleet(g, fleetConfig(3, "partition"), {}, 7);
  const FleetRoute b = planFleet(g, fleetConfig(3, "partition"), {}, 7);
  for (std::size_t v = 0; v < 3; ++v) EXPECT_EQ(a.vehicles[v].edges, b.vehicles[v].edges);
}

TEST(Fleet, RoundTripDominatesTheBoundWhenVehiclesOutnumberTheWork) {
  // A 1 x 4 street (3 streets, 600 m directed), depot at one end, 3 vehicles: L1 / 3 = 200 but
  // the far street needs a 600 m round trip; one vehicle per street is optimal: 600.
  const RoadGraph g = test::grid(1, 4);
  const FleetRoute f = planFleet(g, fleetConfig(3, "partition"), {0}, 1);
  expectCoveringClosedRoutes(g, f);
  EXPECT_NEAR(f.longest_round_trip_m, 600.0, 1e-6);
  EXPECT_NEAR(f.lower_bound_m, 600.0, 1e-6);
  EXPECT_NEAR(f.makespan_m, 600.0, 1e-6);
}

TEST(Fleet, KicksKeepOnlyShorterMakespansAndFindOneOnARestrictedCity) {
  // The kicks (random boundary moves, each re-balanced) keep a partition only when its makespan
  // is shorter, so they never lengthen it; on this restricted city they shorten it.
  GridCitySpec s;
  s.rows = 6, s.cols = 7, s.jitter_m = 20.0, s.one_way_fraction = 0.3, s.forbid_u_turns = true;
  s.seed = 5;
  const RoadGraph g = gridCity(s);
  Config plain = fleetConfig(4, "partition"), kicked = plain;
  plain.fleet.kick_rounds = 0;
  kicked.fleet.kick_rounds = 30;
  const FleetRoute a = planFleet(g, plain, {}, 3), b = planFleet(g, kicked, {}, 3);
  expectCoveringClosedRoutes(g, b);
  EXPECT_LT(b.makespan_m, a.makespan_m - 1.0);
}

TEST(Fleet, DefaultCityTwoVehiclesReachTheProvenBoundAndFourCannotReach1_3TimesL1Over4) {
  // The proven bound (FlowBound.cpp) all but meets the makespan at K = 2: that split is within
  // 0.1 % (8 m of 9.99 km) of the optimum. At K = 4 it shows that no split reaches
  // 1.3 x max(L1 / 4, longest round trip), the issue's yardstick: every vehicle's trip out and
  // back through the one-way streets costs more than L1 / 4 leaves room for.
  const RoadGraph g = test::netGraph(test::defaultCityNet());
  const FleetRoute two = planFleet(g, fleetConfig(2, "partition"), {}, 1);
  expectCoveringClosedRoutes(g, two);
  EXPECT_LE(two.makespan_m, 1.001 * two.depot_bound_m);
  const FleetRoute four = planFleet(g, fleetConfig(4, "partition"), {}, 1);
  expectCoveringClosedRoutes(g, four);
  EXPECT_GT(four.depot_bound_m, 1.3 * four.lower_bound_m);
  EXPECT_LE(four.makespan_m, 1.05 * four.depot_bound_m);
}

TEST(Fleet, AdlershofEightVehiclesMeetTheIssuesTarget) {
  // Berlin-Adlershof (sumo-tools), K = 8 from the default depot at the west edge: 1.3 x
  // max(L1 / 8, longest round trip) = 1.3 x 4.15 km = 5.40 km. Streets moved one at a time
  // stop at 5.88 km; merge-splits of neighbouring parts and the sweep either way round get the
  // routes under it.
  const RoadGraph g = test::netGraph(test::adlershofNet());
  const FleetRoute f = planFleet(g, fleetConfig(8, "partition"), {}, 1);
  expectCoveringClosedRoutes(g, f);
  EXPECT_NEAR(f.lower_bound_m, 4150.0, 10.0);
  EXPECT_LE(f.makespan_m, 1.3 * f.lower_bound_m);
}

TEST(Fleet, RejectsBadRequests) {
  const RoadGraph g = test::grid(2, 2);
  EXPECT_THROW(planFleet(g, fleetConfig(5, "partition"), {}, 1), std::invalid_argument);
  EXPECT_THROW(planFleet(g, fleetConfig(2, "zigzag"), {}, 1), std::invalid_argument);
  EXPECT_THROW(planFleet(g, fleetConfig(2, "partition"), {0, 1, 2}, 1), std::invalid_argument);
  EXPECT_THROW(planFleet(g, fleetConfig(2, "partition"), {99}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::rl
