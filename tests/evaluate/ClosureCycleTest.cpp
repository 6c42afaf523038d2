// The cycle of two loop closures (evaluate/src/slam/ClosureCycle): a street driven twice, a true
// closure on the second pass, then a second closure 30 m later, true or one facade (12 m) along
// the street.
#include <gtest/gtest.h>

#include "slam/ClosureCycle.hpp"
#include "slam/KeyframeGraph.hpp"

namespace slamroute::evaluate {
namespace {

Pose3 along(double x) {
  Pose3 T = Pose3::Identity();
  T.translation() = Vec3(x, 0.0, 1.8);
  return T;
}

/// Keyframes every 10 m along x from 0 to 90 (0-9), then a second pass from 0 to 60 (10-16)
/// whose estimate stretches by `scale` (wheel odometry drift); the first closure joins 3 and 13.
struct TwoPasses {
  Config cfg;
  slam::KeyframeGraph graph{cfg};
  LoopClosure before;
  explicit TwoPasses(double scale) {
    for (int k = 0; k < 10; ++k) graph.add(k, k, along(10.0 * k), {}, {}, {});
    for (int k = 0; k <= 6; ++k)
      graph.add(100 + k, 10 + k, along(30.0 + scale * 10.0 * (k - 3)), {}, {}, {});
    before.from_keyframe = 3;
    before.to_keyframe = 13;
    before.T_old_new = Pose3::Identity();  // the second pass at 30 m is where the first was
  }
};

TEST(ClosureCycle, ATrueSecondClosureClosesTheCycle) {
  const TwoPasses p(1.0);
  const slam::ClosureCycle c = slam::closureCycle(p.graph, p.before, 6, along(60.0));
  EXPECT_NEAR(c.error_m, 0.0, 1e-9);
  EXPECT_NEAR(c.chain_m, 60.0, 1e-9);  // 3 -> 6 and 13 -> 16, 30 m each
  EXPECT_TRUE(slam::consistentCycle(c, p.cfg.loop));
}

TEST(ClosureCycle, DriftOfTheChainsIsTolerated) {
  // The second pass's estimate 2 % long: the truth (60 m) lies 0.6 m behind where it ends.
  const TwoPasses p(1.02);
  const slam::ClosureCycle c = slam::closureCycle(p.graph, p.before, 6, along(60.0));
  EXPECT_NEAR(c.error_m, 0.6, 1e-9);
  EXPECT_TRUE(slam::consistentCycle(c, p.cfg.loop));
}

TEST(ClosureCycle, AMatchOneFacadeAlongBreaksIt) {
  const TwoPasses p(1.0);
  const slam::ClosureCycle c = slam::closureCycle(p.graph, p.before, 6, along(72.0));
  EXPECT_NEAR(c.error_m, 12.0, 1e-9);
  EXPECT_FALSE(slam::consistentCycle(c, p.cfg.loop));
  LoopConfig off = p.cfg.loop;
  off.consistency_m = -1.0;
  EXPECT_TRUE(slam::consistentCycle(c, off));
}

}  // namespace
}  // namespace slamroute::evaluate
