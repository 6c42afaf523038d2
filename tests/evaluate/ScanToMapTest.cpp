// The scan-to-map's registration options (evaluate/src/slam/ScanToMap): with wheel odometry the
// prior towards its prediction, mapping.iterations and mapping.edge_weight; without it
// mapping.iterations_without_odometry, mapping.edge_weight_without_odometry and, with
// odometry.velocity_prior_along_sigma_m set and a velocity, a prior along the heading only.
#include <gtest/gtest.h>

#include "slam/ScanToMap.hpp"

namespace slamroute::evaluate {
namespace {

TEST(ScanToMap, WithoutOdometryTheRegistrationHasItsOwnIterationsEdgeWeightAndPrior) {
  Config cfg;
  cfg.mapping.iterations = 7;
  cfg.mapping.iterations_without_odometry = 23;
  cfg.mapping.edge_weight = 0.2;
  cfg.mapping.edge_weight_without_odometry = 0.7;
  cfg.odometry.velocity_prior_along_sigma_m = 0.002;
  const slam::ScanToMap s2m(cfg);
  slam::MotionModel lidar_only(cfg, Pose3::Identity());
  slam::MotionModel wheels(cfg, Pose3::Identity());
  wheels.setOdometry(WheelOdometry({{0.0, 5.0, 0.0}, {10.0, 5.0, 0.0}}));
  const slam::Prediction step;
  const AlignOptions a = s2m.options(lidar_only, step);
  EXPECT_EQ(a.iterations, 23);
  EXPECT_DOUBLE_EQ(a.edge_weight, 0.7);
  EXPECT_FALSE((a.prior_weight.array() > 0).any());  // no velocity yet
  lidar_only.setInitialMotion(Pose3::Identity(), 0.1);
  const AlignOptions v = s2m.options(lidar_only, step);
  EXPECT_GT(v.prior_weight(3), 0.0);  // along the heading and in yaw only
  EXPECT_GT(v.prior_weight(2), 0.0);
  EXPECT_EQ((v.prior_weight.array() > 0).count(), 2);
  const AlignOptions b = s2m.options(wheels, step);
  EXPECT_EQ(b.iterations, 7);
  EXPECT_DOUBLE_EQ(b.edge_weight, 0.2);
  EXPECT_TRUE((b.prior_weight.array() > 0).any());
}

}  // namespace
}  // namespace slamroute::evaluate
