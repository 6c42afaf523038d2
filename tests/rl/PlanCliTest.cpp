// `slamroute plan` end to end (skipped when the CLI is not built): files and one-line errors.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "RlTestUtil.hpp"
#include "slamroute/core/FleetRoute.hpp"

namespace slamroute::rl {
namespace {

namespace fs = std::filesystem;

struct CmdResult {
  int code;
  std::string output;
};

CmdResult runCli(const std::string& args) {
  const fs::path dir = slamroute::test::testTmp() / "rl_cli";
  fs::create_directories(dir);
  // One log per test: ctest runs the tests of this file in parallel processes.
  const std::string log =
      (dir /
       (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".log"))
          .string();
  const int rc =
      std::system((std::string(SLAMROUTE_BINARY) + " " + args + " > " + log + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, ss.str()};
}

class PlanCli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(SLAMROUTE_BINARY)) GTEST_SKIP() << "slamroute CLI not built";
    dir_ = slamroute::test::testTmp() / "rl_cli";
    fs::create_directories(dir_);
  }
  fs::path dir_;
};

TEST_F(PlanCli, NetWritesRouteJsonAndRouXml) {
  const auto net = test::bolognaNet();
  const fs::path out = dir_ / "bologna_route.json";
  fs::remove(out);
  fs::remove(dir_ / "bologna_route.rou.xml");
  const auto r = runCli("--log-level error plan --net " + net.string() +
                        " --planner postman --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_TRUE(fs::exists(dir_ / "bologna_route.rou.xml"));
  const Route route = Route::readJson(out);
  EXPECT_EQ(route.planner, "postman");
  EXPECT_DOUBLE_EQ(route.edge_coverage_pct, 100.0);
}

TEST_F(PlanCli, GraphJsonInput) {
  const fs::path graph = dir_ / "grid.json", out = dir_ / "grid_route.json";
  test::grid(3, 3).writeJson(graph);
  const auto r = runCli("--log-level error --seed 5 plan --graph " + graph.string() +
                        " --planner qlearning --reward accuracy --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const Route route = Route::readJson(out);
  EXPECT_EQ(route.seed, 5u);
  EXPECT_DOUBLE_EQ(route.node_coverage_pct, 100.0);
}

TEST_F(PlanCli, BadInputGivesOneLineErrors) {
  const fs::path out = dir_ / "never.json";
  fs::remove(out);
  auto r = runCli("plan --graph " + (dir_ / "missing.json").string() + " --out " + out.string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("slamroute: error:"), std::string::npos) << r.output;
  const fs::path graph = dir_ / "grid2.json";
  test::grid(2, 2).writeJson(graph);
  r = runCli("plan --graph " + graph.string() + " --planner nope --out " + out.string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("unknown planner 'nope'"), std::string::npos) << r.output;
  r = runCli("plan --graph " + graph.string() + " --planner postman --start 77 --out " +
             out.string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("start node 77"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(PlanCli, VehiclesWriteOneRoutePerVehicleAndAFleetRouXml) {
  const fs::path net = test::defaultCityNet();
  const fs::path out = dir_ / "fleet_route.json";
  const auto r = runCli("--log-level error plan --net " + net.string() +
                        " --planner partition --vehicles 3 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const FleetRoute f = FleetRoute::readJson(out);
  ASSERT_EQ(f.vehicles.size(), 3u);
  EXPECT_DOUBLE_EQ(f.edge_coverage_pct, 100.0);
  EXPECT_GE(f.makespan_m, f.lower_bound_m);
  std::ifstream rou(dir_ / "fleet_route.rou.xml");
  std::stringstream xml;
  xml << rou.rdbuf();
  for (const char* id : {"mapper_0", "mapper_1", "mapper_2"})
    EXPECT_NE(xml.str().find(std::string("<vehicle id=\"") + id + "\""), std::string::npos);
}

TEST_F(PlanCli, UnknownDepotEdgeIsAOneLineError) {
  const auto r = runCli("--log-level error plan --net " + test::defaultCityNet().string() +
                        " --planner postman --vehicles 2 --depot no_such_edge --out " +
                        (dir_ / "fleet_bad.json").string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("depot edge 'no_such_edge'"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "fleet_bad.json"));
}

}  // namespace
}  // namespace slamroute::rl
