// FleetConfig::validate(): a fleet needs at least one vehicle and a known strategy.
#include "slamroute/rl/FleetConfig.hpp"
#include "slamroute/core/ConfigCheck.hpp"

namespace slamroute::rl {

void FleetConfig::validate() const {
  config::requireRange("vehicles", vehicles, 1, 1000);
  if (strategy != "partition" && strategy != "postman")
    config::rejectValue("strategy", strategy, "partition or postman");
  config::requireRange("balance_moves", balance_moves, 0, 1000000);
  config::requireRange("candidates_per_move", candidates_per_move, 1, 100000);
  config::requireRange("kmeans_iterations", kmeans_iterations, 1, 100000);
  config::requireRange("merge_budget", merge_budget, 0, 1000000);
  config::requireRange("kick_rounds", kick_rounds, 0, 100000);
  config::requireRange("kick_budget", kick_budget, 0, 2000000000);
}

}  // namespace slamroute::rl
