#pragma once
// The swarm seed paper's frontier assignment (Strategies.hpp: `fleet`, `central`).
#include <cstdint>
#include <memory>

#include "slamroute/explore/Strategies.hpp"

namespace slamroute::explore {

/// Groups of `group_size` vehicles (vehicle i in group i / group_size, its first member leads).
std::unique_ptr<Strategy> makeFleetStrategy(const FleetConfig& cfg, int group_size,
                                            std::uint64_t seed);

}  // namespace slamroute::explore
