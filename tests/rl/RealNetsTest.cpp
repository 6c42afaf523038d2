// The planners on the real SUMO nets, one parameterised suite per property: every node covered
// with legal turns (planner x net), the postman's length against its lower bounds (per net) and
// SUMO driving the route to its end without teleports (planner x net).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "RlTestUtil.hpp"
#include "TestTmp.hpp"

namespace slamroute::rl {
namespace {

namespace fs = std::filesystem;

fs::path netNamed(const std::string& name) {
  if (name == "bologna") return test::bolognaNet();
  if (name == "adlershof") return test::adlershofNet();
  return test::defaultCityNet();
}

Route planOn(const fs::path& net, const std::string& planner, std::uint64_t seed) {
  Config c;
  c.planner = planner;
  return plan(test::netGraph(net), c, seed, net.string());
}

using PlannerNet = std::tuple<std::string, std::string>;

std::string caseName(const ::testing::TestParamInfo<PlannerNet>& info) {
  return std::get<0>(info.param) + "_" + std::get<1>(info.param);
}

class PlannerOnNet : public ::testing::TestWithParam<PlannerNet> {};

TEST_P(PlannerOnNet, CoversEveryNodeWithLegalTurns) {
  const auto& [planner, name] = GetParam();
  const Route r = planOn(netNamed(name), planner, 42);
  EXPECT_EQ(r.planner, planner);
  EXPECT_DOUBLE_EQ(r.node_coverage_pct, 100.0);
  EXPECT_EQ(test::extra(r)["illegal_turns"].get<int>(), 0);
  EXPECT_FALSE(r.sumo_edges.empty());
}

INSTANTIATE_TEST_SUITE_P(RealNets, PlannerOnNet,
                         ::testing::Combine(::testing::Values("qlearning", "postman"),
                                            ::testing::Values("bologna", "adlershof",
                                                              "default_city")),
                         caseName);

/// A net and how far above the turn-free optimum its postman route may be.
struct PostmanBound {
  std::string net;
  double max_excess_over_turn_free_pct;
};

class PostmanOnNet : public ::testing::TestWithParam<PostmanBound> {};

TEST_P(PostmanOnNet, DrivesEveryEdgeNearTheLegalLowerBound) {
  const Route r = planOn(netNamed(GetParam().net), "postman", 1);
  const auto x = test::extra(r);
  // A share of summed lengths: on Adlershof's 696 edges it lands 1e-13 below 100.
  EXPECT_NEAR(r.edge_coverage_pct, 100.0, 1e-9);
  // Every directed edge of the planning graph at least once.
  std::set<int> driven(r.edges.begin(), r.edges.end());
  EXPECT_EQ(static_cast<int>(driven.size()), x["plan_graph"]["edges"].get<int>());
  const double lb = x["turn_free_optimum_m"].get<double>();
  const double legal_lb = x["legal_circulation_m"].get<double>();
  EXPECT_GE(r.length_m + 1e-6, legal_lb);
  EXPECT_GE(legal_lb + 1e-6, lb);
  // Within 3 % of the best legal length we can bound (the turn-legal circulation).
  EXPECT_LE(r.length_m, 1.03 * legal_lb);
  EXPECT_LE(r.length_m, (1.0 + GetParam().max_excess_over_turn_free_pct / 100.0) * lb)
      << "turn-free optimum " << lb << " m, legal lower bound " << legal_lb << " m";
}

// Bologna forbids so many U-turns that no legal closed route can come within 3 % of the
// turn-free optimum: the turn-legal circulation (a proven lower bound) is 9.85 % above it.
// The route must reach that legal bound. On Adlershof the two coincide.
INSTANTIATE_TEST_SUITE_P(RealNets, PostmanOnNet,
                         ::testing::Values(PostmanBound{"adlershof", 3.0},
                                           PostmanBound{"bologna", 10.0}),
                         [](const ::testing::TestParamInfo<PostmanBound>& info) {
                           return info.param.net;
                         });

std::string readFile(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class SumoDrivesRoute : public ::testing::TestWithParam<PlannerNet> {};

TEST_P(SumoDrivesRoute, ToItsEndWithoutTeleports) {
  const auto& [planner, name] = GetParam();
  const fs::path net = netNamed(name);
  ASSERT_TRUE(fs::exists("/usr/bin/sumo")) << "scripts/setup.sh installs sumo";
  const Route r = planOn(net, planner, 1);
  const fs::path dir = slamroute::test::testTmp() / ("rl_sumo_" + planner + "_" + name);
  fs::create_directories(dir);
  r.writeRouXml(dir / "route.rou.xml");
  const fs::path log = dir / "sumo.log";
  const std::string cmd =
      "/usr/bin/sumo -n " + net.string() + " -r " + (dir / "route.rou.xml").string() +
      " --end 200000 --no-step-log --duration-log.statistics > " + log.string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  const std::string out = readFile(log);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_EQ(out.find("Error"), std::string::npos) << out;
  EXPECT_EQ(out.find("eleport"), std::string::npos) << out;  // "Teleports" / "teleporting"
  EXPECT_NE(out.find("Inserted: 1"), std::string::npos) << out;
  EXPECT_NE(out.find("Running: 0"), std::string::npos) << out;  // it arrived
  EXPECT_NE(out.find("Waiting: 0"), std::string::npos) << out;
}

INSTANTIATE_TEST_SUITE_P(RealNets, SumoDrivesRoute,
                         ::testing::Values(PlannerNet{"postman", "bologna"},
                                           PlannerNet{"postman", "adlershof"},
                                           PlannerNet{"qlearning", "bologna"}),
                         caseName);

}  // namespace
}  // namespace slamroute::rl
