// KITTI odometry sequence folders: scans from velodyne/ at the times of times.txt beside it, and
// poses.txt's camera poses brought into the LiDAR frame by calib.txt's Tr (known answer).
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

#include "TestTmp.hpp"
#include "slamroute/core/KittiSequence.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

Pose3 pose(double yaw, const Vec3& t) {
  Pose3 T = Pose3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
  T.translation() = t;
  return T;
}

void writeRow(std::ostream& os, const Pose3& T) {
  os.precision(17);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) os << T.matrix()(r, c) << (r == 2 && c == 3 ? "\n" : " ");
}

TEST(KittiSequence, GroundTruthComesIntoTheLidarFrameAtTheScansTimes) {
  const fs::path seq = test::testTmp() / "seq";
  fs::create_directories(seq / "velodyne");
  Scan s;
  s.points = {{1.0f, 2.0f, 0.5f, 0.3f}};
  writeKittiScan(seq / "velodyne/000000.bin", s);
  writeKittiScan(seq / "velodyne/000001.bin", s);
  std::ofstream(seq / "times.txt") << "1.000000e+00\n1.100000e+00\n";
  // camera: x right, y down, z forward; the LiDAR 0.3 m behind and 0.1 m above it
  Pose3 Tr = Pose3::Identity();
  Tr.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  Tr.translation() = Tr.linear() * Vec3(-0.3, 0.0, 0.1);
  std::ofstream calib(seq / "calib.txt");
  calib << "P0: 1 0 0 0 0 1 0 0 0 0 1 0\nTr: ";
  writeRow(calib, Tr);
  calib.close();
  // In the LiDAR's frame the car drives 5 m forward (x) while turning 90 deg left.
  const Pose3 lidar1 = pose(std::numbers::pi / 2, Vec3(5, 0, 0));
  std::ofstream poses(seq / "poses.txt");
  writeRow(poses, Pose3::Identity());
  writeRow(poses, Tr * lidar1 * Tr.inverse());
  poses.close();

  const KittiSequence k = readKittiSequence(seq, lidarPreset("paper"));
  ASSERT_EQ(k.scans->size(), 2u);
  EXPECT_DOUBLE_EQ(k.scans->time(1), 1.1);
  EXPECT_FLOAT_EQ(k.scans->scan(1).points.at(0).y, 2.0f);
  ASSERT_EQ(k.ground_truth.size(), 2u);
  EXPECT_DOUBLE_EQ(k.ground_truth[1].t, 1.1);
  EXPECT_TRUE(k.ground_truth[0].T_world_body.isApprox(Pose3::Identity(), 1e-12));
  EXPECT_LT((k.ground_truth[1].T_world_body.translation() - Vec3(5, 0, 0)).norm(), 1e-12);
  EXPECT_TRUE(k.ground_truth[1].T_world_body.linear().isApprox(lidar1.linear(), 1e-12));
  EXPECT_TRUE(readKittiCalibTr(seq / "calib.txt").isApprox(Tr, 1e-12));

  fs::remove(seq / "poses.txt");  // ground truth is optional
  EXPECT_TRUE(readKittiSequence(seq, lidarPreset("paper")).ground_truth.empty());
}

}  // namespace
}  // namespace slamroute
