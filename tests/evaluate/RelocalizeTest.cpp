// A heading jump of ~95 deg within one scan (SUMO junction internal lanes do this in simulated
// drives): local registration cannot converge from the constant-velocity prediction, the yaw
// search of the relocalisation must recover the pose.
#include <gtest/gtest.h>

#include <numbers>

#include "SyntheticScene.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double runJump(bool relocalize, Pose3& err) {
  const test::Scene scene = test::cityScene(100.0);
  const LidarSpec spec;
  Config cfg;
  cfg.loop.enabled = false;
  cfg.relocalise.enabled = relocalize;
  std::vector<Pose3> poses;
  for (int i = 0; i < 4; ++i) poses.push_back(test::poseXYZYaw(-10.0 + 0.8 * i, 0.3, 1.8, 0.0));
  poses.push_back(test::poseXYZYaw(-10.0 + 0.8 * 3 + 0.3, 0.3, 1.8, 95.0 * kDeg));  // the jump
  poses.push_back(test::poseXYZYaw(-10.0 + 0.8 * 3 + 0.3, 0.3 + 0.8, 1.8, 95.0 * kDeg));
  LidarSlam slam(cfg, spec, poses[0]);
  for (std::size_t i = 0; i < poses.size(); ++i)
    slam.addScan(test::scanScene(scene, poses[i], spec, 0.1 * static_cast<double>(i)));
  err = poses.back().inverse() * slam.currentPose();
  return Eigen::AngleAxisd(err.rotation()).angle() / kDeg;
}

TEST(Relocalize, RecoversHeadingJump) {
  Pose3 err;
  const double deg = runJump(true, err);
  EXPECT_LT(err.translation().norm(), 0.05) << err.translation().transpose();
  EXPECT_LT(deg, 0.3);
}

TEST(Relocalize, WithoutItTheHeadingIsLost) {
  Pose3 err;
  EXPECT_GT(runJump(false, err), 20.0);
}

}  // namespace
}  // namespace slamroute::evaluate
