// OccupancyGrid: ground / obstacle cells from LiDAR returns, free space carved along the beams,
// frontier cells kept incrementally.
#include "slamroute/explore/OccupancyGrid.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace slamroute::explore {

OccupancyGrid::OccupancyGrid(const Point2& min, const Point2& max, double cell_m)
    : min_(min), cell_m_(cell_m) {
  if (!(cell_m > 0.0)) throw std::invalid_argument("occupancy grid: cell size must be > 0");
  const double wx = (max.x() - min.x()) / cell_m, wy = (max.y() - min.y()) / cell_m;
  if (!(wx > 0.0 && wy > 0.0)) throw std::invalid_argument("occupancy grid: empty area");
  if (wx * wy > 5e7) throw std::invalid_argument("occupancy grid: more than 50 million cells");
  w_ = static_cast<int>(std::ceil(wx));
  h_ = static_cast<int>(std::ceil(wy));
  cells_.assign(static_cast<std::size_t>(w_) * static_cast<std::size_t>(h_), Cell::Unknown);
}

std::optional<int> OccupancyGrid::cellOf(double x, double y) const {
  const double fx = std::floor((x - min_.x()) / cell_m_), fy = std::floor((y - min_.y()) / cell_m_);
  if (!(fx >= 0 && fy >= 0 && fx < w_ && fy < h_)) return std::nullopt;
  return static_cast<int>(fy) * w_ + static_cast<int>(fx);
}

Point2 OccupancyGrid::centre(int idx) const {
  return {min_.x() + (col(idx) + 0.5) * cell_m_, min_.y() + (row(idx) + 0.5) * cell_m_};
}

bool OccupancyGrid::mark(int idx, Cell c) {
  Cell& cur = cells_[static_cast<std::size_t>(idx)];
  if (cur == c || cur == Cell::Obstacle || c == Cell::Unknown) return false;
  cur = c;
  return true;
}

// Cells strictly between (c0, r0) and (c1, r1) on a Bresenham line become ground unless known.
void OccupancyGrid::carveFree(int c0, int r0, int c1, int r1, std::vector<int>& changed) {
  const int dc = std::abs(c1 - c0), dr = -std::abs(r1 - r0);
  const int sc = c0 < c1 ? 1 : -1, sr = r0 < r1 ? 1 : -1;
  int err = dc + dr, c = c0, r = r0;
  while (c != c1 || r != r1) {
    if (inside(c, r) && at(r * w_ + c) == Cell::Unknown && mark(r * w_ + c, Cell::Ground))
      changed.push_back(r * w_ + c);
    const int e2 = 2 * err;
    if (e2 >= dr) {
      err += dr;
      c += sc;
    }
    if (e2 <= dc) {
      err += dc;
      r += sr;
    }
  }
}

std::vector<int> OccupancyGrid::addScan(const std::vector<Point3>& points, const Point3& sensor,
                                        double road_z, double max_range_m, double ground_tol_m,
                                        double ground_grade) {
  std::vector<int> changed;
  const auto from = cellOf(sensor.x(), sensor.y());
  if (!from) return changed;
  for (const Point3& p : points) {
    const double d = std::hypot(p.x() - sensor.x(), p.y() - sensor.y());
    if (d > max_range_m) continue;
    const auto to = cellOf(p.x(), p.y());
    if (!to) continue;
    carveFree(col(*from), row(*from), col(*to), row(*to), changed);
    const bool ground = p.z() - road_z <= ground_tol_m + ground_grade * d;
    if (mark(*to, ground ? Cell::Ground : Cell::Obstacle)) changed.push_back(*to);
  }
  updateFrontiers(changed);
  return changed;
}

bool OccupancyGrid::isFrontier(int idx) const {
  if (at(idx) != Cell::Ground) return false;
  const int c = col(idx), r = row(idx);
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      if ((dr || dc) && inside(c + dc, r + dr) && at((r + dr) * w_ + c + dc) == Cell::Unknown)
        return true;
  return false;
}

void OccupancyGrid::updateFrontiers(const std::vector<int>& changed) {
  for (int idx : changed) {
    const int c = col(idx), r = row(idx);
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        if (!inside(c + dc, r + dr)) continue;
        const int n = (r + dr) * w_ + c + dc;
        if (isFrontier(n))
          frontiers_.insert(n);
        else
          frontiers_.erase(n);
      }
  }
}

std::size_t OccupancyGrid::countOf(Cell c) const {
  std::size_t n = 0;
  for (Cell x : cells_) n += x == c;
  return n;
}

}  // namespace slamroute::explore
