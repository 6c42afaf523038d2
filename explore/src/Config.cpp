// Config::validate: every explore setting checked once when loaded.
#include "slamroute/explore/Config.hpp"

#include "slamroute/core/ConfigCheck.hpp"

namespace slamroute::explore {

void Config::validate() const {
  using namespace config;
  requirePositive("grid.cell_m", grid.cell_m, 50.0);
  requirePositive("grid.max_range_m", grid.max_range_m, 1000.0);
  requireNonNegative("grid.ground_tol_m", grid.ground_tol_m, 5.0);
  requireNonNegative("grid.ground_grade", grid.ground_grade, 1.0);
  requireNonNegative("grid.margin_m", grid.margin_m, 10000.0);
  requireRange("sensor.horizontal_samples", sensor.horizontal_samples, 8, 100000);
  requirePositive("sensor.scan_spacing_m", sensor.scan_spacing_m, 1000.0);
  requirePositive("gp.signal_var", gp.signal_var, 100.0);
  requirePositive("gp.length_scale_cells", gp.length_scale_cells, 100.0);
  requirePositive("gp.noise_var", gp.noise_var, 100.0);
  requirePositive("gp.gamma", gp.gamma, 100.0);
  requireNonNegative("gp.beta", gp.beta, 100.0);
  requireRange("gp.kernel_cells", gp.kernel_cells, 3, 51);
  if (gp.kernel_cells % 2 == 0) rejectValue("gp.kernel_cells", gp.kernel_cells, "odd");
  requireRange("gp.p_emp", gp.p_emp, 0.0, 1.0);
  requireRange("gp.p_non_emp", gp.p_non_emp, 0.0, 1.0);
  if (!(gp.p_emp < gp.p_non_emp)) rejectValue("gp.p_emp", gp.p_emp, "< gp.p_non_emp");
  requirePositive("gp.distance_scale_m", gp.distance_scale_m);
  requirePositive("fleet.dbscan_eps_m", fleet.dbscan_eps_m, 10000.0);
  requireRange("fleet.dbscan_min_points", fleet.dbscan_min_points, 1, 1000);
  requireRange("fleet.group_size", fleet.group_size, 1, 100);
  requirePositive("step_length_s", step_length_s, 10.0);
  requireNonNegative("depart_gap_s", depart_gap_s, 600.0);
  requirePositive("speed_factor", speed_factor, 3.0);
  requirePositive("max_time_s", max_time_s, 1e7);
  requirePositive("completeness_radius_m", completeness_radius_m, 1000.0);
  if (map_poses != "truth" && map_poses != "slam")
    rejectValue("map_poses", map_poses, "truth | slam");
}

}  // namespace slamroute::explore
