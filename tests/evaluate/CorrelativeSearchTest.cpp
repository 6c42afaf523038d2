// Correlative search: the offset of a place is found from a start metres off, and a street whose
// poles and windows repeat every 12 m has a rival pose one period along.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "slamroute/evaluate/CorrelativeSearch.hpp"

namespace slamroute::evaluate {
namespace {

constexpr double kSensorHeight = 1.8;

/// A street along x from 0 to 200 m: buildings between marks `period_m` apart (irregular
/// spacing and setbacks when period_m is 0), facades at y = +-8 m plus the setback, a window
/// recess and a pole at each mark, and the road.
Cloud street(double period_m) {
  std::vector<double> marks;
  for (double x = 5, k = 0; x < 195; ++k) {
    marks.push_back(x);
    x += period_m > 0 ? period_m : 7.0 + std::fmod(k * 5.3, 9.0);
  }
  const auto building = [&](double x) {
    std::size_t k = 0;
    while (k + 1 < marks.size() && marks[k + 1] <= x) ++k;
    return k;
  };
  Cloud pts;
  for (double x = 0; x < 200; x += 0.2)
    for (double z = 0.5; z < 8; z += 0.5)
      for (const double side : {-1.0, 1.0}) {
        const std::size_t k = building(x);
        const double setback =
            period_m > 0 ? 0.0 : std::fmod(k * 0.37 + (side > 0 ? 0.5 : 0.0), 1.5);
        const bool window = std::abs(x - marks[k]) < 1.0 && z > 2 && z < 5;
        pts.emplace_back(float(x), float(side * (8.0 + setback + (window ? 0.6 : 0.0))), float(z));
      }
  for (const double m : marks)
    for (double z = 0.4; z < 5; z += 0.2) pts.emplace_back(float(m), -5.5f, float(z));
  for (double x = 0; x < 200; x += 0.5)
    for (double y = -8; y < 8; y += 0.5) pts.emplace_back(float(x), float(y), 0.0f);  // road
  return pts;
}

/// The street as a sensor at `pose` sees it within 30 m, above the road.
Cloud seenFrom(const Cloud& world, const Pose3& pose) {
  Cloud body;
  for (const auto& p : world) {
    const Vec3 b = pose.inverse() * p.cast<double>();
    if (b.head<2>().norm() < 30) body.push_back(b.cast<float>());
  }
  return structureAboveRoad(body, kSensorHeight, 0.4, 10.0);
}

Pose3 at(double x, double y, double yaw) {
  Pose3 T = Pose3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
  T.translation() = Vec3(x, y, kSensorHeight);
  return T;
}

/// The street's structure above the road, as the loop closer builds its target.
Cloud target(const Cloud& world) { return structureAboveRoad(world, 0.0, 0.4, 10.0); }

double yawOfPose(const Pose3& T) { return std::atan2(T.rotation()(1, 0), T.rotation()(0, 0)); }

TEST(CorrelativeSearch, FindsAUniquePlaceFromAStartMetresOff) {
  const Cloud world = street(0.0);
  const Pose3 truth = at(80, 1.0, 0.02);
  CorrelativeOptions o;
  o.window_m = 10;
  const CorrelativeResult r =
      correlativeSearch(target(world), seenFrom(world, truth), at(84.5, 0.0, 0.05), o);
  EXPECT_LT((r.best.translation() - truth.translation()).norm(), 0.3);
  EXPECT_LT(std::abs(yawOfPose(r.best) - 0.02), 0.02);
  EXPECT_GT(r.score, 0.6);
  EXPECT_LT(r.runner_up, 0.9 * r.score) << "rival at " << r.runner_up_offset.transpose();
}

TEST(CorrelativeSearch, ALookAlikeOnePeriodAlongIsARival) {
  const Cloud world = street(12.0);
  const Pose3 truth = at(80, 1.0, 0.0);
  CorrelativeOptions o;
  o.window_m = 15;
  const CorrelativeResult r =
      correlativeSearch(target(world), seenFrom(world, truth), at(83, 1.0, 0.0), o);
  EXPECT_GE(r.runner_up, 0.9 * r.score);
  EXPECT_NEAR(std::abs(r.runner_up_offset.x()), 12.0, 0.5);
}

TEST(CorrelativeSearch, NothingToMatchLeavesTheStart) {
  const Pose3 start = at(3, 4, 0.1);
  const CorrelativeResult r = correlativeSearch({}, seenFrom(street(0.0), start), start, {});
  EXPECT_EQ(r.score, 0.0);
  EXPECT_TRUE(r.best.isApprox(start));
}

TEST(CorrelativeSearch, StructureAboveRoadDropsTheGround) {
  const Cloud body = {{1.f, 0.f, float(-kSensorHeight)}, {1.f, 0.f, 0.f}, {1.f, 0.f, 20.f}};
  const Cloud kept = structureAboveRoad(body, kSensorHeight, 0.4, 10.0);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_FLOAT_EQ(kept[0].z(), 0.f);
}

}  // namespace
}  // namespace slamroute::evaluate
