// The loop closer (evaluate/src/slam/LoopCloser) on a keyframe graph whose poses slipped in a
// U-turn: a revisit matched against that submap fits well but is refused, since the submap's
// sides disagree; on the same turn without the slip it closes with the true relative pose. And
// a revisit whose estimate lies a deck's height above the turn is no candidate for it.
#include <gtest/gtest.h>

#include <vector>

#include "UTurnScene.hpp"
#include "slam/KeyframeGraph.hpp"
#include "slam/LoopCloser.hpp"

namespace slamroute::evaluate {
namespace {

Cloud cloudOf(const Scan& s) {
  Cloud c;
  for (const auto& p : s.points) c.emplace_back(p.x, p.y, p.z);
  return c;
}

/// The U-turn of cityScene with the keyframes after the turn placed `slip_m` too far along +x
/// (the turn dead-reckoned on the wheels), then, 100 s later, a revisit driving north whose
/// estimate continues from those keyframes (the same slip) and lies `raise_m` higher. Its
/// closures.
slam::LoopStats revisitAfterASlip(double slip_m, const LoopConfig& loop, double raise_m = 0.0) {
  Config cfg;
  cfg.loop = loop;
  const test::Scene scene = test::cityScene();
  const LidarSpec spec = lidarPreset("vlp16");
  slam::KeyframeGraph g(cfg);
  slam::LoopCloser closer(cfg, 1.8);
  StageTimes times;
  std::vector<Pose3> kfs = test::uTurnInAStreet();
  kfs.push_back(test::uTurnRevisit());
  const int revisit = static_cast<int>(kfs.size()) - 1;
  for (int k = 0; k <= revisit; ++k) {
    const Pose3& truth = kfs[static_cast<std::size_t>(k)];
    const Cloud c = cloudOf(test::scanScene(scene, truth, spec, 0, 0.02, 10 + k));
    Pose3 estimate = truth;
    if (k > test::kUTurnKeyframe) estimate.translation().x() += slip_m;
    if (k == revisit) estimate.translation().z() += raise_m;
    g.add(k == revisit ? 100.0 : k, k, estimate, c, c, c);
    closer.tryClose(g, times);
  }
  return closer.stats();
}

/// How far a closure's relative pose is from the truth's (the turning keyframe to the revisit).
double relativePoseError(const LoopClosure& l) {
  const std::vector<Pose3> kfs = test::uTurnInAStreet();
  const Pose3 truth = kfs[test::kUTurnKeyframe].inverse() * test::uTurnRevisit();
  return (l.T_old_new.translation() - truth.translation()).norm();
}

TEST(LoopCloser, ARevisitOfARigidSubmapClosesWithTheTrueRelativePose) {
  const slam::LoopStats s = revisitAfterASlip(0.0, LoopConfig{});
  ASSERT_EQ(s.loops.size(), 1u);
  EXPECT_EQ(s.loops[0].from_keyframe, test::kUTurnKeyframe);
  EXPECT_LT(relativePoseError(s.loops[0]), 0.1);
}

TEST(LoopCloser, ARevisitOfASubmapThatSlippedInTheTurnIsRefused) {
  // The check off: the closure fits, and its relative pose is off by the slip.
  LoopConfig off_cfg;
  off_cfg.submap_agreement_m = -1.0;
  const slam::LoopStats off = revisitAfterASlip(1.2, off_cfg);
  ASSERT_EQ(off.loops.size(), 1u);
  EXPECT_EQ(off.loops[0].from_keyframe, test::kUTurnKeyframe);
  EXPECT_NEAR(relativePoseError(off.loops[0]), 1.2, 0.1);
  // On (the default): refused.
  const slam::LoopStats on = revisitAfterASlip(1.2, LoopConfig{});
  EXPECT_EQ(on.loops.size(), 0u);
  EXPECT_EQ(on.ambiguous, 1);
}

struct LevelCase {
  double raise_m, max_height_gap_m;
  int candidates;
};

class LoopCloserLevel : public ::testing::TestWithParam<LevelCase> {};

// The revisit's estimate 6 m above the turn (a deck over the street; 7.8 m from the turning
// keyframe in 3-D, so the search radius is 10 m here) is no candidate with the default gap; the
// height a drive drifts between closures (1 m, more than it does) still is, and so is 6 m with
// a gap that lets it.
TEST_P(LoopCloserLevel, OnlyKeyframesOnTheEstimatesLevelAreCandidates) {
  const LevelCase c = GetParam();
  LoopConfig loop;
  loop.radius_m = 10.0;
  loop.max_height_gap_m = c.max_height_gap_m;
  const slam::LoopStats s = revisitAfterASlip(0.0, loop, c.raise_m);
  EXPECT_EQ(s.candidates, c.candidates);
  if (c.candidates == 0) EXPECT_TRUE(s.loops.empty());
}

INSTANTIATE_TEST_SUITE_P(Heights, LoopCloserLevel,
                         ::testing::Values(LevelCase{0.0, 2.0, 1}, LevelCase{1.0, 2.0, 1},
                                           LevelCase{6.0, 2.0, 0}, LevelCase{6.0, 10.0, 1}));

}  // namespace
}  // namespace slamroute::evaluate
