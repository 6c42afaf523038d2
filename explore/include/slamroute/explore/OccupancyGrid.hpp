#pragma once
// The fleet's shared occupancy grid of the ground: each cell is unknown, ground (free, seen
// flat at road level) or obstacle (a return above the road). A LiDAR return is ground when it
// lies within a tolerance of the road height under the vehicle; the cells its beam crossed
// before it (in the plane) are free as in a 2D occupancy grid. An obstacle cell stays one. A
// frontier cell is a ground cell with an unknown 8-neighbour; the set of frontier cells is kept
// up to date as scans come in (only changed cells and their neighbours are re-examined).
#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute::explore {

enum class Cell : std::uint8_t { Unknown = 0, Ground = 1, Obstacle = 2 };

class OccupancyGrid {
 public:
  /// Covers [min, max] (net frame) with square cells of cell_m. Throws std::invalid_argument
  /// when cell_m <= 0 or the box is empty or larger than 50 million cells.
  OccupancyGrid(const Point2& min, const Point2& max, double cell_m);

  int width() const { return w_; }
  int height() const { return h_; }
  double cellSize() const { return cell_m_; }
  std::size_t size() const { return cells_.size(); }
  /// Index of the cell containing (x, y), nullopt outside the grid.
  std::optional<int> cellOf(double x, double y) const;
  Point2 centre(int idx) const;
  int col(int idx) const { return idx % w_; }
  int row(int idx) const { return idx / w_; }
  bool inside(int col, int row) const { return col >= 0 && row >= 0 && col < w_ && row < h_; }
  Cell at(int idx) const { return cells_[static_cast<std::size_t>(idx)]; }
  Cell atColRow(int col, int row) const {
    return inside(col, row) ? at(row * w_ + col) : Cell::Unknown;
  }

  /// Sets a cell (an obstacle is never turned back to ground); returns true when it changed.
  bool mark(int idx, Cell c);
  /// Adds one sweep: `points` are world positions of the returns, `sensor` where they were seen
  /// from, `road_z` the road height under the vehicle. Returns the cells that changed.
  std::vector<int> addScan(const std::vector<Point3>& points, const Point3& sensor, double road_z,
                           double max_range_m, double ground_tol_m, double ground_grade);

  bool isFrontier(int idx) const;
  /// Frontier cells in index order.
  const std::set<int>& frontiers() const { return frontiers_; }
  /// Re-examines the given cells and their 8-neighbours for the frontier set.
  void updateFrontiers(const std::vector<int>& changed);
  std::size_t countOf(Cell c) const;

 private:
  void carveFree(int c0, int r0, int c1, int r1, std::vector<int>& changed);
  Point2 min_;
  double cell_m_;
  int w_ = 0, h_ = 0;
  std::vector<Cell> cells_;
  std::set<int> frontiers_;
};

}  // namespace slamroute::explore
