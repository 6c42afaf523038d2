#pragma once
// Which streets the fleet knows: the directed streets (PlanGraph edges) laid over the occupancy
// grid, each as the cells its centreline runs through. A street is known once one of its cells
// has been seen as ground (the vehicles then know it exists and where it leads from) or SUMO
// offered it as a turn at a junction a vehicle is driving to; it is fully seen when all of them
// are. A frontier cell on (or next to) a street that is not fully seen marks where that street
// leaves the known area: the street is a frontier street.
#include <unordered_map>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/explore/OccupancyGrid.hpp"
#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::explore {

struct FrontierPoint {
  int cell = 0;  ///< grid cell index
  int edge = 0;  ///< PlanGraph edge the frontier lies on
  Point2 pos = Point2::Zero();
};

class StreetMap {
 public:
  /// Samples every edge's centreline at half a cell. Edges outside the grid get no cells.
  StreetMap(const rl::PlanGraph& pg, const RoadGraph& g, const OccupancyGrid& grid);

  /// Takes the cells a scan changed into account.
  void update(const std::vector<int>& changed_cells);
  bool known(int edge) const {
    return seen_[static_cast<std::size_t>(edge)] > 0 || offered_[static_cast<std::size_t>(edge)];
  }
  /// A street SUMO offers as a turn at a junction a vehicle is driving to is known whatever the
  /// grid saw (the driver sees the street's entry; the grid may not, e.g. under a parked car).
  void markOffered(int edge) { offered_[static_cast<std::size_t>(edge)] = true; }
  bool fullySeen(int edge) const;
  int numKnown() const;
  const std::vector<int>& cells(int edge) const { return cells_[static_cast<std::size_t>(edge)]; }
  /// Point halfway along the edge's centreline.
  const Point2& midpoint(int edge) const { return mid_[static_cast<std::size_t>(edge)]; }
  /// Frontier cells of the grid that lie on a street not yet fully seen (a frontier cell next to
  /// several such streets counts once per street), in cell order.
  std::vector<FrontierPoint> frontierPoints() const;

 private:
  const OccupancyGrid& grid_;
  std::vector<std::vector<int>> cells_;  ///< per edge, distinct cells along it
  std::vector<int> seen_;                ///< per edge, its cells seen as ground
  std::vector<bool> offered_;            ///< per edge, offered as a turn to a vehicle
  std::vector<Point2> mid_;
  std::unordered_map<int, std::vector<int>> edges_at_;  ///< cell -> edges running through it
};

}  // namespace slamroute::explore
