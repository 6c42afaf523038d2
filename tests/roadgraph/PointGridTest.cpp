// The spatial grid behind the hollow-cylinder test (roadgraph/src/PointGrid.hpp): its radius
// queries and its precomputed close pairs agree with brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "PointGrid.hpp"

using namespace slamroute;
using slamroute::roadgraph::detail::PointGrid;

namespace {

std::vector<Point3> randomPoints(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> xy(-60.0, 60.0), z(-6.0, 6.0);
  std::vector<Point3> pts;
  for (std::size_t i = 0; i < n; ++i) pts.emplace_back(xy(rng), xy(rng), z(rng));
  // Pairs exactly at the tolerance count as close (<=).
  pts.emplace_back(100.0, 100.0, 0.0);
  pts.emplace_back(104.0, 100.0, 0.0);
  return pts;
}

}  // namespace

TEST(PointGrid, RadiusQueryMatchesBruteForce) {
  const auto pts = randomPoints(3000, 1);
  const PointGrid grid(pts, 5.0);
  const Point3 c(3.0, -7.0, 1.0);
  std::set<int> got, want;
  grid.forEachNear(c, 25.0, 5.0, [&](int i) { got.insert(i); });
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point3 d = pts[i] - c;
    if (d.x() * d.x() + d.y() * d.y() <= 625.0 && std::abs(d.z()) <= 5.0)
      want.insert(static_cast<int>(i));
  }
  EXPECT_FALSE(want.empty());
  EXPECT_EQ(got, want);
}

TEST(PointGrid, LinkedPairsAreExactlyThePairsWithinTolerance) {
  const auto pts = randomPoints(3000, 2);
  PointGrid grid(pts, 5.0);
  EXPECT_EQ(grid.linkTolerance(), 0.0);
  grid.linkWithin(4.0);
  EXPECT_EQ(grid.linkTolerance(), 4.0);
  std::set<std::pair<int, int>> got, want;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i)
    grid.forEachLinked(i, [&](int j) { got.insert({i, j}); });
  for (int i = 0; i < static_cast<int>(pts.size()); ++i)
    for (int j = 0; j < static_cast<int>(pts.size()); ++j)
      if (i != j &&
          (pts[static_cast<std::size_t>(i)] - pts[static_cast<std::size_t>(j)]).squaredNorm() <=
              16.0)
        want.insert({i, j});
  EXPECT_GT(want.size(), 100u);
  EXPECT_EQ(got, want);
  const int last = static_cast<int>(pts.size()) - 1;
  EXPECT_TRUE(got.count({last - 1, last}));
}
