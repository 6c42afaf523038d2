// Seeded mutation fuzzing of core's readers (tests/FuzzMutate.hpp): SUMO nets, graph.json,
// route.json, TUM and KITTI trajectories. 300 mutants each, a few seconds in all.
#include <gtest/gtest.h>

#include <sstream>

#include "FuzzMutate.hpp"
#include "TestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Trajectory.hpp"

namespace slamroute {
namespace {

const std::string kPlus = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml";
constexpr int kMutants = 300;

TEST(FuzzReaders, SumoNet) {
  test::fuzzReader(readFile(kPlus), test::testTmp() / "m.net.xml", 1, kMutants,
                   [](const auto& p) { networkInfo(SumoNet::read(p)); });
}

TEST(FuzzReaders, GraphJson) {
  const auto dir = test::testTmp();
  RoadGraph::fromSumoNet(SumoNet::read(kPlus), true).writeJson(dir / "base.json");
  test::fuzzReader(readFile(dir / "base.json"), dir / "m.graph.json", 2, kMutants,
                   [](const auto& p) { RoadGraph::readJson(p); });
}

TEST(FuzzReaders, RouteJson) {
  const auto dir = test::testTmp();
  Route r;
  r.planner = "postman";
  r.nodes = {0, 1, 2, 1, 0};
  r.edges = {0, 3, 5, 4};
  r.sumo_edges = {"a", "b", "c", "d"};
  r.length_m = 412.5;
  r.logdet_cov_along = {-3.5, -2.25, -1.0};
  r.writeJson(dir / "base.json");
  test::fuzzReader(readFile(dir / "base.json"), dir / "m.route.json", 3, kMutants,
                   [](const auto& p) { Route::readJson(p); });
}

std::string trajectoryText(bool kitti) {
  std::ostringstream os;
  os.precision(9);
  for (int i = 0; i < 20; ++i) {
    const double c = std::cos(0.05 * i), s = std::sin(0.05 * i);
    if (kitti)
      os << c << " " << -s << " 0 " << 2.0 * i << " " << s << " " << c << " 0 " << 0.1 * i
         << " 0 0 1 0\n";
    else
      os << 0.1 * i << " " << 2.0 * i << " " << 0.1 * i << " 0 0 0 " << std::sin(0.025 * i) << " "
         << std::cos(0.025 * i) << "\n";
  }
  return os.str();
}

TEST(FuzzReaders, TumTrajectory) {
  test::fuzzReader(trajectoryText(false), test::testTmp() / "m.tum", 4, kMutants,
                   [](const auto& p) { readTrajectory(p); });
}

TEST(FuzzReaders, KittiTrajectory) {
  test::fuzzReader(trajectoryText(true), test::testTmp() / "m.txt", 5, kMutants,
                   [](const auto& p) { readTrajectory(p); });
}

}  // namespace
}  // namespace slamroute
