// Scan-to-scan + scan-to-map on synthetic scans with a known rigid motion.
#include <gtest/gtest.h>

#include <numbers>

#include "SyntheticScene.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate {
namespace {

double angleDeg(const Pose3& T) {
  return Eigen::AngleAxisd(T.rotation()).angle() * 180.0 / std::numbers::pi;
}

TEST(Odometry, RecoversKnownRigidMotion) {
  const test::Scene scene = test::cityScene(100.0);
  const LidarSpec spec;  // 64 x 1800, the paper's sensor
  const Pose3 T1 = test::poseXYZYaw(-10.0, 0.5, 1.8, 0.02);
  Pose3 delta = test::poseXYZYaw(0.8, 0.15, 0.02, 2.0 * std::numbers::pi / 180.0);
  delta.linear() =
      delta.linear() * Eigen::AngleAxisd(0.004, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Pose3 T2 = T1 * delta;
  Config cfg;
  cfg.loop.enabled = false;
  LidarSlam slam(cfg, spec, T1);
  EXPECT_EQ(slam.addScan(test::scanScene(scene, T1, spec, 0.0)), FrameStatus::Ok);
  EXPECT_NE(slam.addScan(test::scanScene(scene, T2, spec, 0.1)), FrameStatus::Missing);
  const Pose3 err = T2.inverse() * slam.currentPose();
  EXPECT_LT(err.translation().norm(), 0.01) << err.translation().transpose();
  EXPECT_LT(angleDeg(err), 0.1);
}

}  // namespace
}  // namespace slamroute::evaluate
