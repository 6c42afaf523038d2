// A fleet's route.json and .rou.xml: round trip, K vehicles, malformed files named.
#include <gtest/gtest.h>

#include "TestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/FleetRoute.hpp"

namespace slamroute {
namespace {

FleetRoute twoVehicles() {
  FleetRoute f;
  f.strategy = "partition";
  f.seed = 3;
  for (int v = 0; v < 2; ++v) {
    Route r;
    r.planner = "fleet-partition";
    r.edges = {v, v + 1};
    r.sumo_edges = {"a" + std::to_string(v), "b"};
    r.length_m = 100.0 * (v + 1);
    f.vehicles.push_back(r);
    f.depot_nodes.push_back(5);
  }
  f.makespan_m = 200.0;
  f.total_length_m = 300.0;
  f.lower_bound_m = 160.0;
  f.depot_bound_m = 180.0;
  return f;
}

TEST(FleetRoute, RoundTripAndOneSumoVehiclePerRoute) {
  const auto dir = test::tempDir("fleet_route");
  twoVehicles().writeJson(dir / "route.json");
  EXPECT_TRUE(FleetRoute::isFleetFile(dir / "route.json"));
  const FleetRoute f = FleetRoute::readJson(dir / "route.json");
  ASSERT_EQ(f.vehicles.size(), 2u);
  EXPECT_EQ(f.vehicles[1].edges, (std::vector<int>{1, 2}));
  EXPECT_EQ(f.depot_nodes, (std::vector<int>{5, 5}));
  EXPECT_DOUBLE_EQ(f.makespan_m, 200.0);
  EXPECT_DOUBLE_EQ(f.lower_bound_m, 160.0);
  EXPECT_DOUBLE_EQ(f.depot_bound_m, 180.0);
  f.writeRouXml(dir / "route.rou.xml");
  const std::string xml = readFile(dir / "route.rou.xml");
  EXPECT_NE(xml.find("<vehicle id=\"mapper_0\""), std::string::npos);
  EXPECT_NE(xml.find("<vehicle id=\"mapper_1\""), std::string::npos);
  EXPECT_NE(xml.find("edges=\"a1 b\""), std::string::npos);
}

TEST(FleetRoute, SingleRouteIsNoFleetAndBadFilesAreNamed) {
  const auto dir = test::tempDir("fleet_route_bad");
  Route single;
  single.edges = {1};
  single.writeJson(dir / "single.json");
  EXPECT_FALSE(FleetRoute::isFleetFile(dir / "single.json"));
  test::writeText(dir / "none.json", R"({"fleet": {}, "vehicles": []})");
  test::writeText(dir / "empty_route.json", R"({"vehicles": [{"planner": "x"}]})");
  test::writeText(dir / "wrong.json", R"({"vehicles": [{"edges": "no"}]})");
  for (const char* name : {"none.json", "empty_route.json", "wrong.json", "single.json"}) {
    try {
      FleetRoute::readJson(dir / name);
      ADD_FAILURE() << name << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace slamroute
