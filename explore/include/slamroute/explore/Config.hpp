#pragma once
// Settings of `slamroute explore` (YAML section "explore:"): the shared occupancy grid, the
// sparse LiDAR that feeds it, the GP frontier map (Table 1 of the GP frontier seed paper), the
// DBSCAN / grouping of the fleet strategy and the online loop's limits.
#include <string>

namespace slamroute::explore {

/// Occupancy grid of the drivable area, fed by the simulated LiDAR at the poses `map_poses` picks.
struct GridConfig {
  double cell_m = 2.0;         ///< cell edge [m]
  double max_range_m = 40.0;   ///< returns farther than this are ignored [m]
  double ground_tol_m = 0.35;  ///< a return this high above the road under the vehicle is ground
  double ground_grade = 0.03;  ///< ... plus this much per metre of distance (slopes) [m/m]
  double margin_m = 60.0;      ///< the grid reaches this far beyond the net's bounds [m]
};
template <class V>
void visitFields(V& v, GridConfig& c) {
  v.field("cell_m", c.cell_m, "occupancy cell edge [m]");
  v.field("max_range_m", c.max_range_m, "LiDAR returns beyond this are ignored [m]");
  v.field("ground_tol_m", c.ground_tol_m, "returns this high above the road are ground [m]");
  v.field("ground_grade", c.ground_grade, "extra ground tolerance per metre of range [m/m]");
  v.field("margin_m", c.margin_m, "grid margin around the net [m]");
}

/// The sparse sensor of the exploring vehicles: a preset with fewer columns, one sweep every
/// scan_spacing_m driven (the grid needs far fewer rays than SLAM).
struct SensorConfig {
  std::string preset = "vlp16";
  int horizontal_samples = 360;  ///< columns per sweep (vlp16 has 1800)
  double scan_spacing_m = 8.0;   ///< one sweep per this much driven [m]
};
template <class V>
void visitFields(V& v, SensorConfig& c) {
  v.field("preset", c.preset, "LiDAR preset (paper | vlp16 | hdl32)");
  v.field("horizontal_samples", c.horizontal_samples, "columns per sweep");
  v.field("scan_spacing_m", c.scan_spacing_m, "one sweep per this distance driven [m]");
}

/// GP occupancy with the local-kernel approximation and the frontier probability (eq. 11);
/// defaults are the seed paper's Table 1 (kernel 11 x 11 cells).
struct GpConfig {
  double signal_var = 0.434;         ///< sigma_f^2
  double length_scale_cells = 3.26;  ///< rho, in cells
  double noise_var = 0.05;           ///< sigma_n^2
  double gamma = 2.0;                ///< logistic weight (eq. 6)
  double beta = 4.0;                 ///< occupied boundary factor (eq. 11)
  int kernel_cells = 11;             ///< local kernel edge (odd)
  double p_emp = 0.1;                ///< training value of a free cell
  double p_non_emp = 0.5;            ///< training value of any other cell (= p_unknown)
  double distance_scale_m = 400.0;   ///< gp-frontier: score = p_frontier * exp(-d / this) [m]
};
template <class V>
void visitFields(V& v, GpConfig& c) {
  v.field("signal_var", c.signal_var, "Matern 3/2 signal variance sigma_f^2");
  v.field("length_scale_cells", c.length_scale_cells, "Matern length scale rho [cells]");
  v.field("noise_var", c.noise_var, "noise variance sigma_n^2");
  v.field("gamma", c.gamma, "logistic regression weight");
  v.field("beta", c.beta, "occupied boundary factor of the frontier probability");
  v.field("kernel_cells", c.kernel_cells, "local kernel edge, odd [cells]");
  v.field("p_emp", c.p_emp, "training value of a free cell");
  v.field("p_non_emp", c.p_non_emp, "training value of an occupied or unknown cell");
  v.field("distance_scale_m", c.distance_scale_m, "gp-frontier distance discount [m]");
}

/// The fleet strategy (swarm seed paper): DBSCAN of frontier points, groups of vehicles.
struct FleetConfig {
  double dbscan_eps_m = 12.0;  ///< neighbourhood radius [m]
  int dbscan_min_points = 2;   ///< core point threshold (itself included)
  int group_size = 2;          ///< vehicles per group (leader + followers)
};
template <class V>
void visitFields(V& v, FleetConfig& c) {
  v.field("dbscan_eps_m", c.dbscan_eps_m, "DBSCAN radius [m]");
  v.field("dbscan_min_points", c.dbscan_min_points, "DBSCAN core point threshold");
  v.field("group_size", c.group_size, "vehicles per group");
}

struct Config {
  GridConfig grid;
  SensorConfig sensor;
  GpConfig gp;
  FleetConfig fleet;
  double step_length_s = 0.5;   ///< SUMO step [s]
  double depart_gap_s = 4.0;    ///< vehicles sharing a start edge leave this far apart [s]
  double speed_factor = 1.0;    ///< vehicles drive at this share of the speed limit
  double max_time_s = 36000.0;  ///< simulated time limit [s]
  /// Poses the scans enter the grid at: `truth` (the simulator's) or `slam` (each vehicle's own
  /// online estimate, wheel odometry + gyro dead reckoning with simulate.drive's errors).
  std::string map_poses = "truth";
  /// `evaluate`'s map completeness: grid cells this near a street are measured [m]
  double completeness_radius_m = 30.0;
  void validate() const;
};
template <class V>
void visitFields(V& v, Config& c) {
  v.section("grid", c.grid);
  v.section("sensor", c.sensor);
  v.section("gp", c.gp);
  v.section("fleet", c.fleet);
  v.field("step_length_s", c.step_length_s, "SUMO step [s]");
  v.field("depart_gap_s", c.depart_gap_s, "departure gap of vehicles on one start edge [s]");
  v.field("speed_factor", c.speed_factor, "share of the speed limit driven");
  v.field("max_time_s", c.max_time_s, "simulated time limit [s]");
  v.field("map_poses", c.map_poses,
          "scans enter the grid at the true poses (truth) or the vehicles' dead reckoning (slam)");
  v.field("completeness_radius_m", c.completeness_radius_m,
          "evaluate's map completeness: cells this near a street are measured [m]");
}

}  // namespace slamroute::explore
