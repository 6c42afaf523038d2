// LiDAR-only on a bridge deck: two straight parapets and a flat deck leave the motion along the
// street to the motion model. The constant-velocity prior along the heading
// (odometry.velocity_prior_along_sigma_m, an option) keeps the car's speed there; without it the
// scan-to-map holds the car where the local map was built and the estimate stalls.
#include <gtest/gtest.h>

#include "SyntheticScene.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate {
namespace {

/// Buildings round the approach (x < 0), then a deck 300 m long between parapets 1 m high.
test::Scene deckScene() {
  test::Scene s;
  for (double x = -100.0; x < -10.0; x += 18.0) {
    s.boxes.push_back({{x, 9.0, 0.0}, {x + 12.0, 20.0, 8.0 + std::fmod(x * 7.0, 5.0)}});
    s.boxes.push_back({{x + 5.0, -22.0, 0.0}, {x + 14.0, -9.0, 12.0}});
  }
  s.boxes.push_back({{-10.0, 5.0, 0.0}, {300.0, 5.3, 1.0}});
  s.boxes.push_back({{-10.0, -5.3, 0.0}, {300.0, -5.0, 1.0}});
  return s;
}

/// 15 m/s along +x, 10 scans per second, from 60 m before the deck to 160 m onto it (past the
/// 100 m the sensor sees, so the last scans see parapets and deck only).
class DeckDrive : public ScanSource {
 public:
  std::size_t size() const override { return 150; }
  double time(std::size_t i) const override { return 0.1 * static_cast<double>(i); }
  Scan scan(std::size_t i) const override {
    return test::scanScene(scene_, pose(i), test::coarseLidar(32), time(i));
  }
  LidarSpec spec() const override { return test::coarseLidar(32); }
  static Pose3 pose(std::size_t i) {
    return test::poseXYZYaw(-60.0 + 1.5 * static_cast<double>(i), 0.0, 1.8, 0.0);
  }

 private:
  test::Scene scene_ = deckScene();
};

class Corridor : public ::testing::TestWithParam<double> {};

TEST_P(Corridor, TheConstantVelocityPriorCarriesTheCarAcrossTheDeck) {
  const double sigma = GetParam();
  Config cfg;
  cfg.input.scan_stride = 1;
  cfg.loop.enabled = false;
  cfg.odometry.velocity_prior_along_sigma_m = sigma;
  const DeckDrive drive;
  const SlamResult r = runSlam(drive, cfg, DeckDrive::pose(0));
  ASSERT_EQ(r.trajectory.size(), drive.size());
  const Vec3 end = r.trajectory.back().T_world_body.translation();
  const Vec3 truth = DeckDrive::pose(drive.size() - 1).translation();
  if (sigma > 0) {
    EXPECT_NEAR(end.x(), truth.x(), 1.0);  // 223.5 m driven at a constant speed
    EXPECT_NEAR(end.y(), truth.y(), 0.3);
  } else {
    EXPECT_LT(end.x(), truth.x() - 100.0);  // held where the buildings fell behind
  }
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutPrior, Corridor, ::testing::Values(0.002, 0.0));

}  // namespace
}  // namespace slamroute::evaluate
