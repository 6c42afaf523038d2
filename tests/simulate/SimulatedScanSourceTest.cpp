#include "TestTmp.hpp"
#include "slamroute/simulate/SimulatedScanSource.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/ConfigIO.hpp"
#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::simulate {
namespace {

namespace fs = std::filesystem;

struct DriveDir {
  fs::path dir;
  fs::path net = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/test/overpass.net.xml";
  Trajectory gt;
  LidarConfig lidar;
  DriveWorldFile wf;
  TrafficFrames traffic;
};

/// A hand-made drive folder on the shipped overpass net: three poses along W_E (y = 498.4).
DriveDir makeDrive(const std::string& name) {
  DriveDir d;
  d.dir = slamroute::test::testTmp() / "simscan" / name;
  fs::remove_all(d.dir);
  fs::create_directories(d.dir);
  for (int i = 0; i < 3; ++i) {
    StampedPose p;
    p.t = 0.1 * i;
    p.T_world_body.translation() = Vec3(470 + 2.0 * i, 498.4, 1.8);
    d.gt.push_back(p);
  }
  writeTum(d.dir / drive_files::kGroundTruth, d.gt);
  d.lidar.preset = "vlp16";
  d.lidar.spec = resolveLidarSpec(d.lidar);
  writeFileAtomic(d.dir / drive_files::kSensor, config::dumpYaml(d.lidar));
  d.wf.net = fs::absolute(d.net).string();
  d.wf.seed = 77;
  writeFileAtomic(d.dir / drive_files::kWorld, config::dumpYaml(d.wf));
  d.traffic.resize(3);
  VehicleBox car;
  car.id = "bg1";
  car.x = 482, car.y = 498.4, car.z = 0, car.heading_deg = 0;
  d.traffic[1].push_back(car);
  writeTrafficCsv(d.dir / kTrafficFile, d.traffic, {0.0, 0.1, 0.2});
  return d;
}

TEST(SimulatedScanSource, RegeneratesExactlyWhatTheLidarProduces) {
  const DriveDir d = makeDrive("exact");
  ASSERT_TRUE(fs::exists(d.net)) << d.net << " missing";
  const SimulatedScanSource src(d.dir);
  ASSERT_EQ(src.size(), 3u);
  EXPECT_DOUBLE_EQ(src.time(2), 0.2);
  EXPECT_EQ(src.spec().channels, 16);
  const World w = World::build(SumoNet::read(d.net), d.wf.world, d.wf.seed);
  const Lidar lidar(d.lidar, d.wf.seed);
  for (std::size_t i = 0; i < 3; ++i) {
    const Scan a = src.scan(i);
    // the sweep ends where the sensor is 0.1 s later (the last pose: held)
    const Pose3 end = i + 1 < 3 ? d.gt[i + 1].T_world_body : d.gt[i].T_world_body;
    const Scan b = lidar.scan(w, d.gt[i].T_world_body, end, d.traffic[i], i, d.gt[i].t);
    ASSERT_EQ(a.points.size(), b.points.size());
    ASSERT_TRUE(a.has_point_times);
    for (std::size_t k = 0; k < a.points.size(); ++k) {
      ASSERT_EQ(a.points[k].x, b.points[k].x);
      ASSERT_EQ(a.points[k].z, b.points[k].z);
      ASSERT_EQ(a.points[k].ring, b.points[k].ring);
      ASSERT_EQ(a.points[k].dt, b.points[k].dt);
    }
    EXPECT_DOUBLE_EQ(a.t, d.gt[i].t);
  }
  // the traffic box of frame 1 (centre 10 m ahead, 4.5 m long) shows up at x ~ 7.75
  std::size_t car = 0;
  for (const auto& p : src.scan(1).points)
    if (std::abs(p.x - 7.75) < 0.1 && std::abs(p.y) < 0.9) ++car;
  EXPECT_GT(car, 5u);
  EXPECT_THROW(src.scan(3), std::out_of_range);
}

TEST(SimulatedScanSource, MissingFilesAreNamed) {
  EXPECT_THROW(SimulatedScanSource("/nonexistent/drive"), std::runtime_error);
  const DriveDir d = makeDrive("missing");
  fs::remove(d.dir / drive_files::kSensor);
  try {
    SimulatedScanSource src(d.dir);
    FAIL() << "no exception";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("sensor.yaml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamroute::simulate
