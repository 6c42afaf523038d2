#pragma once
// `slamroute explore`: K vehicles enter a city they know nothing of and drive in one SUMO
// session, each choosing its next turn online when it enters a street (Strategies.hpp). They see
// the world (the procedural 3D city) with a sparse simulated LiDAR, at their true poses or their
// own dead-reckoned estimates (Config::map_poses), and share
// one occupancy grid (OccupancyGrid.hpp); the streets they know are the ones seen there
// (StreetMap.hpp) and they plan only over those. The goal is to drive every directed street of
// the net's largest legally drivable part (the PlanGraph edges).
//
// DIR receives
//   driven.rou.xml  one vehicle per explorer with the route it actually drove (SUMO format)
//   explore.json    per vehicle and for the fleet: distance and simulated time until 90 / 95 /
//                   100 % of the directed streets were driven; the offline fleet bound; the
//                   coverage curve; decisions made (same seed, same bytes)
//   coverage.png    the exploration curve: share of directed streets driven against time
//   timing.json     compute time per decision (wall clock, so not reproducible)
// Everything is written to a hidden folder beside DIR and moved in at the end.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/explore/Config.hpp"
#include "slamroute/explore/OccupancyGrid.hpp"
#include "slamroute/simulate/DriveConfig.hpp"
#include "slamroute/simulate/WorldConfig.hpp"

namespace slamroute::explore {

struct ExploreOptions {
  std::filesystem::path net;
  int vehicles = 1;
  std::string strategy = "nearest";
  std::filesystem::path out_dir;
  /// Start edge per vehicle (SUMO ids); fewer than `vehicles`: the rest start on the last one
  /// given (one departure gap apart); empty: all on the first edge of the drivable part.
  std::vector<std::string> start_edges;
  std::uint64_t seed = 42;
};

/// Distance and time when a share of the directed streets had been driven.
struct Milestone {
  double share = 0.0;
  bool reached = false;
  double time_s = 0.0;            ///< simulated time since the first departure [s]
  double fleet_distance_m = 0.0;  ///< summed over the vehicles [m]
  std::vector<double> vehicle_distance_m;
};

struct CoverageSample {
  double time_s = 0.0;
  double fleet_distance_m = 0.0;
  std::vector<double> vehicle_distance_m;
  int edges_driven = 0;
};

struct VehicleResult {
  std::string id;
  std::vector<std::string> edges;  ///< SUMO edges in the order driven
  double depart_s = 0.0;
  double distance_m = 0.0;
  int decisions = 0;
};

struct ExploreResult {
  std::string strategy;
  int total_edges = 0;  ///< directed streets to drive
  int edges_driven = 0;
  double end_time_s = 0.0;
  bool time_limit_hit = false;
  std::vector<VehicleResult> vehicles;
  std::vector<Milestone> milestones;  ///< 0.90, 0.95, 1.00
  std::vector<CoverageSample> curve;
  double offline_bound_m = 0.0;     ///< offline fleet plan, summed route length [m]
  double offline_makespan_m = 0.0;  ///< offline fleet plan, longest route [m]
  int decisions = 0;
  std::vector<double> decision_ms;  ///< compute time per decision [ms]
  int grid_cells_known = 0, streets_known = 0;
  std::vector<Cell> grid;  ///< the shared grid at the end (OccupancyGrid's order)
};

/// Runs the exploration and writes DIR. Throws std::invalid_argument on bad options (unknown
/// strategy, K < 1, a start edge outside the drivable part), std::runtime_error when SUMO fails.
/// drive: the odometry errors of the dead reckoning when cfg.map_poses is `slam`.
ExploreResult runExplore(const ExploreOptions& opts, const Config& cfg,
                         const simulate::WorldConfig& world, const simulate::DriveConfig& drive);

}  // namespace slamroute::explore
