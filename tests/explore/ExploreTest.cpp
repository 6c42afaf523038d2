// The online exploration in SUMO: the plus, the 3 x 3 grid and the stub net (a sub-metre dead
// end) explored to 100 % with every strategy family, the outputs written, the same seed giving
// the same bytes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include "TestTmp.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/explore/Explore.hpp"
#include "slamroute/explore/Measures.hpp"

namespace slamroute::explore {
namespace {

std::filesystem::path testNet(const std::string& name) {
  return std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks/test" / name;
}

ExploreResult explore(const std::string& net, int k, const std::string& strategy,
                      const std::filesystem::path& out, const Config& cfg) {
  ExploreOptions o;
  o.net = testNet(net);
  o.vehicles = k;
  o.strategy = strategy;
  o.out_dir = out;
  return runExplore(o, cfg, simulate::WorldConfig{}, simulate::DriveConfig{});
}

ExploreResult explore(const std::string& net, int k, const std::string& strategy,
                      const std::filesystem::path& out) {
  const Config defaults;
  return explore(net, k, strategy, out, defaults);
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Explore, PlusNetIsExploredToTheEndByOneVehicle) {
  const auto out = test::testTmp() / "plus";
  const ExploreResult r = explore("plus.net.xml", 1, "nearest", out);
  EXPECT_EQ(r.total_edges, 8);
  EXPECT_EQ(r.edges_driven, 8);
  ASSERT_EQ(r.milestones.size(), 3u);
  EXPECT_TRUE(r.milestones[2].reached);
  // one vehicle on a plus must drive every arm both ways: at least the 8 edges' length
  EXPECT_GE(r.milestones[2].fleet_distance_m, 8 * 140.0);
  EXPECT_GE(r.milestones[2].fleet_distance_m, r.offline_bound_m - 1e-6);
  // driven.rou.xml: one vehicle whose route is a legal SUMO route through every edge
  const SumoNet net = SumoNet::read(testNet("plus.net.xml"));
  ASSERT_EQ(r.vehicles.size(), 1u);
  for (std::size_t i = 1; i < r.vehicles[0].edges.size(); ++i)
    EXPECT_TRUE(net.turnAllowed(r.vehicles[0].edges[i - 1], r.vehicles[0].edges[i]));
  const std::string xml = slurp(out / "driven.rou.xml");
  EXPECT_NE(xml.find("<vehicle id=\"explorer0\""), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(out / "explore.json"));
  EXPECT_EQ(j["streets_driven"], 8);
  EXPECT_TRUE(std::filesystem::exists(out / "coverage.png"));
  EXPECT_TRUE(std::filesystem::exists(out / "timing.json"));
}

TEST(Explore, GridNetIsExploredToTheEndByEveryStrategy) {
  for (const std::string s : {"gp-frontier", "fleet", "siba"}) {
    const int k = s == "fleet" ? 2 : 1;
    const ExploreResult r = explore("grid3x3.net.xml", k, s, test::testTmp() / s);
    EXPECT_EQ(r.total_edges, 24) << s;
    EXPECT_EQ(r.edges_driven, 24) << s;
    EXPECT_TRUE(r.milestones[2].reached) << s;
    EXPECT_FALSE(r.time_limit_hit) << s;
    EXPECT_EQ(r.vehicles.size(), static_cast<std::size_t>(k)) << s;
  }
}

// The stub's edges M_A and A_M (the dead end at its east edge) are 0.2 m long: an explorer
// turning round at A and back at M drives them between two looks and is seen only inside the
// junctions, where it must still get a route on.
TEST(Explore, SubMetreDeadEndIsDrivenBothWaysAndTheNetToTheEnd) {
  const SumoNet net = SumoNet::read(testNet("stub.net.xml"));
  const Config defaults;
  for (const auto& [s, k] :
       std::vector<std::pair<std::string, int>>{{"nearest", 1}, {"siba", 2}, {"fleet", 2}}) {
    ExploreOptions o;
    o.net = testNet("stub.net.xml");
    o.vehicles = k;
    o.strategy = s;
    o.start_edges = {"W_C"};  // the far end: the stub is met at the edge of what is known
    o.out_dir = test::testTmp() / s;
    const ExploreResult r =
        runExplore(o, defaults, simulate::WorldConfig{}, simulate::DriveConfig{});
    EXPECT_EQ(r.total_edges, 12) << s;
    EXPECT_EQ(r.edges_driven, 12) << s;
    EXPECT_TRUE(r.milestones[2].reached) << s;
    EXPECT_FALSE(r.time_limit_hit) << s;
    int stub_both_ways = 0;
    for (const VehicleResult& v : r.vehicles)
      for (std::size_t i = 1; i < v.edges.size(); ++i) {
        EXPECT_TRUE(net.turnAllowed(v.edges[i - 1], v.edges[i])) << s << ": " << v.edges[i];
        stub_both_ways += v.edges[i - 1] == "M_A" && v.edges[i] == "A_M";
      }
    EXPECT_GE(stub_both_ways, 1) << s;
  }
}

TEST(Explore, PlusNetIsExploredToTheEndWithDeadReckonedMapPoses) {
  const ExploreResult truth = explore("plus.net.xml", 1, "nearest", test::testTmp() / "truth");
  Config cfg;
  cfg.map_poses = "slam";
  const ExploreResult slam = explore("plus.net.xml", 1, "nearest", test::testTmp() / "slam", cfg);
  EXPECT_EQ(slam.edges_driven, 8);
  EXPECT_TRUE(slam.milestones[2].reached);
  // the drift moves what the scans mark: the grids differ, though the same streets were seen
  ASSERT_EQ(slam.grid.size(), truth.grid.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < truth.grid.size(); ++i) differ += truth.grid[i] != slam.grid[i];
  EXPECT_GT(differ, 20u);
  EXPECT_GT(slam.streets_known, 0);
  EXPECT_EQ(nlohmann::json::parse(slurp(test::testTmp() / "slam/explore.json"))["map_poses"],
            "slam");
}

TEST(Explore, SameSeedSameSummaryBytes) {
  const auto a = test::testTmp() / "a", b = test::testTmp() / "b";
  explore("plus.net.xml", 2, "central", a);
  explore("plus.net.xml", 2, "central", b);
  EXPECT_EQ(slurp(a / "explore.json"), slurp(b / "explore.json"));
  EXPECT_EQ(slurp(a / "driven.rou.xml"), slurp(b / "driven.rou.xml"));
}

TEST(Explore, BadOptionsAreRejectedAndLeaveNothing) {
  const auto out = test::testTmp() / "bad";
  EXPECT_THROW(explore("plus.net.xml", 1, "random-walk", out), std::invalid_argument);
  ExploreOptions o;
  o.net = testNet("plus.net.xml");
  o.out_dir = out;
  o.start_edges = {"no_such_edge"};
  EXPECT_THROW(runExplore(o, Config{}, simulate::WorldConfig{}, simulate::DriveConfig{}),
               std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ExploreMeasures, MilestonesAreTheFirstCurvePointsAtTheirShare) {
  std::vector<CoverageSample> curve;
  for (int i = 1; i <= 20; ++i) curve.push_back({10.0 * i, 100.0 * i, {100.0 * i}, i});
  const Milestone m90 = milestoneAt(curve, 20, 0.90), m95 = milestoneAt(curve, 20, 0.95);
  EXPECT_TRUE(m90.reached);
  EXPECT_DOUBLE_EQ(m90.time_s, 180.0);  // 18 of 20 edges
  EXPECT_DOUBLE_EQ(m95.fleet_distance_m, 1900.0);
  curve.pop_back();
  EXPECT_FALSE(milestoneAt(curve, 20, 1.0).reached);
}

}  // namespace
}  // namespace slamroute::explore
