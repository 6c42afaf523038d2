// Directed coverage of SUMO edges and route lengths as SUMO drives them (SumoCoverage.hpp).
#include <gtest/gtest.h>

#include <fstream>

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

// A-B two-way, cars turn round at A and at B; B-C two-way to C at the map border, where they
// may not turn round: BC is entered but never left, CB left but never entered.
const char* kBorderNet = R"(<?xml version="1.0"?>
<net version="1.9">
  <location netOffset="0.00,0.00" convBoundary="0,0,200,0" origBoundary="0,0,200,0" projParameter="!"/>
  <edge id="AB" from="A" to="B"><lane id="AB_0" index="0" speed="13.89" length="100" shape="0,-1.6 100,-1.6"/></edge>
  <edge id="BA" from="B" to="A"><lane id="BA_0" index="0" speed="13.89" length="100" shape="100,1.6 0,1.6"/></edge>
  <edge id="BC" from="B" to="C"><lane id="BC_0" index="0" speed="13.89" length="100" shape="100,-1.6 200,-1.6"/></edge>
  <edge id="CB" from="C" to="B"><lane id="CB_0" index="0" speed="13.89" length="100" shape="200,1.6 100,1.6"/></edge>
  <junction id="A" type="priority" x="0" y="0" incLanes="BA_0" intLanes="" shape=""/>
  <junction id="B" type="priority" x="100" y="0" incLanes="AB_0 CB_0" intLanes="" shape=""/>
  <junction id="C" type="dead_end" x="200" y="0" incLanes="BC_0" intLanes="" shape=""/>
  <connection from="AB" to="BA" fromLane="0" toLane="0" dir="t" state="M"/>
  <connection from="AB" to="BC" fromLane="0" toLane="0" dir="s" state="M"/>
  <connection from="CB" to="BA" fromLane="0" toLane="0" dir="s" state="M"/>
  <connection from="BA" to="AB" fromLane="0" toLane="0" dir="t" state="M"/>
</net>
)";

TEST(SumoCoverage, EdgesWithoutALegalDriveRoundAreCountedApart) {
  const auto path = test::tempDir("sumo_coverage_border") / "border.net.xml";
  std::ofstream(path, std::ios::binary) << kBorderNet;
  const SumoCoverage c = sumoCoverage(SumoNet::read(path), {"AB", "BA", "AB", "BC"});
  EXPECT_EQ(c.edges_total, 2);  // AB, BA: BC and CB are no part of a legal drive round
  EXPECT_EQ(c.edges_driven, 2);
  EXPECT_DOUBLE_EQ(c.edges_pct, 100.0);
  EXPECT_EQ(c.junction_part_edges, 4);  // over junctions A, B, C strongly connect
  EXPECT_EQ(c.junction_part_driven, 3);
  EXPECT_DOUBLE_EQ(c.junction_part_pct, 75.0);
  EXPECT_EQ(c.edges_without_legal_route, 2);
  nlohmann::json j;
  sumoCoverageToJson(c, j);
  EXPECT_EQ(j["directed_coverage"]["junction_part"]["edges_without_legal_route"].get<int>(), 2);
  const auto back = sumoCoverageFromJson(j);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->edges_without_legal_route, 2);
  EXPECT_DOUBLE_EQ(back->junction_part_pct, 75.0);
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
