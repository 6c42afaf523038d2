// The fleet merge on a synthetic city block: two vehicles drive the same loop from opposite
// corners; closures between them are found by place and ICP, and the pose graph puts the second
// vehicle's offset estimate back onto the first's frame; a vehicle on another level (a deck over
// the street) closes none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SyntheticScene.hpp"
#include "fleet/FleetInternal.hpp"
#include "slamroute/evaluate/Fleet.hpp"

namespace {
using namespace slamroute;
using namespace slamroute::evaluate;

Trajectory moved(const Trajectory& t, const Pose3& T) {
  Trajectory out = t;
  for (auto& p : out) p.T_world_body = T * p.T_world_body;
  return out;
}

TEST(FleetMerge, ClosuresFromGroundTruthLeaveExactEstimatesUnchanged) {
  const test::LoopScanSource a(0.0, 200), b(150.0, 200);
  std::vector<FleetVehicleInput> vs = {{"a", {}, a.groundTruth(), a.groundTruth(), &a},
                                       {"b", {}, b.groundTruth(), b.groundTruth(), &b}};
  const FleetMergeOptions opt;
  std::vector<std::vector<FleetKeyframe>> kfs = {fleetKeyframes(vs[0].estimate, a, 10.0),
                                                 fleetKeyframes(vs[1].estimate, b, 10.0)};
  // every keyframe of b closed to a's keyframe nearest it, with the true relative pose
  std::vector<FleetClosure> closures;
  for (std::size_t k = 0; k < kfs[1].size(); ++k) {
    std::size_t best = 0;
    for (std::size_t j = 0; j < kfs[0].size(); ++j)
      if ((kfs[0][j].pose.translation() - kfs[1][k].pose.translation()).norm() <
          (kfs[0][best].pose.translation() - kfs[1][k].pose.translation()).norm())
        best = j;
    closures.push_back({0, 1, static_cast<int>(best), static_cast<int>(k), kfs[0][best].t,
                        kfs[1][k].t, kfs[0][best].pose.inverse() * kfs[1][k].pose, 0.0});
  }
  const auto merged = mergeFleetTrajectories(vs, kfs, closures, Config{}, opt);
  for (std::size_t v = 0; v < 2; ++v)
    for (std::size_t i = 0; i < merged[v].size(); ++i) {
      const Pose3 d = vs[v].ground_truth[i].T_world_body.inverse() * merged[v][i].T_world_body;
      ASSERT_LT(d.translation().norm(), 1e-4) << v << " " << i;
      ASSERT_LT(Eigen::AngleAxisd(d.rotation()).angle(), 1e-5) << v << " " << i;
    }
}

/// Per keyframe of vehicle 1, a closure to vehicle 0's keyframe nearest it in the truth, with
/// the true relative pose (ground truths sampled like the scans, every 0.1 s).
std::vector<FleetClosure> trueClosures(const std::vector<FleetVehicleInput>& vs,
                                       const std::vector<std::vector<FleetKeyframe>>& kfs) {
  const auto truth = [&](int v, const FleetKeyframe& kf) {
    return vs[static_cast<std::size_t>(v)].ground_truth[kf.scan].T_world_body;
  };
  std::vector<FleetClosure> out;
  for (std::size_t k = 0; k < kfs[1].size(); ++k) {
    std::size_t best = 0;
    const Vec3 at = truth(1, kfs[1][k]).translation();
    for (std::size_t j = 0; j < kfs[0].size(); ++j)
      if ((truth(0, kfs[0][j]).translation() - at).norm() <
          (truth(0, kfs[0][best]).translation() - at).norm())
        best = j;
    out.push_back({0, 1, static_cast<int>(best), static_cast<int>(k), kfs[0][best].t, kfs[1][k].t,
                   truth(0, kfs[0][best]).inverse() * truth(1, kfs[1][k]), 0.0, 1.0});
  }
  return out;
}

/// Largest position error of the merged trajectories against the vehicles' ground truths [m].
double largestError(const std::vector<Trajectory>& merged,
                    const std::vector<FleetVehicleInput>& vs) {
  double worst = 0.0;
  for (std::size_t v = 0; v < merged.size(); ++v)
    for (std::size_t i = 0; i < merged[v].size(); ++i)
      worst = std::max(worst, (merged[v][i].T_world_body.translation() -
                               vs[v].ground_truth[i].T_world_body.translation())
                                  .norm());
  return worst;
}

TEST(FleetMerge, AnOffsetVehicleWithTrueClosuresMergesToTheTruthAndAWrongClosureIsRefused) {
  const test::LoopScanSource a(0.0, 200), b(150.0, 200);
  // b's own estimate is exact in shape but starts 2.5 m and 4 degrees off
  const Pose3 off = test::poseXYZYaw(2.0, -1.5, 0.0, 4.0 * M_PI / 180.0);
  std::vector<FleetVehicleInput> vs = {{"a", {}, a.groundTruth(), a.groundTruth(), &a},
                                       {"b", {}, moved(b.groundTruth(), off), b.groundTruth(), &b}};
  const FleetMergeOptions opt;
  const std::vector<std::vector<FleetKeyframe>> kfs = {fleetKeyframes(vs[0].estimate, a, 10.0),
                                                       fleetKeyframes(vs[1].estimate, b, 10.0)};
  std::vector<FleetClosure> closures = trueClosures(vs, kfs);
  ASSERT_GE(closures.size(), 10u);
  // One look-alike place: ICP slid 3 m along the street (what a corridor allows).
  FleetClosure wrong = closures[closures.size() / 2];
  wrong.T_a_b.translation() += wrong.T_a_b.rotation() * Vec3(3.0, 0.0, 0.0);
  closures.push_back(wrong);
  const std::vector<FleetClosure> kept = consistentClosures(closures, kfs, opt);
  ASSERT_EQ(kept.size(), closures.size() - 1);
  for (const auto& c : kept)
    EXPECT_GT((c.T_a_b.translation() - wrong.T_a_b.translation()).norm(), 1.0);
  // With the true closures b follows them, not its offset start: both on the truth.
  EXPECT_LT(largestError(mergeFleetTrajectories(vs, kfs, kept, Config{}, opt), vs), 1e-3);
  // Given to the pose graph all the same, the wrong closure pulls the map by little: its Cauchy
  // loss weighs a closure 30 sigmas off the rest by about 1/100.
  EXPECT_LT(largestError(mergeFleetTrajectories(vs, kfs, closures, Config{}, opt), vs), 0.1);
}

TEST(FleetMerge, FindsClosuresBetweenVehiclesAndJoinsAnOffsetEstimate) {
  const test::LoopScanSource a(0.0, 200), b(150.0, 200);
  // b's estimate is its truth moved by 2.5 m and 4 degrees: a start pose known only roughly
  Pose3 off = test::poseXYZYaw(2.0, -1.5, 0.0, 4.0 * M_PI / 180.0);
  std::vector<FleetVehicleInput> vs = {{"a", {}, a.groundTruth(), a.groundTruth(), &a},
                                       {"b", {}, moved(b.groundTruth(), off), b.groundTruth(), &b}};
  FleetMergeOptions opt;
  const FleetResult r = mergeFleet(vs, Config{}, opt);
  ASSERT_GE(r.closures.size(), 5u);
  for (const auto& c : r.closures) {
    const Pose3 truth =
        a.groundTruth()[static_cast<std::size_t>(std::lround(c.t_a / 0.1))].T_world_body.inverse() *
        b.groundTruth()[static_cast<std::size_t>(std::lround(c.t_b / 0.1))].T_world_body;
    EXPECT_LT((c.T_a_b.translation() - truth.translation()).norm(), 0.3);
  }
  // Vehicle a alone is exact; under one common alignment b's offset shows, and the merge
  // removes it: both end within a few centimetres of the truth.
  EXPECT_LT(r.vehicles[0].own_ate_rmse_m, 1e-6);
  EXPECT_LT(r.vehicles[1].own_ate_rmse_m, 1e-6);
  EXPECT_GT(r.common_ate_before_m, 0.8);
  EXPECT_LT(r.common_ate_after_m, 0.15);
  EXPECT_LT(r.vehicles[1].common_ate_after_m, 0.15);
}

// b's estimate 6 m above a's (a deck over the street a drives): no closures between the two
// levels with the default loop.max_height_gap_m; with a gap that lets it, the same ones as level.
TEST(FleetMerge, KeyframesOnAnotherLevelAreNoCandidates) {
  const test::LoopScanSource a(0.0, 200), b(150.0, 200);
  const Pose3 up = test::poseXYZYaw(0.0, 0.0, 6.0, 0.0);
  std::vector<FleetVehicleInput> vs = {{"a", {}, a.groundTruth(), a.groundTruth(), &a},
                                       {"b", {}, moved(b.groundTruth(), up), b.groundTruth(), &b}};
  EXPECT_TRUE(mergeFleet(vs, Config{}, FleetMergeOptions{}).closures.empty());
  Config wide;
  wide.loop.max_height_gap_m = 10.0;
  EXPECT_GE(mergeFleet(vs, wide, FleetMergeOptions{}).closures.size(), 5u);
}

TEST(FleetMerge, CommonAteOfTwoEqualOffsetsIsZeroAndOfOneOffsetIsShared) {
  const test::LoopScanSource a(0.0, 200), b(150.0, 200);
  const Pose3 shift = test::poseXYZYaw(3.0, 0.0, 0.0, 0.0);
  const auto same = commonAteRmse({moved(a.groundTruth(), shift), moved(b.groundTruth(), shift)},
                                  {a.groundTruth(), b.groundTruth()}, 0.02);
  EXPECT_LT(same.back(), 1e-6);
  const auto one = commonAteRmse({a.groundTruth(), moved(b.groundTruth(), shift)},
                                 {a.groundTruth(), b.groundTruth()}, 0.02);
  // one vehicle 3 m off: no single alignment fits both, so both carry part of the error
  EXPECT_GT(one[0], 0.5);
  EXPECT_GT(one[1], 0.5);
  EXPECT_LT(one.back(), 3.0);
}

}  // namespace
