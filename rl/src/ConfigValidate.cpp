// validate() of the rl config sections: values with which a planner cannot work (a negative
// variance makes the filter's information NaN and the route unreadable; zero episodes learn
// nothing; an exact TSP above ~24 nodes needs more memory than a machine has).
#include "slamroute/core/ConfigCheck.hpp"
#include "slamroute/rl/Config.hpp"

namespace slamroute::rl {
using config::requireNonNegative;
using config::requirePositive;
using config::requireRange;

void EifConfig::validate() const {
  requirePositive("init_sigma_xy_m", init_sigma_xy_m, 1e4);
  requirePositive("init_sigma_heading_rad", init_sigma_heading_rad, 10.0);
  requireNonNegative("long_var_per_m", long_var_per_m, 1e4);
  requireNonNegative("lat_var_per_m", lat_var_per_m, 1e4);
  requireNonNegative("heading_var_per_m", heading_var_per_m, 10.0);
  requireNonNegative("poor_weight_gain", poor_weight_gain, 1e4);
  requirePositive("closure_sigma_xy_m", closure_sigma_xy_m, 1e4);
  requirePositive("closure_sigma_heading_rad", closure_sigma_heading_rad, 10.0);
  requireNonNegative("loop_min_travel_m", loop_min_travel_m, 1e7);
}

void QLearningConfig::validate() const {
  requireRange("episodes", episodes, 1, 10000000);
  requireRange("gamma", gamma, 0.0, 1.0);
  if (!(alpha > 0 && alpha <= 1)) config::rejectValue("alpha", alpha, "in (0, 1]");
  requireRange("epsilon_start", epsilon_start, 0.0, 1.0);
  requireRange("epsilon_end", epsilon_end, 0.0, 1.0);
  if (!(epsilon_decay_fraction > 0 && epsilon_decay_fraction <= 1))
    config::rejectValue("epsilon_decay_fraction", epsilon_decay_fraction, "in (0, 1]");
  requirePositive("max_steps_per_edge", max_steps_per_edge, 1e4);
  requireRange("signature_bits", signature_bits, 0, 6);
  requireNonNegative("weight_coverage", weight_coverage, 1e6);
  requireNonNegative("weight_accuracy", weight_accuracy, 1e6);
  requireNonNegative("weight_uncertainty", weight_uncertainty, 1e6);
  requireNonNegative("step_length_cost", step_length_cost, 1e6);
  requireNonNegative("uncertainty_clip", uncertainty_clip, 1e6);
  requireRange("stall_steps", stall_steps, 0, 1000000);
  requireNonNegative("guide_reward", guide_reward, 1e6);
}

void RandomConfig::validate() const {
  requirePositive("max_steps_per_edge", max_steps_per_edge, 1e6);
  requireNonNegative("budget_m", budget_m, 1e8);
}

void TspConfig::validate() const {
  requireRange("exact_max_nodes", exact_max_nodes, 0, 24);  // 2^23 * 24 * 8 B = 1.6 GB
  requireRange("christofides_max_nodes", christofides_max_nodes, 0, 100000);
  requireRange("max_nodes", max_nodes, 1, 100000);
}

void PostmanConfig::validate() const {
  requireRange("max_forcing_rounds", max_forcing_rounds, 0, 1000);
}

}  // namespace slamroute::rl
