#pragma once
// PlannerStats as route.json's "extra" object (Plan.cpp adds the planning graph and checks).
#include <nlohmann/json.hpp>

#include "slamroute/rl/PlannerStats.hpp"

namespace slamroute::rl {

/// The planner's figures as a JSON object ({} for none).
nlohmann::json plannerStatsJson(const PlannerStats& stats);

}  // namespace slamroute::rl
