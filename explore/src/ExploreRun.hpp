#pragma once
// The online loop of runExplore (Explore.hpp), split out so its steps read as methods.
#include <chrono>
#include <map>
#include <memory>
#include <optional>

#include "DeadReckoning.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/explore/Explore.hpp"
#include "slamroute/explore/Measures.hpp"
#include "slamroute/explore/OccupancyGrid.hpp"
#include "slamroute/explore/Strategies.hpp"
#include "slamroute/explore/StreetMap.hpp"
#include "slamroute/rl/PlanGraph.hpp"
#include "slamroute/simulate/Lidar.hpp"
#include "slamroute/simulate/OnlineVehicles.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::explore {

class ExploreRun {
 public:
  ExploreRun(const ExploreOptions& opts, const Config& cfg, const simulate::WorldConfig& world,
             const simulate::DriveConfig& drive);
  /// Drives until every directed street is driven, nothing known is left, or the time limit.
  ExploreResult run();
  /// The offline fleet plan from the vehicles' starts (Measures.hpp).
  OfflineBound offlineBound() const;

 private:
  struct Explorer {
    std::string id;
    int edge = -1;              ///< PlanGraph edge it is on
    std::vector<int> route;     ///< the route SUMO has: edge, chosen turn, provisional ones
    double last_scan_m = -1e9;  ///< odometer at the last sweep [m]
    double odometer_m = 0.0;
    Point2 pos = Point2::Zero();                  ///< where it is (its start before it departs)
    bool idle = false;                            ///< the last decision found nothing to do
    bool settled = false;                         ///< idle through a whole street
    std::optional<DeadReckoning> dead_reckoning;  ///< its pose estimate (map_poses: slam)
    VehicleResult result;
  };

  std::vector<int> startEdges() const;
  void depart(simulate::OnlineVehicles& vehicles);
  void follow(simulate::OnlineVehicles& vehicles, int k);
  void scan(int k, const simulate::OnlineVehicleState& s, const Pose3& sensor);
  void enterEdge(simulate::OnlineVehicles& vehicles, int k, int at, int edge, double t);
  void passUnseen(simulate::OnlineVehicles& vehicles, int k, int at, double t);
  void sendRoute(simulate::OnlineVehicles& vehicles, int k, double t);
  int chooseNext(int k);
  int wander(int e, const std::vector<int>& planned) const;
  /// Bookkeeping of the street `edge` being entered (the previous one counts as driven).
  void advance(int k, int edge, double t);
  const std::string& sumoEdge(int e) const;
  void recordDriven(int edge, double t);
  bool finished() const;
  FleetView view() const;

  ExploreOptions opts_;
  Config cfg_;
  simulate::DriveConfig drive_;
  SumoNet net_;
  RoadGraph graph_;
  rl::PlanGraph pg_;
  std::map<std::string, int> edge_of_;  ///< SUMO edge -> PlanGraph edge
  simulate::World world_;
  simulate::Lidar lidar_;
  OccupancyGrid grid_;
  StreetMap streets_;
  std::unique_ptr<Strategy> strategy_;
  std::vector<Explorer> explorers_;
  std::vector<bool> driven_;      ///< entered (being or been driven)
  std::vector<int> drive_count_;  ///< times completed
  std::vector<int> targets_;
  ExploreResult result_;
  int entered_ = 0;  ///< streets entered at least once
  std::size_t scans_ = 0;
  double t0_ = -1.0;  ///< first departure [s]
};

/// Bounding box of the net's drivable streets, grown by `margin_m`.
std::pair<Point2, Point2> streetBounds(const RoadGraph& g, double margin_m);

}  // namespace slamroute::explore
