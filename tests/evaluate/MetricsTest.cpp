// ATE / RPE / per-edge metrics on trajectories with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {
namespace {

Pose3 pose(double x, double y, double z, double yaw) {
  Pose3 T = Pose3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
  T.translation() = Vec3(x, y, z);
  return T;
}

/// A winding 3D path, 10 Hz, about 1 m per pose.
Trajectory winding(int n) {
  Trajectory t;
  for (int i = 0; i < n; ++i) {
    const double s = i * 1.0;
    t.push_back({0.1 * i, pose(s, 20.0 * std::sin(s / 50.0), 0.5 * std::sin(s / 30.0),
                               std::cos(s / 50.0) * 0.4)});
  }
  return t;
}

TEST(Metrics, IdenticalTrajectoryHasZeroError) {
  const Trajectory gt = winding(1200);
  const TrajectoryMetrics m = compareTrajectories(gt, gt, {});
  EXPECT_EQ(m.pairs.size(), gt.size());
  EXPECT_NEAR(m.ate.rmse_m, 0.0, 1e-9);
  EXPECT_NEAR(m.ate.max_m, 0.0, 1e-9);
  EXPECT_NEAR(m.rpe_kitti.trans_pct, 0.0, 1e-9);
  EXPECT_GT(m.rpe_kitti.segments, 0);
  EXPECT_GT(m.route_length_m, 1199.0);
  EXPECT_NEAR(m.end_drift_pct, 0.0, 1e-9);
}

TEST(Metrics, RigidlyMovedCopyHasZeroErrorAfterAlignment) {
  const Trajectory gt = winding(600);
  Pose3 M = pose(120.0, -35.0, 4.0, 0.7);
  M.linear() = M.linear() * Eigen::AngleAxisd(0.1, Vec3::UnitX()).toRotationMatrix();
  Trajectory est = gt;
  for (auto& p : est) p.T_world_body = M * p.T_world_body;
  const TrajectoryMetrics m = compareTrajectories(est, gt, {});
  EXPECT_NEAR(m.ate.rmse_m, 0.0, 1e-6);
  EXPECT_NEAR(m.ate.max_m, 0.0, 1e-6);
  EXPECT_TRUE(m.T_gt_est.isApprox(M.inverse(), 1e-6));
  EXPECT_NEAR(m.rpe_kitti.trans_pct, 0.0, 1e-6);  // RPE is frame-independent anyway
}

TEST(Metrics, ShiftedCopyHasKnownErrorWithoutMatchingTimes) {
  // Timestamps offset by 1 s, beyond the tolerance: nothing associates -> clear error.
  const Trajectory gt = winding(50);
  Trajectory est = gt;
  for (auto& p : est) p.t += 1000.0;
  EXPECT_THROW(compareTrajectories(est, gt, {}), std::invalid_argument);
}

TEST(Metrics, ConstantDriftGivesThatRpe) {
  // Straight 1 km line; the estimate stretches distances by 1 % -> 1 % translational drift.
  Trajectory gt, est;
  for (int i = 0; i <= 1000; ++i) {
    gt.push_back({0.1 * i, pose(i * 1.0, 0, 0, 0)});
    est.push_back({0.1 * i, pose(i * 1.01, 0, 0, 0)});
  }
  MetricsOptions o;
  o.segment_m = 50.0;
  const TrajectoryMetrics m = compareTrajectories(est, gt, o);
  EXPECT_NEAR(m.rpe_kitti.trans_pct, 1.0, 1e-9);
  EXPECT_NEAR(m.rpe_kitti.rot_deg_per_m, 0.0, 1e-12);
  EXPECT_NEAR(m.rpe_segment.trans_pct, 1.0, 1e-9);
  EXPECT_NEAR(m.end_drift_pct, 1.0, 1e-9);  // 1010 m estimated for 1000 m driven
  // 100 m segments start every 10 frames: 91 starts for 100 m, ..., 21 for 800 m
  int expected = 0;
  for (int len = 100; len <= 800; len += 100) expected += (1000 - len) / 10 + 1;
  EXPECT_EQ(m.rpe_kitti.segments, expected);
}

TEST(Metrics, ConstantYawRateDriftGivesThatRotationalRpe) {
  // The estimate turns 0.01 deg per metre more than the ground truth (a circle vs a line).
  Trajectory gt, est;
  const double k = 0.01 * std::numbers::pi / 180.0;  // rad per metre
  Pose3 T = Pose3::Identity();
  for (int i = 0; i <= 400; ++i) {
    gt.push_back({0.1 * i, pose(i, 0, 0, 0)});
    est.push_back({0.1 * i, T});
    T = T * pose(1.0, 0, 0, k);
  }
  const TrajectoryMetrics m = compareTrajectories(est, gt, {});
  EXPECT_NEAR(m.rpe_kitti.rot_deg_per_m, 0.01, 1e-9);
  // The estimate's 400 steps of 1 m, the j-th turned by j k, end at the sum of (cos jk, sin jk):
  // sin(200 k) / sin(k / 2) along the direction 199.5 k; the truth ends at (400, 0).
  const double chord = std::sin(200.0 * k) / std::sin(0.5 * k);
  const Eigen::Vector2d end_off(chord * std::cos(199.5 * k) - 400.0, chord * std::sin(199.5 * k));
  EXPECT_NEAR(m.end_drift_pct, 100.0 * end_off.norm() / 400.0, 1e-9);
}

TEST(Metrics, AssociationUsesNearestTimestamp) {
  Trajectory gt, est;
  for (int i = 0; i < 10; ++i) gt.push_back({0.1 * i, pose(i, 0, 0, 0)});
  est.push_back({0.305, pose(3, 0, 0, 0)});  // within 0.02 s of 0.3
  est.push_back({0.55, pose(5, 0, 0, 0)});   // 0.05 s from both neighbours: dropped
  est.push_back({0.701, pose(7, 0, 0, 0)});
  const auto pairs = associate(est, gt, 0.02);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_NEAR(pairs[0].gt.translation().x(), 3.0, 1e-12);
  EXPECT_NEAR(pairs[1].gt.translation().x(), 7.0, 1e-12);
}

TEST(Metrics, PerEdgeDriftSeparatesStreets) {
  // Edge "a" (first 100 m) is perfect, edge "b" (next 100 m) stretches by 2 %.
  Trajectory gt, est;
  std::vector<PoseEdge> edges;
  double xe = 0;
  for (int i = 0; i <= 200; ++i) {
    gt.push_back({0.1 * i, pose(i, 0, 0, 0)});
    est.push_back({0.1 * i, pose(xe, 0, 0, 0)});
    xe += i < 100 ? 1.0 : 1.02;
    edges.push_back({i, 0.1 * i, i <= 100 ? "a" : "b", 0.0});
  }
  // without alignment effects on drift: drift is relative
  const TrajectoryMetrics m = compareTrajectories(est, gt, {});
  const auto rows = perEdgeErrors(m, edges, 0.02);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].edge, "a");
  EXPECT_NEAR(rows[0].drift_pct, 0.0, 1e-9);
  EXPECT_EQ(rows[1].edge, "b");
  EXPECT_NEAR(rows[1].drift_pct, 2.0, 1e-6);
  EXPECT_NEAR(rows[0].window_drift_pct, 0.0, 1e-9);
  EXPECT_NEAR(rows[1].window_drift_pct, 2.0, 1e-6);  // every window of a stretch stretches
  EXPECT_EQ(rows[0].poses + rows[1].poses, 201);
  EXPECT_EQ(rows[1].visits, 1);
}

TEST(Metrics, AHeadingErrorAtAVisitsFirstPoseIsOneWindowOfFiftyOne) {
  // 100 m straight, exact but for the first pose, turned by 2 deg where it stands (a heading
  // still off from the turn onto the street). End to end: the 100 m chord seen turned by 2 deg,
  // 2 sin(1 deg) of it. Windows of 50 m start at poses 0..50, and only the first is off.
  const double turn = 2.0 * std::numbers::pi / 180.0;
  Trajectory gt, est;
  std::vector<PoseEdge> edges;
  for (int i = 0; i <= 100; ++i) {
    gt.push_back({0.1 * i, pose(i, 0, 0, 0)});
    est.push_back({0.1 * i, pose(i, 0, 0, i == 0 ? turn : 0.0)});
    edges.push_back({i, 0.1 * i, "a", 0.0});
  }
  const TrajectoryMetrics m = compareTrajectories(est, gt, {});
  const auto rows = perEdgeErrors(m, edges, 0.02);
  ASSERT_EQ(rows.size(), 1u);
  const double end_to_end = 100.0 * 2.0 * std::sin(turn / 2);
  EXPECT_NEAR(rows[0].drift_pct, end_to_end, 1e-9);
  EXPECT_NEAR(rows[0].window_drift_pct, end_to_end / 51, 1e-9);
}

}  // namespace
}  // namespace slamroute::evaluate
