// The shared occupancy grid: ground / obstacle from returns, free space along the beams,
// frontier cells where ground meets unknown.
#include <gtest/gtest.h>

#include "slamroute/explore/OccupancyGrid.hpp"

namespace slamroute::explore {
namespace {

TEST(OccupancyGrid, ReturnsMarkGroundObstacleAndTheBeamCellsFree) {
  OccupancyGrid grid({0, 0}, {20, 10}, 1.0);  // 20 x 10 cells
  const Point3 sensor(2.5, 5.5, 1.8);
  // a ground return 6 m east, a wall return 10 m east, a return beyond the range
  const std::vector<Point3> pts = {{8.5, 5.5, 0.05}, {12.5, 5.5, 1.0}, {19.5, 5.5, 0.0}};
  grid.addScan(pts, sensor, 0.0, 12.0, 0.35, 0.0);
  EXPECT_EQ(grid.at(*grid.cellOf(8.5, 5.5)), Cell::Ground);
  EXPECT_EQ(grid.at(*grid.cellOf(12.5, 5.5)), Cell::Obstacle);
  for (double x : {3.5, 6.5, 11.5}) EXPECT_EQ(grid.at(*grid.cellOf(x, 5.5)), Cell::Ground) << x;
  EXPECT_EQ(grid.at(*grid.cellOf(19.5, 5.5)), Cell::Unknown);  // beyond max range
  EXPECT_EQ(grid.at(*grid.cellOf(2.5, 6.5)), Cell::Unknown);
  // an obstacle is never turned back into ground by a later beam through it
  grid.addScan({{14.5, 5.5, 0.0}}, sensor, 0.0, 20.0, 0.35, 0.0);
  EXPECT_EQ(grid.at(*grid.cellOf(12.5, 5.5)), Cell::Obstacle);
  EXPECT_EQ(grid.countOf(Cell::Obstacle), 1u);
}

TEST(OccupancyGrid, FrontiersAreGroundCellsNextToUnknownOnes) {
  OccupancyGrid grid({0, 0}, {10, 10}, 1.0);
  std::vector<int> changed;
  for (int r = 0; r < 10; ++r)
    for (int c = 0; c < 4; ++c)
      if (grid.mark(r * 10 + c, Cell::Ground)) changed.push_back(r * 10 + c);
  grid.updateFrontiers(changed);
  // the known strip is columns 0..3: its frontier is column 3 (column 4 unknown)
  ASSERT_EQ(grid.frontiers().size(), 10u);
  for (int f : grid.frontiers()) EXPECT_EQ(grid.col(f), 3);
  // seeing column 4 as obstacle closes the frontier (an obstacle is no unknown)
  changed.clear();
  for (int r = 0; r < 10; ++r)
    if (grid.mark(r * 10 + 4, Cell::Obstacle)) changed.push_back(r * 10 + 4);
  grid.updateFrontiers(changed);
  EXPECT_TRUE(grid.frontiers().empty());
}

TEST(OccupancyGrid, RejectsBadGeometry) {
  EXPECT_THROW(OccupancyGrid({0, 0}, {10, 10}, 0.0), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid({0, 0}, {0, 10}, 1.0), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid({0, 0}, {1e6, 1e6}, 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::explore
