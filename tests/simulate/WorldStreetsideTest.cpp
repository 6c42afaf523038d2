// What lines the streets: fences along open streets, buildings that differ from their
// neighbours and have recessed windows, walls with height steps and pillars.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "WorldTestNet.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {
namespace {

const SumoNet& net() {
  static const SumoNet n = testnet::gridNet(5, 150);
  return n;
}
const World& world() {
  static const World w = World::build(net(), WorldConfig{}, 5);
  return w;
}

/// Edges of a street kind whose lane 0 runs straight along +x or +y.
std::vector<const SumoEdge*> edgesOf(StreetKind kind) {
  std::vector<const SumoEdge*> out;
  for (const auto& e : net().edges)
    if (world().streetKind(e.id) == kind) out.push_back(&e);
  return out;
}

/// Calls f(origin on the lane-0 centre line, outward unit vector) every `step` metres, 15 m
/// away from both ends of the edge.
template <class F>
void alongRightSide(const SumoEdge& e, double step, F f) {
  const auto& s = e.lanes.front().shape;
  const Vec3 d = s.back() - s.front();
  const double len = d.head<2>().norm();
  const Vec3 u = d / len, out(u.y(), -u.x(), 0.0);
  for (double t = 15; t < len - 15; t += step) f(s.front() + u * t, out);
}

TEST(WorldStreetside, OpenStreetsHaveFencesWithin15MetresOfTheRoad) {
  const auto open = edgesOf(StreetKind::Open);
  ASSERT_FALSE(open.empty());
  std::size_t rays = 0, fence = 0;
  for (const SumoEdge* e : open)
    alongRightSide(*e, 1.0, [&](const Point3& p, const Vec3& out) {
      ++rays;  // at the lower rail's height, over the kerb
      const RayHit h = world().castRay(Point3(p.x(), p.y(), 0.41), out, 15.0);
      if (h.hit && h.kind == SurfaceKind::Fence) ++fence;
    });
  ASSERT_GT(rays, 100u);
  EXPECT_GT(static_cast<double>(fence) / rays, 0.6) << fence << " of " << rays;
  EXPECT_GT(world().stats().fence_posts, 100u);
}

TEST(WorldStreetside, NeighbouringBuildingsDifferAndHaveRecessedWindows) {
  std::size_t pairs = 0, recessed = 0, fronts = 0;
  for (const SumoEdge* e : edgesOf(StreetKind::Rich)) {
    // one run of facade hits per building front (rays at 6 m height, outward from the lane)
    std::vector<std::vector<double>> runs;
    bool in_run = false;
    alongRightSide(*e, 0.2, [&](const Point3& p, const Vec3& out) {
      const RayHit h = world().castRay(Point3(p.x(), p.y(), 6.0), out, 30.0);
      if (h.hit && h.kind == SurfaceKind::Building) {
        if (!in_run) runs.emplace_back();
        runs.back().push_back(h.range_m);
        in_run = true;
      } else {
        in_run = false;
      }
    });
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (runs[i].size() < 20) continue;  // a building, not a corner or a balcony
      ++fronts;
      std::set<long> depths;  // distinct facade depths in 5 cm steps
      for (double r : runs[i]) depths.insert(std::lround(r / 0.05));
      if (depths.size() >= 2) ++recessed;
      if (i + 1 < runs.size() && runs[i + 1].size() >= 20) {
        ++pairs;
        EXPECT_NE(runs[i], runs[i + 1]) << e->id << " buildings " << i << " and " << i + 1;
      }
    }
  }
  ASSERT_GT(fronts, 10u);
  EXPECT_GT(pairs, 3u);
  EXPECT_GT(recessed, fronts * 9 / 10);
}

TEST(WorldStreetside, WallsStepInHeightAndHavePillars) {
  std::set<long> heights;
  std::size_t pillar = 0, wall = 0;
  for (const SumoEdge* e : edgesOf(StreetKind::Wall))
    alongRightSide(*e, 0.25, [&](const Point3& p, const Vec3& out) {
      const RayHit h = world().castRay(Point3(p.x(), p.y(), 1.0), out, 30.0);
      if (!h.hit || h.kind != SurfaceKind::Wall) return;
      ++wall;
      // pillars stand 0.35 m before the wall's face
      const double face = 1.6 + WorldConfig{}.sidewalk_width_m + WorldConfig{}.wall_setback_m;
      if (h.range_m < face - 0.2) ++pillar;
      const Point3 top = p + out * (h.range_m + 0.2);
      const RayHit down = world().castRay(Point3(top.x(), top.y(), 20.0), -Vec3::UnitZ(), 30.0);
      if (down.hit && down.kind == SurfaceKind::Wall)
        heights.insert(std::lround((20.0 - down.range_m) / 0.1));
    });
  ASSERT_GT(wall, 100u);
  EXPECT_GT(pillar, wall / 50);
  EXPECT_LT(pillar, wall / 3);
  EXPECT_GE(heights.size(), 4u);
}

}  // namespace
}  // namespace slamroute::simulate
