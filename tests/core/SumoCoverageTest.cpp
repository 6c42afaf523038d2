// Directed coverage of SUMO edges and route lengths as SUMO drives them (SumoCoverage.hpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "TestUtil.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoCoverage.hpp"

namespace slamroute {
namespace {

// One two-way street A-B (100 m each way) and a bus-only edge beside it. The turn at B (AB onto
// BA) passes two internal lanes (5 m + 2 m, an internal junction splits it), the one at A one
// (8 m).
const char* kStreetNet = R"(<?xml version="1.0"?>
<net version="1.9">
  <location netOffset="0.00,0.00" convBoundary="0,0,100,0" origBoundary="0,0,100,0" projParameter="!"/>
  <edge id=":A_0" function="internal"><lane id=":A_0_0" index="0" speed="5" length="8" shape="0,1.6 0,-1.6"/></edge>
  <edge id=":B_0" function="internal"><lane id=":B_0_0" index="0" speed="5" length="5" shape="100,-1.6 102,0"/></edge>
  <edge id=":B_1" function="internal"><lane id=":B_1_0" index="0" speed="5" length="2" shape="102,0 100,1.6"/></edge>
  <edge id="AB" from="A" to="B" priority="1">
    <lane id="AB_0" index="0" speed="13.89" length="100" shape="0,-1.6 100,-1.6"/>
  </edge>
  <edge id="BA" from="B" to="A" priority="1">
    <lane id="BA_0" index="0" speed="13.89" length="100" shape="100,1.6 0,1.6"/>
  </edge>
  <edge id="AB_bus" from="A" to="B" priority="1">
    <lane id="AB_bus_0" index="0" speed="13.89" length="100" allow="bus" shape="0,-5 100,-5"/>
  </edge>
  <junction id="A" type="priority" x="0" y="0" incLanes="BA_0" intLanes=":A_0_0" shape=""/>
  <junction id="B" type="priority" x="100" y="0" incLanes="AB_0" intLanes=":B_0_0 :B_1_0" shape=""/>
  <junction id=":B_1_0" type="internal" x="102" y="0" incLanes=":B_0_0" intLanes=""/>
  <connection from="AB" to="BA" fromLane="0" toLane="0" via=":B_0_0" dir="t" state="M"/>
  <connection from="BA" to="AB" fromLane="0" toLane="0" via=":A_0_0" dir="t" state="M"/>
  <connection from=":B_0" to="BA" fromLane="0" toLane="0" via=":B_1_0" dir="t" state="M"/>
  <connection from=":B_1" to="BA" fromLane="0" toLane="0" dir="t" state="M"/>
  <connection from=":A_0" to="AB" fromLane="0" toLane="0" dir="t" state="M"/>
</net>
)";

SumoNet streetNet() {
  const auto dir = test::tempDir("sumo_coverage");
  test::writeText(dir / "street.net.xml", kStreetNet);
  return SumoNet::read(dir / "street.net.xml");
}

TEST(SumoCoverage, TwoWayStreetDrivenOneWayIsHalfCovered) {
  const SumoCoverage c = sumoCoverage(streetNet(), {"AB"});
  EXPECT_EQ(c.edges_total, 2);  // the bus lane and the internal edges are not drivable
  EXPECT_EQ(c.edges_driven, 1);
  EXPECT_DOUBLE_EQ(c.edges_pct, 50.0);
  EXPECT_DOUBLE_EQ(c.length_pct, 50.0);
  EXPECT_DOUBLE_EQ(c.length_total_m, 200.0);
  EXPECT_DOUBLE_EQ(c.routeLengthM(), 100.0);
}

TEST(SumoCoverage, RouteLengthAddsTheJunctionLanesBetweenEdges) {
  // AB, (5 + 2 m at B), BA, (8 m at A), AB: 300 m on edges, 15 m in junctions.
  const SumoCoverage c = sumoCoverage(streetNet(), {"AB", ":B_0", "BA", "BA", "AB"});
  EXPECT_DOUBLE_EQ(c.edges_pct, 100.0);
  EXPECT_DOUBLE_EQ(c.route_on_edges_m, 300.0);
  EXPECT_DOUBLE_EQ(c.route_in_junctions_m, 15.0);
  EXPECT_DOUBLE_EQ(c.routeLengthM(), 315.0);
  EXPECT_EQ(c.turns_without_connection, 0);
}

TEST(SumoCoverage, CountsTurnsSumoDoesNotJoin) {
  const SumoCoverage c = sumoCoverage(streetNet(), {"AB", "AB_bus"});
  EXPECT_EQ(c.turns_without_connection, 1);
  EXPECT_DOUBLE_EQ(c.route_in_junctions_m, 0.0);
  EXPECT_EQ(c.edges_driven, 1);  // the bus lane is driven but not counted
}

TEST(SumoCoverage, RoundTripsThroughRouteJson) {
  Route r;
  r.planner = "manual";
  r.sumo_edges = {"AB", "BA"};
  r.sumo_coverage = sumoCoverage(streetNet(), r.sumo_edges);
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
