// StreetMap: directed streets over the occupancy grid; known / fully seen / frontier streets.
#include "slamroute/explore/StreetMap.hpp"

#include <algorithm>
#include <cmath>

namespace slamroute::explore {
namespace {

/// Distinct grid cells along a polyline, sampled every `step` metres, in driving order.
std::vector<int> cellsAlong(const Polyline& pl, const OccupancyGrid& grid, double step) {
  std::vector<int> out;
  auto add = [&](const Point3& p) {
    const auto c = grid.cellOf(p.x(), p.y());
    if (c && std::find(out.begin(), out.end(), *c) == out.end()) out.push_back(*c);
  };
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
    const double len = (pl[i + 1] - pl[i]).head<2>().norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    for (int k = 0; k < n; ++k) add(pl[i] + (pl[i + 1] - pl[i]) * (static_cast<double>(k) / n));
  }
  if (!pl.empty()) add(pl.back());
  return out;
}

Point2 halfway(const Polyline& pl) {
  if (pl.empty()) return Point2::Zero();
  double rest = polylineLength(pl) / 2.0;
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
    const double len = (pl[i + 1] - pl[i]).norm();
    if (rest <= len && len > 0) return (pl[i] + (pl[i + 1] - pl[i]) * (rest / len)).head<2>();
    rest -= len;
  }
  return pl.back().head<2>();
}

}  // namespace

StreetMap::StreetMap(const rl::PlanGraph& pg, const RoadGraph& g, const OccupancyGrid& grid)
    : grid_(grid),
      cells_(static_cast<std::size_t>(pg.m)),
      seen_(static_cast<std::size_t>(pg.m), 0),
      offered_(static_cast<std::size_t>(pg.m), false),
      mid_(static_cast<std::size_t>(pg.m)) {
  for (int e = 0; e < pg.m; ++e) {
    const Polyline& pl =
        g.edges[static_cast<std::size_t>(pg.edge_orig[static_cast<std::size_t>(e)])].polyline;
    cells_[static_cast<std::size_t>(e)] = cellsAlong(pl, grid, grid.cellSize() / 2.0);
    mid_[static_cast<std::size_t>(e)] = halfway(pl);
    for (int c : cells_[static_cast<std::size_t>(e)]) {
      edges_at_[c].push_back(e);
      if (grid.at(c) == Cell::Ground) ++seen_[static_cast<std::size_t>(e)];
    }
  }
}

void StreetMap::update(const std::vector<int>& changed_cells) {
  for (int c : changed_cells) {
    if (grid_.at(c) != Cell::Ground) continue;
    const auto it = edges_at_.find(c);
    if (it == edges_at_.end()) continue;
    for (int e : it->second) ++seen_[static_cast<std::size_t>(e)];
  }
}

bool StreetMap::fullySeen(int edge) const {
  const auto& cs = cells(edge);
  return std::none_of(cs.begin(), cs.end(), [&](int c) { return grid_.at(c) == Cell::Unknown; });
}

int StreetMap::numKnown() const {
  int n = 0;
  for (std::size_t e = 0; e < seen_.size(); ++e) n += known(static_cast<int>(e));
  return n;
}

std::vector<FrontierPoint> StreetMap::frontierPoints() const {
  std::vector<FrontierPoint> out;
  std::vector<int> near;
  for (int f : grid_.frontiers()) {
    near.clear();
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int c = grid_.col(f) + dc, r = grid_.row(f) + dr;
        if (!grid_.inside(c, r)) continue;
        const auto it = edges_at_.find(r * grid_.width() + c);
        if (it == edges_at_.end()) continue;
        for (int e : it->second)
          if (!fullySeen(e) && std::find(near.begin(), near.end(), e) == near.end())
            near.push_back(e);
      }
    std::sort(near.begin(), near.end());
    for (int e : near) out.push_back({f, e, grid_.centre(f)});
  }
  return out;
}

}  // namespace slamroute::explore
