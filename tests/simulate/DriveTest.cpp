// runDrive on the 3x3 grid: ground truth on the route's lanes, 10 Hz, pose edges in route order.
#include <gtest/gtest.h>
#include "DriveTestUtil.hpp"
#include "TestTmp.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace {
namespace fs = std::filesystem;
using namespace slamroute;

using test::distToPolyline;

/// Wheel odometry and gyro without noise, scale error or bias.
simulate::DriveConfig noiseFreeOdometry() {
  simulate::DriveConfig exact;
  exact.odometry_scale_sigma = exact.odometry_speed_noise_mps = 0;
  exact.gyro_bias_sigma_deg_s = exact.gyro_noise_deg_s = 0;
  return exact;
}

void expectPosesOnTheRouteLanes(const Trajectory& gt, const simulate::DriveResult& r,
                                const SumoNet& net) {
  // Positions on the route's lanes (outside junctions), the sensor its mount height above the
  // road (z = 0) give or take the road's camber and relief and the body's motion on them.
  const double h = lidarPreset("vlp16").mount_height_m;
  std::size_t on_edges = 0;
  for (std::size_t i = 0; i < gt.size(); ++i) {
    const Point3 p = gt[i].T_world_body.translation();
    EXPECT_NEAR(p.z(), h, 0.15);
    const SumoEdge* e = net.findEdge(r.pose_edges[i].sumo_edge);
    ASSERT_NE(e, nullptr);
    if (r.pose_edges[i].lane_pos_m > e->length()) continue;  // inside the junction after e
    double d = 1e18;
    for (const auto& lane : e->lanes) d = std::min(d, distToPolyline(p, lane.shape));
    EXPECT_LT(d, 0.5) << "pose " << i << " on " << e->id;
    ++on_edges;
  }
  EXPECT_GT(on_edges, gt.size() * 8 / 10);
}

void expectHeadingFollowsTheRoute(const Trajectory& gt, const SumoNet& net,
                                  const std::string& first_edge) {
  // Heading: the first edge runs from g00 to g01; the body x axis points along it.
  const Polyline& s0 = net.findEdge(first_edge)->lanes[0].shape;
  const Vec3 dir0 = (s0.back() - s0.front()).normalized();
  EXPECT_GT(gt[5].T_world_body.linear().col(0).dot(dir0), 0.999);
  // The route turns at four junctions: the heading turns smoothly (a car does not rotate by tens
  // of degrees in 0.1 s, as SUMO's lane angle does when it enters an internal lane): at most
  // 0.5 rad per metre driven (of arc: 1 % over the chord), and not at all while standing.
  for (std::size_t i = 1; i < gt.size(); ++i) {
    const Vec3 a = gt[i - 1].T_world_body.linear().col(0), b = gt[i].T_world_body.linear().col(0);
    const Vec3 step = gt[i].T_world_body.translation() - gt[i - 1].T_world_body.translation();
    const double limit = 0.505 * std::hypot(step.x(), step.y());
    const double turn = std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0));
    EXPECT_LE(turn, limit + 1e-6) << "pose " << i;
  }
}

void expectOdometryFollowsTheGroundTruth(const Trajectory& gt, const WheelOdometry& odo,
                                         double driven_m) {
  // odometry.csv: integrated over the whole drive, the wheel odometry + gyro (1 % scale, gyro
  // bias, noise) ends within a few metres and degrees of the ground truth's relative motion.
  const Pose3 dg = gt.front().T_world_body.inverse() * gt.back().T_world_body;
  const Pose3 dm = odo.motion(gt.front().t, gt.back().t);
  EXPECT_LT((dm.translation() - dg.translation()).head<2>().norm(), 0.05 * driven_m);
  EXPECT_LT(Eigen::AngleAxisd(dg.rotation().transpose() * dm.rotation()).angle(),
            5.0 * M_PI / 180.0);
  // Noise-free odometry reproduces each step of the ground truth to 2 cm (1.2 cm at most on
  // this drive): the recorded path never moves across its heading, so the wheels and gyro see
  // all of it.
  const WheelOdometry clean = simulate::simulateOdometry(gt, noiseFreeOdometry(), 5);
  for (std::size_t i = 10; i + 1 < gt.size(); i += 37) {
    const Pose3 step = gt[i].T_world_body.inverse() * gt[i + 1].T_world_body;
    const Pose3 m = clean.motion(gt[i].t, gt[i + 1].t);
    EXPECT_LT((m.translation() - step.translation()).head<2>().norm(), 0.02) << i;
  }
}

void expectImuTiltAndSeededNoise(const Trajectory& gt, const WheelOdometry& odo,
                                 const simulate::Config& cfg) {
  simulate::DriveConfig exact = noiseFreeOdometry();
  // IMU roll / pitch: noise-free they are the ground truth's (Z-Y-X Euler) roll and pitch; with
  // the default noise (0.05 deg bias, 0.1 deg white) within half a degree of them.
  exact.tilt_bias_sigma_deg = exact.tilt_noise_deg = 0;
  const WheelOdometry level = simulate::simulateOdometry(gt, exact, 5);
  for (std::size_t i = 0; i + 1 < gt.size(); i += 23) {
    const Mat3 R = gt[i].T_world_body.rotation();
    ASSERT_TRUE(level.attitude(gt[i].t).has_value());
    EXPECT_NEAR(level.attitude(gt[i].t)->roll_rad, std::atan2(R(2, 1), R(2, 2)), 1e-6) << i;
    EXPECT_NEAR(level.attitude(gt[i].t)->pitch_rad, -std::asin(R(2, 0)), 1e-6) << i;
    ASSERT_TRUE(odo.attitude(gt[i].t).has_value());
    EXPECT_NEAR(odo.attitude(gt[i].t)->pitch_rad, -std::asin(R(2, 0)), 0.5 * M_PI / 180.0) << i;
  }
  simulate::DriveConfig no_imu = cfg.drive;
  no_imu.tilt_bias_sigma_deg = -1.0;
  EXPECT_FALSE(simulate::simulateOdometry(gt, no_imu, 5).attitude(gt[5].t).has_value());
  // Same seed, same odometry; another seed, another bias.
  const auto a1 = simulate::simulateOdometry(gt, cfg.drive, 5).samples();
  const auto a2 = simulate::simulateOdometry(gt, cfg.drive, 5).samples();
  const auto a3 = simulate::simulateOdometry(gt, cfg.drive, 6).samples();
  ASSERT_EQ(a1.size(), a2.size());
  for (std::size_t i = 0; i < a1.size(); ++i) ASSERT_EQ(a1[i].yaw_rate_rad_s, a2[i].yaw_rate_rad_s);
  EXPECT_NE(a1[3].yaw_rate_rad_s, a3[3].yaw_rate_rad_s);
  EXPECT_NEAR(a1[3].yaw_rate_rad_s, odo.samples()[3].yaw_rate_rad_s, 1e-6);  // file = 7 decimals
}

TEST(Drive, GridRouteGroundTruthFollowsTheRouteLanesAt10Hz) {
  const fs::path dir = slamroute::test::testTmp() / "drive_grid";
  const fs::path route = slamroute::test::testTmp() / "drive_grid_route.json";
  const std::vector<std::string> edges = {"g00_g01", "g01_g02", "g02_g12",
                                          "g12_g11", "g11_g10", "g10_g20"};
  std::ofstream(route) << nlohmann::json(edges).dump();
  const simulate::Config cfg = test::vlp16Config();
  const simulate::DriveOptions o = test::testDrive("test/grid3x3.net.xml", route, dir, 5);
  const simulate::DriveResult r = simulate::runDrive(o, cfg);
  EXPECT_EQ(r.teleports, 0);
  EXPECT_EQ(r.route, edges);

  for (const char* f : {drive_files::kGroundTruth, drive_files::kPoseEdges, drive_files::kSensor,
                        drive_files::kWorld, drive_files::kDriveInfo, "traffic.csv"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_FALSE(fs::exists(dir / drive_files::kScanDir));

  const Trajectory gt = readTum(dir / drive_files::kGroundTruth);
  ASSERT_GT(gt.size(), 100u);
  ASSERT_EQ(gt.size(), r.pose_edges.size());
  for (std::size_t i = 1; i < gt.size(); ++i) ASSERT_NEAR(gt[i].t - gt[i - 1].t, 0.1, 1e-6) << i;

  // pose_edges.csv: the distinct edges, in order, are exactly the route.
  std::ifstream pe(dir / drive_files::kPoseEdges);
  std::string line;
  std::getline(pe, line);
  EXPECT_EQ(line, "index,t,sumo_edge,lane_pos_m");
  EXPECT_EQ(test::drivenEdges(dir), edges);

  const SumoNet net = SumoNet::read(o.net);
  expectPosesOnTheRouteLanes(gt, r, net);
  expectHeadingFollowsTheRoute(gt, net, edges[0]);
  const WheelOdometry odo = readOdometryCsv(dir / drive_files::kOdometry);
  ASSERT_EQ(odo.samples().size() + 1, gt.size());
  expectOdometryFollowsTheGroundTruth(gt, odo, r.driven_m);
  expectImuTiltAndSeededNoise(gt, odo, cfg);

  const auto j = nlohmann::json::parse(std::ifstream(dir / drive_files::kDriveInfo));
  EXPECT_EQ(j["teleports"].get<int>(), 0);
  EXPECT_EQ(j["frames"].get<std::size_t>(), gt.size());
  EXPECT_NEAR(j["route_length_m"].get<double>(), r.route_length_m, 1e-9);
}

}  // namespace

namespace {

TEST(Drive, TeleportedMapperIsAnErrorAndNothingIsWritten) {
  // With a 1 s teleport time and dense traffic, SUMO teleports the mapper the first time it
  // waits (at the traffic light of R1C2): the drive must fail instead of recording a jump.
  const fs::path dir = slamroute::test::testTmp() / "drive_teleport";
  const fs::path route = slamroute::test::testTmp() / "drive_teleport_route.json";
  fs::remove_all(dir);
  std::ofstream(route)
      << R"(["R1C1_R1C2","R1C2_R3C2","R3C2_R3C1","R3C1_R3C0","R3C0_R2C0","R2C0_R2C1","R2C1_R2C3"])";
  simulate::Config cfg;
  cfg.drive.time_to_teleport_s = 1.0;
  cfg.drive.traffic_per_km = 20.0;
  simulate::DriveOptions o;
  o.net = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
  o.route_file = route;
  o.out_dir = dir;
  o.seed = 42;
  try {
    simulate::runDrive(o, cfg);
    FAIL() << "a teleported mapper was recorded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("teleported the mapping vehicle"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir));
  for (const auto& e : fs::directory_iterator(dir.parent_path()))
    EXPECT_EQ(e.path().filename().string().find(".drive_teleport.tmp"), std::string::npos);
}

}  // namespace
