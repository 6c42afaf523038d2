// Directed coverage of SUMO edges and route lengths as SUMO drives them (SumoCoverage.hpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "TestUtil.hpp"
#include "TwoWayStreetNet.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoCoverage.hpp"

namespace slamroute {
namespace {

TEST(SumoCoverage, TwoWayStreetDrivenOneWayIsHalfCovered) {
  const SumoCoverage c = sumoCoverage(test::twoWayStreetNet(), {"AB"});
  EXPECT_EQ(c.edges_total, 2);  // the bus lane and the internal edges are not drivable
  EXPECT_EQ(c.edges_driven, 1);
  EXPECT_DOUBLE_EQ(c.edges_pct, 50.0);
  EXPECT_DOUBLE_EQ(c.length_pct, 50.0);
  EXPECT_DOUBLE_EQ(c.length_total_m, 200.0);
  EXPECT_DOUBLE_EQ(c.routeLengthM(), 100.0);
}

TEST(SumoCoverage, RouteLengthAddsTheJunctionLanesBetweenEdges) {
  // AB, (5 + 2 m at B), BA, (8 m at A), AB: 300 m on edges, 15 m in junctions.
  const SumoCoverage c = sumoCoverage(test::twoWayStreetNet(), {"AB", ":B_0", "BA", "BA", "AB"});
  EXPECT_DOUBLE_EQ(c.edges_pct, 100.0);
  EXPECT_DOUBLE_EQ(c.route_on_edges_m, 300.0);
  EXPECT_DOUBLE_EQ(c.route_in_junctions_m, 15.0);
  EXPECT_DOUBLE_EQ(c.routeLengthM(), 315.0);
  EXPECT_EQ(c.turns_without_connection, 0);
}

TEST(SumoCoverage, CountsTurnsSumoDoesNotJoin) {
  const SumoCoverage c = sumoCoverage(test::twoWayStreetNet(), {"AB", "AB_bus"});
  EXPECT_EQ(c.turns_without_connection, 1);
  EXPECT_DOUBLE_EQ(c.route_in_junctions_m, 0.0);
  EXPECT_EQ(c.edges_driven, 1);  // the bus lane is driven but not counted
}

TEST(SumoCoverage, RoundTripsThroughRouteJson) {
  Route r;
  r.planner = "manual";
  r.sumo_edges = {"AB", "BA"};
  r.sumo_coverage = sumoCoverage(test::twoWayStreetNet(), r.sumo_edges);
  const auto path = test::tempDir("sumo_coverage_json") / "route.json";
  r.writeJson(path);
  const Route back = Route::readJson(path);
  ASSERT_TRUE(back.sumo_coverage.has_value());
  EXPECT_DOUBLE_EQ(back.sumo_coverage->edges_pct, 100.0);
  EXPECT_DOUBLE_EQ(back.sumo_coverage->routeLengthM(), 207.0);
  EXPECT_EQ(back.sumo_coverage->edges_total, 2);
}

}  // namespace
}  // namespace slamroute
