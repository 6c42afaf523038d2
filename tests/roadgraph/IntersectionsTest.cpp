// Hollow-cylinder intersection detection (paper §3.1 step 1) on synthetic traces with known
// answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "SyntheticTraces.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/Intersections.hpp"

namespace slamroute::roadgraph {
namespace {

using testing::gridRoads;
using testing::line;
using testing::makeTraces;
using testing::plusRoads;
using testing::Road;

std::vector<Point3> positions(const Traces& tr) {
  std::vector<Point3> p;
  for (const auto& q : tr.points) p.push_back(q.pos);
  return p;
}

IntersectionResult detect(const Traces& tr, const NodeConfig& cfg = {}) {
  return detectIntersections(downsample(positions(tr), cfg.downsample_m).points, cfg);
}

/// As detect(), with the travel axes from the traces (as graphFromTraces does).
IntersectionResult detectWithAxes(const Traces& tr, const NodeConfig& cfg = {}) {
  const auto travel = travelDirections(tr, cfg.travel_span_m, 3.0);
  const auto ds = downsample(positions(tr), cfg.downsample_m, &travel);
  return detectIntersections(ds.points, cfg, &ds.axes);
}

/// Traces of a road with `lanes` lanes per direction (3.2 m wide, right-hand traffic).
Traces multiLane(const std::vector<Road>& roads, int lanes, double noise, std::uint64_t seed,
                 int passes) {
  Traces all;
  for (int l = 0; l < lanes; ++l) {
    const Traces t =
        makeTraces(roads, noise, seed + static_cast<std::uint64_t>(l), 1.0, passes, 1.6 + 3.2 * l);
    const int base = static_cast<int>(all.vehicles.size());
    all.vehicles.insert(all.vehicles.end(), t.vehicles.begin(), t.vehicles.end());
    for (auto p : t.points) {
      p.vehicle += base;
      all.points.push_back(p);
    }
  }
  return all;
}

void append(Traces& a, const Traces& b) {
  const int base = static_cast<int>(a.vehicles.size());
  a.vehicles.insert(a.vehicles.end(), b.vehicles.begin(), b.vehicles.end());
  for (auto p : b.points) {
    p.vehicle += base;
    a.points.push_back(p);
  }
}

TEST(Intersections, BranchCountsOfPlus) {
  const auto pts = downsample(positions(makeTraces(plusRoads())), 1.0).points;
  NodeConfig cfg;
  EXPECT_EQ(countBranches(pts, {0, 0, 0}, cfg), 4);    // centre: four arms
  EXPECT_EQ(countBranches(pts, {60, 0, 0}, cfg), 2);   // mid-street: two ways
  EXPECT_EQ(countBranches(pts, {100, 0, 0}, cfg), 1);  // dead end
}

TEST(Intersections, PlusHasExactlyOneNodeAtTheCrossing) {
  const auto r = detect(makeTraces(plusRoads()));
  ASSERT_EQ(r.nodes.size(), 1u);
  EXPECT_LT(r.nodes[0].head<2>().norm(), 1.0);
  EXPECT_EQ(r.branches[0], 4);
}

TEST(Intersections, TJunctionCentreIsNotPulledToTheStem) {
  const std::vector<Road> t = {{line({-100, 0, 0}, {100, 0, 0})}, {line({0, 0, 0}, {0, -100, 0})}};
  const auto r = detect(makeTraces(t));
  ASSERT_EQ(r.nodes.size(), 1u);
  EXPECT_LT(r.nodes[0].head<2>().norm(), 2.0) << r.nodes[0].transpose();
  EXPECT_EQ(r.branches[0], 3);
}

TEST(Intersections, OverpassIsNotANode) {
  // Street along x at z = 0; a bridge along y at z = 7 over it (ramps from |y| = 100 to 40);
  // a real junction at x = 120 so the graph has a node.
  Polyline bridge;
  for (double y = -200; y <= 200; y += 5) {
    const double a = std::abs(y);
    const double z = a <= 40 ? 7.0 : (a >= 100 ? 0.0 : 7.0 * (100 - a) / 60.0);
    bridge.emplace_back(0, y, z);
  }
  const std::vector<Road> roads = {
      {line({-150, 0, 0}, {250, 0, 0})}, {bridge}, {line({120, -100, 0}, {120, 100, 0})}};
  const auto r = detect(makeTraces(roads));
  ASSERT_EQ(r.nodes.size(), 1u);
  EXPECT_NEAR(r.nodes[0].x(), 120.0, 1.5);
  EXPECT_NEAR(r.nodes[0].y(), 0.0, 1.5);
  // Without height the same traces would see a crossing at the origin.
  NodeConfig flat;
  flat.height_m = 100.0;
  flat.require_connected = false;  // connectivity is 3D too and would also reject the bridge
  const auto r2 = detect(makeTraces(roads), flat);
  bool at_origin = false;
  for (const auto& n : r2.nodes) at_origin = at_origin || n.head<2>().norm() < 5.0;
  EXPECT_TRUE(at_origin);
}

TEST(Intersections, GridWithOverhangHasNineNodes) {
  const auto r = detect(makeTraces(gridRoads(3, 100, 50)));
  ASSERT_EQ(r.nodes.size(), 9u);
  for (const auto& n : r.nodes) {
    EXPECT_NEAR(n.x() / 100.0, std::round(n.x() / 100.0), 0.015) << n.transpose();
    EXPECT_NEAR(n.y() / 100.0, std::round(n.y() / 100.0), 0.015) << n.transpose();
  }
}

TEST(Intersections, GridCornersAreNotIntersections) {
  // A closed 3x3 grid: the 4 corners are bends (2 branches), 4 T junctions, 1 crossing.
  const auto r = detect(makeTraces(gridRoads(3, 100, 0)));
  EXPECT_EQ(r.nodes.size(), 5u);
  int t = 0, x = 0;
  for (int b : r.branches) (b == 3 ? t : x) += (b == 3 || b == 4) ? 1 : 0;
  EXPECT_EQ(t, 4);
  EXPECT_EQ(x, 1);
}

TEST(Intersections, OneMetreNoiseAndUnevenSamplingStillWork) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    auto tr = makeTraces(gridRoads(3, 100, 50), 1.0, seed, 1.0, 2);
    // Uneven sampling: drop a pseudo-random 40% of the points.
    Traces thin = tr;
    thin.points.clear();
    std::mt19937_64 rng(seed);
    for (const auto& p : tr.points)
      if (std::uniform_real_distribution<double>(0, 1)(rng) > 0.4) thin.points.push_back(p);
    const auto r = detect(thin);
    EXPECT_EQ(r.nodes.size(), 9u) << "seed " << seed;
    for (const auto& n : r.nodes) {
      const Point3 snap(std::round(n.x() / 100) * 100, std::round(n.y() / 100) * 100, 0);
      EXPECT_LT((n - snap).head<2>().norm(), 3.0) << "seed " << seed << " node " << n.transpose();
    }
  }
}

TEST(Intersections, FourLaneAvenueEndingAtAStreetIsOneNodeAtItsCentre) {
  // T junction: a two-lane street along x, a four-lane avenue (2 lanes per direction, 13 m
  // wide) from the south ends at it. Inside the ring the avenue's stem is ~13 m wide and ~13 m
  // long: its principal axis is unreliable, the vehicles' travel axis is not.
  for (std::uint64_t seed : {1u, 2u}) {
    Traces tr = makeTraces({{line({-150, 0, 0}, {150, 0, 0})}}, 0.5, seed, 1.0, 3);
    append(tr, multiLane({{line({0, -150, 0}, {0, -8, 0})}}, 2, 0.5, seed + 10, 3));
    // Turning traffic between the avenue and both halves of the street.
    append(tr, makeTraces({{{{0, -30, 0}, {0, -10, 0}, {-10, 0, 0}, {-40, 0, 0}}},
                           {{{0, -30, 0}, {0, -10, 0}, {10, 0, 0}, {40, 0, 0}}}},
                          0.5, seed + 20, 1.0, 2));
    const auto r = detectWithAxes(tr);
    ASSERT_EQ(r.nodes.size(), 1u) << "seed " << seed;
    // With the travel axes the centre is within 0.2 m; the arms' principal axes alone put it
    // 1.3-2.4 m off (measured with detect()).
    EXPECT_LT(r.nodes[0].head<2>().norm(), 1.0)
        << "seed " << seed << ": " << r.nodes[0].transpose();
  }
}

TEST(Intersections, BendOfADividedRoadIsNotANode) {
  // Two one-way carriageways of three lanes, centre lines 12 m apart, bending by 25 degrees: the
  // ring sees four clusters (two per side) but they are one road.
  const double a = 25.0 * M_PI / 180.0;
  auto road = [&](double off) {
    return Polyline{
        {-200, off, 0},
        {0, off, 0},
        {200 * std::cos(a) - off * std::sin(a), 200 * std::sin(a) + off * std::cos(a), 0}};
  };
  Traces tr = multiLane({{road(-6.0), false}}, 3, 0.5, 3, 2);
  Polyline back = road(6.0);
  std::reverse(back.begin(), back.end());
  append(tr, multiLane({{back, false}}, 3, 0.5, 4, 2));
  EXPECT_TRUE(detectWithAxes(tr).nodes.empty());
  EXPECT_TRUE(detect(tr).nodes.empty());
}

TEST(Intersections, ParallelStreetDoesNotMakeNodes) {
  // Two parallel streets 20 m apart, each crossed once, far apart: only the two crossings.
  const std::vector<Road> roads = {{line({-200, 0, 0}, {200, 0, 0})},
                                   {line({-200, 20, 0}, {200, 20, 0})},
                                   {line({-150, -100, 0}, {-150, 0, 0})},
                                   {line({150, 20, 0}, {150, 120, 0})}};
  const auto r = detect(makeTraces(roads));
  EXPECT_EQ(r.nodes.size(), 2u);
}

TEST(Intersections, IntersectionPointsAtTheCrossingBelongToItsNode) {
  // Every kept node keeps its votes: the intersection points around the crossing are assigned
  // to it (node_of_point), none is left without a node.
  const Traces tr = makeTraces(plusRoads(), 0.5, 5);
  const NodeConfig cfg;
  const auto ds = downsample(positions(tr), cfg.downsample_m);
  const auto r = detectIntersections(ds.points, cfg);
  ASSERT_EQ(r.nodes.size(), 1u);
  int near = 0;
  for (std::size_t i = 0; i < ds.points.size(); ++i) {
    if (!r.is_intersection[i] || ds.points[i].head<2>().norm() > 5.0) continue;
    ++near;
    EXPECT_EQ(r.node_of_point[i], 0) << "point " << ds.points[i].transpose();
  }
  EXPECT_GT(near, 5);
}

/// Two divided roads (one-way carriageways of `lanes` lanes, centre lines `gap` apart) crossing
/// at the origin, with left and right turns between all carriageways.
Traces dividedCrossing(double gap, int lanes, std::uint64_t seed) {
  const double h = 0.5 * gap, L = 150.0;
  Traces tr = multiLane({{line({-L, -h, 0}, {L, -h, 0}), false},
                         {line({L, h, 0}, {-L, h, 0}), false},
                         {line({h, -L, 0}, {h, L, 0}), false},
                         {line({-h, L, 0}, {-h, -L, 0}), false}},
                        lanes, 0.5, seed, 2);
  // Right and left turns from each carriageway, as Bezier-like three-point paths.
  std::vector<Road> turns;
  for (int k = 0; k < 4; ++k) {
    const double a = k * M_PI / 2, c = std::cos(a), s = std::sin(a);
    auto rot = [&](double x, double y) { return Point3(c * x - s * y, s * x + c * y, 0); };
    // Arriving eastbound on y = -h from the west.
    turns.push_back(
        {{rot(-60, -h), rot(-h - 6, -h), rot(-h, -h - 6), rot(-h, -60)}, false});          // right
    turns.push_back({{rot(-60, -h), rot(h - 6, -h), rot(h, -h + 6), rot(h, 60)}, false});  // left
  }
  append(tr, makeTraces(turns, 0.5, seed + 50, 1.0, 2));
  return tr;
}

TEST(Intersections, CrossingOfTwoDividedRoadsIsOneNode) {
  // Carriageway centre lines 16 m apart (two lanes each): the junction box is ~30 m wide. Each
  // of the four carriageway crossings (+-8, +-8) collects votes of its own, 10-16 m apart (with
  // merge_distance_m 8 this gave 4 nodes); merged, the node lies at the strongest crossing's
  // vote median, inside the box (6.6 / 7.4 m from its centre for these seeds).
  for (std::uint64_t seed : {1u, 2u}) {
    const auto r = detectWithAxes(dividedCrossing(16.0, 2, seed));
    ASSERT_EQ(r.nodes.size(), 1u) << "seed " << seed;
    EXPECT_LT(r.nodes[0].head<2>().norm(), 10.0)
        << "seed " << seed << ": " << r.nodes[0].transpose();
  }
}

}  // namespace
}  // namespace slamroute::roadgraph
