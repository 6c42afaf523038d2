// runFleetDrive on the 3x3 grid: two mapping vehicles in one SUMO session, each folder's ground
// truth on its own route's lanes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "DriveTestUtil.hpp"
#include "TestTmp.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/core/FleetRoute.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/simulate/FleetDrive.hpp"

namespace {
namespace fs = std::filesystem;
using namespace slamroute;

using test::distToPolyline;
using test::drivenEdges;

/// Share of the ground-truth positions within 0.5 m of a lane of one of `edges`.
double shareOnEdges(const Trajectory& gt, const SumoNet& net,
                    const std::vector<std::string>& edges) {
  std::size_t on = 0;
  for (const auto& p : gt) {
    double d = 1e18;
    for (const auto& id : edges)
      for (const auto& lane : net.findEdge(id)->lanes)
        d = std::min(d, distToPolyline(p.T_world_body.translation(), lane.shape));
    on += d < 0.5 ? 1 : 0;
  }
  return static_cast<double>(on) / static_cast<double>(gt.size());
}

TEST(FleetDrive, TwoVehiclesInOneSessionEachFollowItsOwnRoute) {
  const fs::path dir = test::testTmp() / "fleet_drive";
  const fs::path route = test::testTmp() / "fleet_drive_route.json";
  const std::vector<std::vector<std::string>> routes = {
      {"g00_g01", "g01_g02", "g02_g12", "g12_g22"}, {"g00_g10", "g10_g20", "g20_g21", "g21_g22"}};
  FleetRoute fleet;
  fleet.strategy = "manual";
  for (const auto& r : routes) {
    Route v;
    v.planner = "manual";
    v.sumo_edges = r;
    fleet.vehicles.push_back(v);
  }
  fleet.writeJson(route);
  simulate::Config cfg = test::vlp16Config();
  cfg.drive.traffic_per_km = 5.0;
  const simulate::DriveOptions o = test::testDrive("test/grid3x3.net.xml", route, dir, 7);
  const simulate::FleetDriveResult r = simulate::runFleetDrive(o, cfg);
  ASSERT_EQ(r.vehicles.size(), 2u);

  const FleetDriveInfo info = FleetDriveInfo::read(dir);
  ASSERT_EQ(info.vehicles.size(), 2u);
  const SumoNet net = SumoNet::read(o.net);
  for (std::size_t k = 0; k < 2; ++k) {
    const fs::path vdir = dir / info.vehicles[k].folder;
    EXPECT_EQ(info.vehicles[k].folder, "vehicle_" + std::to_string(k));
    EXPECT_EQ(info.vehicles[k].id, "mapper_" + std::to_string(k));
    for (const char* f : {drive_files::kGroundTruth, drive_files::kPoseEdges, drive_files::kSensor,
                          drive_files::kWorld, drive_files::kDriveInfo, drive_files::kOdometry})
      EXPECT_TRUE(fs::exists(vdir / f)) << vdir / f;
    EXPECT_EQ(drivenEdges(vdir), routes[k]);
    const Trajectory gt = readTum(vdir / drive_files::kGroundTruth);
    ASSERT_GT(gt.size(), 100u);
    EXPECT_EQ(gt.size(), info.vehicles[k].frames);
    // On its own route's lanes (junctions aside), and mostly off the other vehicle's streets.
    EXPECT_GT(shareOnEdges(gt, net, routes[k]), 0.8) << k;
    EXPECT_LT(shareOnEdges(gt, net, routes[1 - k]), 0.2) << k;
  }
  // Both drove at once: their time spans overlap, and the makespan is the longer one.
  const auto& a = info.vehicles[0];
  const auto& b = info.vehicles[1];
  EXPECT_LT(std::max(a.depart_s, b.depart_s), std::min(a.arrive_s, b.arrive_s));
  EXPECT_NEAR(info.makespanSeconds(),
              std::max(a.arrive_s, b.arrive_s) - std::min(a.depart_s, b.depart_s), 1e-9);
  // Each vehicle has its own odometry noise.
  std::ifstream o0(dir / "vehicle_0" / drive_files::kOdometry),
      o1(dir / "vehicle_1" / drive_files::kOdometry);
  std::stringstream s0, s1;
  s0 << o0.rdbuf();
  s1 << o1.rdbuf();
  EXPECT_NE(s0.str(), s1.str());
}

}  // namespace
