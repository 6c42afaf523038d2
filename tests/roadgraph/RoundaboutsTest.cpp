// Roundabouts (roadgraph/src/Roundabouts.cpp) on synthetic traces with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "SyntheticTraces.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/Intersections.hpp"
#include "slamroute/roadgraph/Roundabouts.hpp"

namespace slamroute::roadgraph {
namespace {

using testing::makeTraces;
using testing::Road;

constexpr double kPi = 3.14159265358979323846;

/// Paths through a roundabout of radius `r` at the origin with two-way arms (100 m long) at
/// `arm_deg`: one drive from every arm to every other, counter-clockwise round the ring (right-hand
/// traffic). makeTraces puts vehicles 1.6 m right of these lines: the ring lane is at r + 1.6.
std::vector<Road> roundaboutDrives(double r, const std::vector<double>& arm_deg) {
  std::vector<Road> drives;
  for (std::size_t i = 0; i < arm_deg.size(); ++i)
    for (std::size_t j = 0; j < arm_deg.size(); ++j) {
      if (i == j) continue;
      const double a = arm_deg[i] * kPi / 180.0;
      double b = arm_deg[j] * kPi / 180.0;
      while (b <= a) b += 2 * kPi;
      Polyline pl;
      pl.emplace_back((r + 100) * std::cos(a), (r + 100) * std::sin(a), 0.0);
      for (double t = a; t < b; t += 0.1) pl.emplace_back(r * std::cos(t), r * std::sin(t), 0.0);
      pl.emplace_back(r * std::cos(b), r * std::sin(b), 0.0);
      pl.emplace_back((r + 100) * std::cos(b), (r + 100) * std::sin(b), 0.0);
      drives.push_back({pl, /*two_way=*/false});
    }
  return drives;
}

std::vector<Roundabout> detect(const Traces& tr, const Config& cfg = Config{}) {
  const std::vector<std::size_t> order = byVehicleThenTime(tr);
  const auto travel = travelDirections(tr, order, cfg.nodes.travel_span_m, cfg.edges.max_gap_s);
  return detectRoundabouts(tr, order, travel, cfg.roundabouts, cfg.edges.max_gap_s,
                           0.5 * cfg.nodes.height_m);
}

TEST(Roundabouts, FourArmRoundaboutHasOneJunctionPerArm) {
  const std::vector<double> arms = {0, 90, 180, 270};
  const Traces tr = makeTraces(roundaboutDrives(12.0, arms), 0.3, 5, 1.0, /*passes=*/2);
  const auto rbs = detect(tr);
  ASSERT_EQ(rbs.size(), 1u);
  const Roundabout& rb = rbs[0];
  EXPECT_LT(rb.centre.head<2>().norm(), 1.0);
  EXPECT_NEAR(rb.radius_m, 13.6, 1.0);  // ring lane: 12 m + 1.6 m lane offset
  EXPECT_EQ(rb.sense, 1);               // counter-clockwise
  ASSERT_EQ(rb.junctions.size(), arms.size());
  for (double deg : arms) {
    const Eigen::Vector2d arm(13.6 * std::cos(deg * kPi / 180), 13.6 * std::sin(deg * kPi / 180));
    double best = 1e9;
    for (const auto& j : rb.junctions) best = std::min(best, (j.head<2>() - arm).norm());
    EXPECT_LT(best, 4.0) << "arm at " << deg << " deg";
  }
}

TEST(Roundabouts, ClockwiseRingIsFoundWithItsSense) {
  // Left-hand traffic: the same roundabout mirrored (y -> -y) is circled clockwise.
  Traces tr = makeTraces(roundaboutDrives(12.0, {0, 120, 240}), 0.3, 5, 1.0, 2);
  for (auto& p : tr.points) p.pos.y() = -p.pos.y();
  const auto rbs = detect(tr);
  ASSERT_EQ(rbs.size(), 1u);
  EXPECT_EQ(rbs[0].sense, -1);
  EXPECT_EQ(rbs[0].junctions.size(), 3u);
}

TEST(Roundabouts, CrossingWithTurningTrafficIsNoRoundabout) {
  // A four-arm crossing where vehicles drive every movement: the turning arcs about the corners
  // fit circles, but they cover part of a circle each and traffic runs through the middle.
  std::vector<Road> drives;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (i == j) continue;
      const Eigen::Vector2d in(std::cos(i * kPi / 2), std::sin(i * kPi / 2));
      const Eigen::Vector2d out(std::cos(j * kPi / 2), std::sin(j * kPi / 2));
      Polyline pl{Point3(100 * in.x(), 100 * in.y(), 0)};
      for (double t = 0; t <= 1.0001; t += 0.05) {  // quadratic Bezier 10 in -> centre -> 10 out
        const Eigen::Vector2d q = (1 - t) * (1 - t) * 10 * in + t * t * 10 * out;
        pl.emplace_back(q.x(), q.y(), 0.0);
      }
      pl.emplace_back(100 * out.x(), 100 * out.y(), 0.0);
      drives.push_back({pl, false});
    }
  const Traces tr = makeTraces(drives, 0.3, 5, 1.0, 3);
  EXPECT_TRUE(detect(tr).empty());
  const auto r = graphFromTraces(tr, Config{});
  EXPECT_EQ(r.stats.roundabouts, 0u);
  EXPECT_EQ(r.stats.intersections, 1u);
}

TEST(Roundabouts, DisabledFindsNothing) {
  Config cfg;
  cfg.roundabouts.enabled = false;
  EXPECT_TRUE(
      detect(makeTraces(roundaboutDrives(12.0, {0, 90, 180, 270}), 0.3, 5, 1.0, 2), cfg).empty());
}

TEST(Roundabouts, BadConfigThrowsClearly) {
  const Traces tr = makeTraces(roundaboutDrives(12.0, {0, 120, 240}), 0.3, 5, 1.0, 2);
  Config cfg;
  cfg.roundabouts.max_radius_m = 3.0;  // below min_radius_m
  EXPECT_THROW(detect(tr, cfg), std::invalid_argument);
  cfg = Config{};
  cfg.roundabouts.ring_width_m = 0.0;
  EXPECT_THROW(graphFromTraces(tr, cfg), std::invalid_argument);
}

TEST(Roundabouts, GraphHasTheRingJunctionsLinkedOneWayRoundTheRing) {
  // The graph gets one node per arm on the ring in place of the hollow cylinder's, each arm a
  // street to it, and the ring between consecutive junctions driven counter-clockwise only.
  const std::vector<double> arms = {0, 90, 180, 270};
  const Traces tr = makeTraces(roundaboutDrives(12.0, arms), 0.3, 5, 1.0, 2);
  const auto r = graphFromTraces(tr, Config{});
  EXPECT_EQ(r.stats.roundabouts, 1u);
  ASSERT_EQ(r.roundabouts.size(), 1u);
  EXPECT_EQ(r.roundabouts[0].junctions.size(), arms.size());
  EXPECT_EQ(r.stats.intersections, 4u);
  std::vector<int> junction(arms.size(), -1);
  for (std::size_t n = 0; n < r.graph.nodes.size(); ++n) {
    if (r.node_is_end[n]) continue;
    const auto& p = r.graph.nodes[n].pos;
    for (std::size_t k = 0; k < arms.size(); ++k) {
      const double a = arms[k] * kPi / 180;
      if (std::hypot(p.x() - 13.6 * std::cos(a), p.y() - 13.6 * std::sin(a)) < 4.0)
        junction[k] = static_cast<int>(n);
    }
  }
  auto has = [&](int u, int v) {
    for (const auto& e : r.graph.edges)
      if (e.u == u && e.v == v) return true;
    return false;
  };
  for (std::size_t k = 0; k < arms.size(); ++k) {
    ASSERT_GE(junction[k], 0) << "arm " << arms[k];
    const int next = junction[(k + 1) % arms.size()];
    ASSERT_GE(next, 0);
    EXPECT_TRUE(has(junction[k], next)) << "ring " << arms[k] << " deg, counter-clockwise";
    EXPECT_FALSE(has(next, junction[k])) << "ring " << arms[k] << " deg, clockwise";
  }
}

}  // namespace
}  // namespace slamroute::roadgraph
