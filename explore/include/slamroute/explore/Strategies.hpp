#pragma once
// How a vehicle that just entered a street chooses where to go next (`--strategy`):
//   nearest      the nearest open street by known legal path;
//   gp-frontier  open streets ranked by their GP frontier probability (GpFrontier.hpp), max over
//                their frontier cells, discounted by the known path length;
//   fleet        swarm seed paper: DBSCAN segments of the frontier points, segments assigned to
//                groups of vehicles by the Hungarian algorithm with cost D_ij / W_j (distance from
//                the group leader to the segment's centre over its number of points), the largest
//                segment split by K-means while there are fewer segments than groups, K-means
//                waypoints inside a group (the waypoint nearest their mean to the leader, the
//                rest by a Hungarian assignment on distance);
//   central      the same with every vehicle its own group (the paper's centralised baseline);
//   siba         SIBA adapted to streets: take the rightmost offered turn onto an open street
//                (sweeping around blocks the same way), else the shortest known path to the
//                nearest open street.
// An open street is known, not yet driven and not another vehicle's target. Once no frontier
// point remains, fleet and central cluster the midpoints of the open streets instead.
#include <memory>
#include <string>
#include <vector>

#include "slamroute/explore/Config.hpp"
#include "slamroute/explore/OccupancyGrid.hpp"
#include "slamroute/explore/StreetMap.hpp"
#include "slamroute/rl/PlanGraph.hpp"

namespace slamroute::explore {

struct VehicleView {
  int edge = -1;  ///< PlanGraph edge it is on, -1 when not (yet) in the net
  Point2 pos = Point2::Zero();
};

struct FleetView {
  const rl::PlanGraph& pg;
  const StreetMap& streets;
  const OccupancyGrid& grid;
  const std::vector<bool>& driven;  ///< per edge: driven or being driven
  std::vector<VehicleView> vehicles;
  std::vector<int> targets;  ///< current target edge per vehicle, -1 none
  /// Known, not driven and not the target of a vehicle other than `k`.
  bool open(int edge, int k) const;
};

struct Decision {
  std::vector<int> path;  ///< edges to drive after the current one (empty: nothing to do)
  int target = -1;
};

class Strategy {
 public:
  virtual ~Strategy() = default;
  /// Vehicle k has just entered vehicles[k].edge and must choose its next turn.
  virtual Decision decide(const FleetView& f, int k) = 0;
};

/// nearest | gp-frontier | fleet | central | siba. Throws std::invalid_argument on others.
std::unique_ptr<Strategy> makeStrategy(const std::string& name, const Config& cfg,
                                       std::uint64_t seed);
const std::vector<std::string>& strategyNames();

/// The path to the nearest open street from vehicle k (shared fallback of every strategy).
Decision nearestOpen(const FleetView& f, int k);

}  // namespace slamroute::explore
