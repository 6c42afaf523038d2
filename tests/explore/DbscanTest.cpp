// DBSCAN on plane points: known clusters, border points, noise.
#include <gtest/gtest.h>

#include "slamroute/explore/Dbscan.hpp"

namespace slamroute::explore {
namespace {

TEST(Dbscan, TwoBlobsAndANoisePoint) {
  std::vector<Point2> pts;
  for (int i = 0; i < 5; ++i) pts.emplace_back(i * 1.0, 0.0);           // a line, 1 m apart
  for (int i = 0; i < 4; ++i) pts.emplace_back(100.0 + i * 1.5, 50.0);  // 1.5 m apart
  pts.emplace_back(-50.0, -50.0);                                       // alone
  const DbscanResult r = dbscan(pts, 2.0, 3);
  EXPECT_EQ(r.clusters, 2);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r.label[static_cast<std::size_t>(i)], 0);
  for (int i = 5; i < 9; ++i) EXPECT_EQ(r.label[static_cast<std::size_t>(i)], 1);
  EXPECT_EQ(r.label[9], -1);
}

TEST(Dbscan, EndPointsJoinAsBorderPointsAndTooFewNeighboursIsNoise) {
  // at eps 1.1 and min 3, points 1 and 2 are core (3 neighbours each), 0 and 3 only border
  const std::vector<Point2> pts = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  const DbscanResult r = dbscan(pts, 1.1, 3);
  EXPECT_EQ(r.clusters, 1);
  EXPECT_EQ(r.label, (std::vector<int>{0, 0, 0, 0}));
  const DbscanResult strict = dbscan(pts, 1.1, 4);
  EXPECT_EQ(strict.clusters, 0);
  EXPECT_EQ(strict.label, (std::vector<int>{-1, -1, -1, -1}));
  EXPECT_THROW(dbscan(pts, 0.0, 2), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::explore
