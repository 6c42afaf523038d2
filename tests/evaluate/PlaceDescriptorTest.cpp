// Place recognition on scans of analytic scenes of scattered boxes (SyntheticScene.hpp): the
// descriptor of a scan turned on the spot matches with the turn as its yaw; other places do not
// match, a place 1 m away does; the database finds the keyframe of the place among the others;
// ICP from the descriptor's yaw recovers the relative pose that ICP from no turn misses.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "SyntheticScene.hpp"
#include "slamroute/evaluate/LoopVerification.hpp"
#include "slamroute/evaluate/PlaceDatabase.hpp"
#include "slamroute/evaluate/PlaceDescriptor.hpp"

namespace slamroute::evaluate {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kSensorHeight = 1.8;
constexpr double kSectorRad = 6.0 * kDeg;  ///< the default 60 sectors

/// 64 x 900 rays (0.4 deg): every 6 deg sector gets 15 columns, and a turn by a multiple of
/// 0.4 deg meets the same rays.
LidarSpec spec() {
  LidarSpec s = lidarPreset("paper");
  s.horizontal_samples = 900;
  return s;
}

const test::Scene& scene(std::uint64_t seed) {
  static std::map<std::uint64_t, test::Scene> scenes;
  if (!scenes.count(seed)) scenes[seed] = test::scatteredScene(seed);
  return scenes[seed];
}

/// Scene `seed`'s scan from (x, y) at sensor height, heading `yaw_deg`, as a body-frame cloud.
Cloud scanAt(std::uint64_t seed, double x, double y, double yaw_deg) {
  const Scan s =
      test::scanScene(scene(seed), test::poseXYZYaw(x, y, kSensorHeight, yaw_deg * kDeg), spec());
  Cloud c;
  c.reserve(s.points.size());
  for (const auto& p : s.points) c.emplace_back(p.x, p.y, p.z);
  return c;
}

PlaceDescriptor describe(std::uint64_t seed, double x, double y, double yaw_deg) {
  return makePlaceDescriptor(scanAt(seed, x, y, yaw_deg), kSensorHeight, PlaceRecognitionConfig{});
}

/// |a - b| wrapped into [0, pi].
double angleGap(double a, double b) {
  return std::abs(std::remainder(a - b, 2 * std::numbers::pi));
}

TEST(PlaceDescriptor, HeightsAreCountedFromTheRoadPerRingAndSector) {
  PlaceRecognitionConfig cfg;
  cfg.rings = 4;
  cfg.sectors = 8;
  cfg.max_radius_m = 40.0;  // 10 m rings, 45 deg sectors from -180 deg
  cfg.ring_spread = 0.0;
  const Cloud c = {{15, 1, 3.2f}, {15, 1, 0.2f}, {-5, -1, -0.8f}, {45, 0, 9.0f}};
  const PlaceDescriptor d = makePlaceDescriptor(c, kSensorHeight, cfg);
  EXPECT_FLOAT_EQ(d.at(1, 4), 5.0f);  // ring 10-20 m, sector 0-45 deg: the higher point
  EXPECT_FLOAT_EQ(d.at(0, 0), 1.0f);  // ring 0-10 m, sector -180..-135 deg
  EXPECT_FLOAT_EQ(d.ring_key[0], 1.0f / 8);
  EXPECT_FLOAT_EQ(d.ring_key[1], 5.0f / 8);
  float total = 0;
  for (const float h : d.height_m) total += h;
  EXPECT_FLOAT_EQ(total, 6.0f);  // the point beyond 40 m is left out
  cfg.ring_spread = 1.0;         // neighbouring rings get exp(-k^2 / 2) of a cell's height
  const PlaceDescriptor spread = makePlaceDescriptor(c, kSensorHeight, cfg);
  EXPECT_FLOAT_EQ(spread.at(1, 4), 5.0f);
  EXPECT_FLOAT_EQ(spread.at(2, 4), 5.0f * std::exp(-0.5f));
  EXPECT_FLOAT_EQ(spread.at(3, 4), 5.0f * std::exp(-2.0f));
  EXPECT_FLOAT_EQ(spread.at(0, 4), 5.0f * std::exp(-0.5f));
  EXPECT_FLOAT_EQ(spread.at(1, 0), 1.0f * std::exp(-0.5f));
}

TEST(PlaceDescriptor, AScanTurnedOnTheSpotMatchesWithItsYaw) {
  const PlaceDescriptor base = describe(1, 0, 0, 0);
  const double threshold = PlaceRecognitionConfig{}.max_distance;
  for (const double yaw_deg : {90.0, 37.0, -122.0}) {
    const PlaceMatch m = placeDistance(describe(1, 0, 0, yaw_deg), base);
    // a quarter turn meets the same rays; other turns sample the sectors a little differently
    EXPECT_LT(m.distance, yaw_deg == 90.0 ? 1e-6 : threshold / 2) << yaw_deg;
    EXPECT_LE(angleGap(m.yaw_rad, yaw_deg * kDeg), kSectorRad)
        << yaw_deg << " deg, got " << m.yaw_rad / kDeg;
  }
}

TEST(PlaceDescriptor, OtherPlacesAreFartherThanTheThreshold) {
  const PlaceDescriptor here = describe(1, 0, 0, 0);
  const double threshold = PlaceRecognitionConfig{}.max_distance;
  for (const std::uint64_t other : {2, 3, 4}) {
    const double d = placeDistance(describe(other, 0, 0, 0), here).distance;
    EXPECT_GT(d, threshold) << "scene " << other;
  }
  // the same scene 40 m away is another place too
  EXPECT_GT(placeDistance(describe(1, 30, 25, 0), here).distance, threshold);
}

TEST(PlaceDescriptor, OneMetreAwayStillMatchesBetterThanAnotherPlace) {
  const PlaceDescriptor here = describe(1, 0, 0, 0);
  const double other = placeDistance(describe(2, 0, 0, 0), here).distance;
  for (const auto& [x, y] : {std::pair{1.0, 0.0}, {0.0, -1.0}, {0.6, 0.8}}) {
    const double moved = placeDistance(describe(1, x, y, 15), here).distance;
    EXPECT_LT(moved, PlaceRecognitionConfig{}.max_distance) << x << "," << y;
    EXPECT_LT(moved, other) << x << "," << y;
  }
  // The spread over rings is what keeps a wall that changed ring with the shift: without it
  // the same shift costs more.
  PlaceRecognitionConfig plain;
  plain.ring_spread = 0.0;
  const auto plainAt = [&](double x, double y, double yaw) {
    return makePlaceDescriptor(scanAt(1, x, y, yaw), kSensorHeight, plain);
  };
  EXPECT_GT(placeDistance(plainAt(1, 0, 15), plainAt(0, 0, 0)).distance,
            1.5 * placeDistance(describe(1, 1, 0, 15), here).distance);
}

TEST(PlaceDatabase, FindsTheKeyframeOfThePlaceAmongTheOthers) {
  // Keyframe k: scene k + 1 seen from its origin, stored at (100 k, 0), heading 10 k deg.
  PlaceDatabase db(PlaceRecognitionConfig{});
  const int n = 12;
  for (int k = 0; k < n; ++k)
    db.add(k, describe(static_cast<std::uint64_t>(k + 1), 0, 0, 10.0 * k), Vec3(100.0 * k, 0, 0));
  ASSERT_EQ(db.size(), static_cast<std::size_t>(n));
  const int truth = 7;
  const PlaceDescriptor q = describe(truth + 1, 0.5, 0.8, -60);
  const auto found = db.query(q);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found.front().keyframe, truth);
  EXPECT_EQ(found.size(), 1u);  // no other scene is within the threshold
  // the query is turned -60 deg, the keyframe 70 deg: -130 deg in the keyframe's frame
  EXPECT_LE(angleGap(found.front().yaw_rad, -130 * kDeg), kSectorRad)
      << found.front().yaw_rad / kDeg;

  PlaceQuery recent;  // the keyframe counts as recent: not a candidate
  recent.newest_keyframe = truth - 1;
  EXPECT_TRUE(db.query(q, recent).empty());
  PlaceQuery gate;  // gated around an odometry estimate near the keyframe
  gate.gate_centre = Vec3(100.0 * truth + 6, -3, 0);
  gate.gate_radius_m = 10.0;
  const auto gated = db.query(q, gate);
  ASSERT_EQ(gated.size(), 1u);
  EXPECT_EQ(gated.front().keyframe, truth);
  gate.gate_centre = Vec3(100.0 * truth + 50, 0, 0);  // ... or far from it
  EXPECT_TRUE(db.query(q, gate).empty());
}

TEST(PlaceDatabase, RejectsABadConfigAndForeignDescriptors) {
  PlaceRecognitionConfig bad;
  bad.rings = 0;
  try {
    PlaceDatabase db(bad);
    FAIL() << "rings 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "place.rings must be in [1, 1000] (got 0)");
  }
  PlaceDatabase db(PlaceRecognitionConfig{});
  PlaceRecognitionConfig small;
  small.rings = 10;
  EXPECT_THROW(db.add(0, makePlaceDescriptor({}, kSensorHeight, small), Vec3::Zero()),
               std::invalid_argument);
}

TEST(LoopVerification, IcpFromTheDescriptorsYawFindsTheRelativePose) {
  const Cloud target = voxelFilter(scanAt(1, 0, 0, 0), 0.4);
  const Cloud query = voxelFilter(scanAt(1, 1.0, 0.6, 90), 0.4);
  const IcpTarget icp_target(target);
  PlaceCandidate c{0, 0.0, 0.0};
  c.yaw_rad = placeDistance(makePlaceDescriptor(query, kSensorHeight, {}),
                            makePlaceDescriptor(target, kSensorHeight, {}))
                  .yaw_rad;
  const LoopVerification v = verifyLoop(icp_target, Pose3::Identity(), query, c, {});
  EXPECT_TRUE(v.accepted) << v.icp.fitness_m2 << " " << v.icp.inlier_ratio;
  const Pose3 truth = test::poseXYZYaw(1.0, 0.6, 0.0, 90 * kDeg);
  EXPECT_LT((v.icp.T_target_source.translation() - truth.translation()).norm(), 0.05);
  EXPECT_LT(
      Eigen::AngleAxisd(v.icp.T_target_source.rotation().transpose() * truth.rotation()).angle(),
      0.5 * kDeg);
  EXPECT_LT(v.yaw_change_deg, 6.0);
  // Without the descriptor's yaw ICP stays a quarter turn off (or is refused).
  const LoopVerification blind =
      verifyLoop(icp_target, Pose3::Identity(), query, {0, 0.0, 0.0}, {});
  const double blind_err =
      Eigen::AngleAxisd(blind.icp.T_target_source.rotation().transpose() * truth.rotation())
          .angle();
  EXPECT_TRUE(!blind.accepted || blind_err > 10 * kDeg) << blind_err / kDeg;
}

}  // namespace
}  // namespace slamroute::evaluate
