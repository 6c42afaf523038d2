// The keyframe graph and the loop closer of the SLAM (evaluate/src/slam/) on known geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "SyntheticScene.hpp"
#include "slam/KeyframeGraph.hpp"
#include "slam/LoopCloser.hpp"

namespace slamroute::evaluate {
namespace {

Pose3 at(double x, double y) {
  Pose3 T = Pose3::Identity();
  T.translation() = Vec3(x, y, 1.8);
  return T;
}

Cloud cloudOf(const Scan& s) {
  Cloud c;
  for (const auto& p : s.points) c.emplace_back(p.x, p.y, p.z);
  return c;
}

test::Scene townBlock() {
  test::Scene scene;
  scene.boxes = {{{8, 4, 0}, {20, 9, 12}},   {{-15, 6, 0}, {-4, 14, 7}},
                 {{5, -12, 0}, {9, -6, 20}}, {{-9, -10, 0}, {-7, -8, 4}},
                 {{25, -3, 0}, {26, 3, 9}},  {{-30, -20, 0}, {-18, -14, 15}}};
  return scene;
}

/// A loop closer with the default config on an empty keyframe graph, in the town block seen by a
/// VLP-16 mounted 1.8 m above the road.
struct LoopRig {
  Config cfg;
  test::Scene scene = townBlock();
  LidarSpec spec = lidarPreset("vlp16");
  slam::KeyframeGraph g{cfg};
  slam::LoopCloser closer{cfg, 1.8};
  StageTimes times;
};

TEST(KeyframeGraph, OdometryEdgesChainTheKeyframesAndALoopPullsThemBack) {
  Config cfg;
  cfg.mapping.local_map_keyframes = 2;
  slam::KeyframeGraph g(cfg);
  const Cloud some = {{1, 0, 0}, {0, 1, 0}};
  for (int k = 0; k < 4; ++k) g.add(10.0 * k, k, at(10.0 * k, 0.0), some, some, some);
  EXPECT_EQ(g.size(), 4u);
  EXPECT_NEAR(g.drivenSinceLoop(), 30.0, 1e-9);
  EXPECT_TRUE(g.at(1).edges.empty());  // beyond the local map's reach: features freed
  EXPECT_FALSE(g.at(3).edges.empty());
  // The loop says keyframe 3 sits 27 m from keyframe 0, not 30: the graph spreads the 3 m.
  PoseGraphEdge loop;
  loop.from = 0;
  loop.to = 3;
  loop.T_from_to = at(27.0, 0.0);
  loop.T_from_to.translation().z() = 0;
  loop.sigma_m = 0.01;
  loop.sigma_rad = 0.001;
  g.closeLoop(loop);
  EXPECT_NEAR(g.at(3).T_world.translation().x(), 27.0, 0.05);
  EXPECT_NEAR(g.at(0).T_world.translation().x(), 0.0, 1e-9);  // the first keyframe is held
  EXPECT_EQ(g.drivenSinceLoop(), 0.0);
}

/// Keyframes 10 m apart along x, level, the IMU reading `imu_deg` nose down at each; optimised.
std::vector<double> pitchesDegAfterOptimising(double imu_sigma_deg, double imu_deg) {
  constexpr double deg = std::numbers::pi / 180.0;
  Config cfg;
  cfg.loop.graph_imu_pitch_sigma_deg = imu_sigma_deg;
  cfg.loop.graph_pitch_bias_sigma_deg = 0.0;  // the bias held at 0: the IMU is taken as read
  slam::KeyframeGraph g(cfg);
  const Cloud some = {{1, 0, 0}, {0, 1, 0}};
  for (int k = 0; k < 5; ++k)
    g.add(10.0 * k, k, at(10.0 * k, 0.0), some, some, some, imu_deg * deg);
  g.optimize();
  std::vector<double> out;
  for (std::size_t k = 0; k < g.size(); ++k)
    out.push_back(std::asin(-g.at(k).T_world.linear()(2, 0)) / deg);
  return out;
}

TEST(KeyframeGraph, TheIMUPitchFactorsTiltTheKeyframesOnlyWhenAsked) {
  for (double p : pitchesDegAfterOptimising(0.0, 0.3)) EXPECT_NEAR(p, 0.0, 1e-9);
  const std::vector<double> tied = pitchesDegAfterOptimising(0.1, 0.3);
  EXPECT_NEAR(tied[0], 0.0, 1e-9);  // the first keyframe is held
  for (std::size_t k = 1; k < tied.size(); ++k) EXPECT_NEAR(tied[k], 0.3, 0.1) << k;
}

TEST(LoopCloser, ARevisitWithDriftClosesAndCorrectsIt) {
  LoopRig rig;
  auto& [cfg, scene, spec, g, closer, times] = rig;
  // Out along the street and back: the last keyframe is at the first place, estimated 0.6 m off.
  const double xs[] = {0, 10, 20, 30, 0};
  for (int k = 0; k < 5; ++k) {
    const Cloud c = cloudOf(test::scanScene(scene, at(xs[k], 0), spec));
    const Pose3 estimate = k == 4 ? at(0.6, 0.2) : at(xs[k], 0);
    g.add(20.0 * k, k, estimate, c, c, c);
    EXPECT_EQ(closer.tryClose(g, times), k == 4) << "keyframe " << k;
  }
  ASSERT_EQ(closer.stats().loops.size(), 1u);
  const LoopClosure& l = closer.stats().loops.front();
  EXPECT_EQ(l.from_keyframe, 0);
  EXPECT_EQ(l.to_keyframe, 4);
  EXPECT_NEAR(l.correction_m, std::hypot(0.6, 0.2), 0.1);
  EXPECT_LT(l.T_old_new.translation().norm(), 0.1);  // the measured relative pose: same place
  EXPECT_LT((g.back().T_world.translation() - at(0, 0).translation()).norm(), 0.35);
}

/// A revisit 0.6 m off along a street between two long plain walls (a bridge deck between
/// parapets), with the restart and correlative checks off so that only the conditioning decides.
int corridorClosures(double min_conditioning) {
  Config cfg;
  cfg.loop.ambiguity_along_m.clear();
  cfg.loop.ambiguity_across_m.clear();
  cfg.loop.correlative = false;
  cfg.loop.min_horizontal_conditioning = min_conditioning;
  test::Scene corridor;
  corridor.boxes = {{{-200, 6, 0}, {200, 7, 3}}, {{-200, -7, 0}, {200, -6, 3}}};
  const LidarSpec spec = lidarPreset("vlp16");
  slam::KeyframeGraph g(cfg);
  slam::LoopCloser closer(cfg, 1.8);
  StageTimes times;
  const double xs[] = {0, 10, 20, 30, 0};
  for (int k = 0; k < 5; ++k) {
    const Cloud c = cloudOf(test::scanScene(corridor, at(xs[k], 0), spec));
    g.add(20.0 * k, k, k == 4 ? at(0.6, 0.0) : at(xs[k], 0), c, c, c);
    closer.tryClose(g, times);
  }
  return static_cast<int>(closer.stats().loops.size());
}

TEST(LoopCloser, ARevisitThatICPCannotPlaceAlongTheStreetIsRefused) {
  EXPECT_EQ(corridorClosures(LoopConfig{}.min_horizontal_conditioning), 0);
  EXPECT_EQ(corridorClosures(0.05), 0);
  EXPECT_EQ(corridorClosures(0.0), 1);  // the check off: ICP stays where it started, 0.6 m off
}

class PlaceSearch : public ::testing::TestWithParam<bool> {};

TEST_P(PlaceSearch, ThePlaceDescriptorFindsARevisitTheEstimateHasDriftedAwayFrom) {
  Config cfg;
  cfg.loop.place_gate_per_m = 0.5;  // a drift of 15 m in 60 m of path
  const test::Scene scene = townBlock();
  const LidarSpec spec = lidarPreset("vlp16");
  slam::KeyframeGraph g(cfg);
  slam::LoopCloser closer(cfg, 1.8);
  StageTimes times;
  // Out along the street and back; the last keyframe is 15 m off: no keyframe within 7 m of it.
  const double xs[] = {0, 10, 20, 30, 0};
  std::vector<Cloud> clouds;
  for (double x : xs) clouds.push_back(cloudOf(test::scanScene(scene, at(x, 0), spec)));
  const auto revisit = [&](slam::KeyframeGraph& graph, slam::LoopCloser& lc, int k) {
    graph.add(20.0 * k, k, k == 4 ? at(0, 15) : at(xs[k], 0), clouds[k], clouds[k], clouds[k]);
    lc.addPlace(graph, clouds[k]);
    return lc.tryClose(graph, times);
  };
  for (int k = 0; k < 5; ++k) EXPECT_EQ(revisit(g, closer, k), k == 4) << "keyframe " << k;
  ASSERT_EQ(closer.stats().loops.size(), 1u);
  EXPECT_TRUE(closer.stats().loops.front().by_place);
  EXPECT_NEAR(closer.stats().loops.front().correction_m, 15.0, 0.2);
  // Without the descriptor (switched off, or a run with wheel odometry, whose estimate stays
  // within radius_m of a true revisit) the same revisit is no candidate at all.
  const bool with_odometry = GetParam();
  if (!with_odometry) cfg.loop.place_recognition = false;
  slam::KeyframeGraph g2(cfg);
  slam::LoopCloser blind(cfg, 1.8);
  blind.setPlaceSearch(!with_odometry);
  for (int k = 0; k < 5; ++k) EXPECT_FALSE(revisit(g2, blind, k)) << "keyframe " << k;
}

INSTANTIATE_TEST_SUITE_P(OffOrWithOdometry, PlaceSearch, ::testing::Bool());

TEST(LoopCloser, NothingOldEnoughOrNearEnoughIsNoCandidate) {
  LoopRig rig;
  auto& [cfg, scene, spec, g, closer, times] = rig;
  const Cloud c = cloudOf(test::scanScene(scene, at(0, 0), spec));
  g.add(0.0, 0, at(0, 0), c, c, c);
  g.add(10.0, 1, at(0.5, 0), c, c, c);  // near, but only 10 s later
  EXPECT_FALSE(closer.tryClose(g, times));
  g.add(100.0, 2, at(40, 0), c, c, c);  // old enough, but 40 m away in the estimate
  EXPECT_FALSE(closer.tryClose(g, times));
  EXPECT_EQ(closer.stats().candidates, 0);
}

}  // namespace
}  // namespace slamroute::evaluate
