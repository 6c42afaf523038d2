// Degenerate input: empty, all-NaN, missing and feature-poor scans keep the pipeline going and
// are reported as unreliable.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "SyntheticScene.hpp"
#include "slamroute/evaluate/Evaluate.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate {
namespace {

/// Scans a moving sensor (1 m per scan along +x); index `missing` throws like a lost file.
class StreetSource : public ScanSource {
 public:
  StreetSource(test::Scene scene, int n, int missing)
      : scene_(std::move(scene)), n_(n), missing_(missing) {}
  std::size_t size() const override { return static_cast<std::size_t>(n_); }
  double time(std::size_t i) const override { return 0.1 * static_cast<double>(i); }
  Scan scan(std::size_t i) const override {
    if (static_cast<int>(i) == missing_) throw std::runtime_error("scans/000002.bin: cannot open");
    return test::scanScene(scene_, pose(i), test::coarseLidar(32), time(i));
  }
  LidarSpec spec() const override { return test::coarseLidar(32); }
  static Pose3 pose(std::size_t i) {
    return test::poseXYZYaw(-20.0 + 1.0 * static_cast<double>(i), 0.3, 1.8, 0.0);
  }

 private:
  test::Scene scene_;
  int n_, missing_;
};

TEST(Degenerate, EmptyAndNaNScansArePredicted) {
  const test::Scene scene = test::cityScene(80.0);
  Config cfg;
  cfg.loop.enabled = false;
  LidarSlam slam(cfg, test::coarseLidar(32), StreetSource::pose(0));
  StreetSource src(scene, 6, -1);
  EXPECT_EQ(slam.addScan(src.scan(0)), FrameStatus::Ok);
  EXPECT_EQ(slam.addScan(src.scan(1)), FrameStatus::Ok);
  Scan empty;
  empty.t = 0.2;
  EXPECT_EQ(slam.addScan(empty), FrameStatus::Empty);
  Scan nan;
  nan.t = 0.3;
  const float q = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 5000; ++i) nan.points.push_back({q, q, q, 0.0f, i % 32});
  EXPECT_EQ(slam.addScan(nan), FrameStatus::Invalid);
  EXPECT_NE(slam.addScan(src.scan(4)), FrameStatus::Missing);
  EXPECT_NE(slam.addScan(src.scan(5)), FrameStatus::Missing);
  const SlamResult r = slam.finish();
  ASSERT_EQ(r.trajectory.size(), 6u);
  // the constant-velocity prediction bridged the gap and registration recovered
  EXPECT_LT(
      (r.trajectory[5].T_world_body.translation() - StreetSource::pose(5).translation()).norm(),
      0.05);
  EXPECT_LT(
      (r.trajectory[2].T_world_body.translation() - StreetSource::pose(2).translation()).norm(),
      0.05);
  const auto rel = reliabilityJson(r);
  EXPECT_EQ(rel["unreliable_scans"], 2);
  EXPECT_EQ(rel["stretches"].size(), 1u);
  EXPECT_EQ(rel["stretches"][0]["first_scan"], 2);
  EXPECT_EQ(rel["stretches"][0]["last_scan"], 3);
  EXPECT_FALSE(rel["reliable"].get<bool>());
}

TEST(Degenerate, MissingScanFileIsSkipped) {
  StreetSource src(test::cityScene(80.0), 5, 2);
  Config cfg;
  cfg.input.scan_stride = 1;  // every scan: the test names scans by index
  cfg.loop.enabled = false;
  const SlamResult r = runSlam(src, cfg, StreetSource::pose(0));
  ASSERT_EQ(r.trajectory.size(), 5u);
  EXPECT_EQ(r.status[2], FrameStatus::Missing);
  EXPECT_LT(
      (r.trajectory[4].T_world_body.translation() - StreetSource::pose(4).translation()).norm(),
      0.05);
}

TEST(Degenerate, FeaturePoorSceneIsFlagged) {
  test::Scene flat;  // ground only: x, y and yaw are unobservable
  StreetSource src(flat, 4, -1);
  Config cfg;
  cfg.input.scan_stride = 1;
  cfg.loop.enabled = false;
  const SlamResult r = runSlam(src, cfg, StreetSource::pose(0));
  ASSERT_EQ(r.status.size(), 4u);
  for (std::size_t i = 1; i < 4; ++i) EXPECT_NE(r.status[i], FrameStatus::Ok) << "scan " << i;
}

TEST(Degenerate, FirstScanEmptyStartsAtTheGivenPose) {
  Config cfg;
  const Pose3 T0 = test::poseXYZYaw(5, 6, 1.8, 0.4);
  LidarSlam slam(cfg, test::coarseLidar(32), T0);
  EXPECT_EQ(slam.addScan(Scan{}), FrameStatus::Empty);
  const SlamResult r = slam.finish();
  ASSERT_EQ(r.trajectory.size(), 1u);
  EXPECT_TRUE(r.trajectory[0].T_world_body.isApprox(T0));
}

}  // namespace
}  // namespace slamroute::evaluate
