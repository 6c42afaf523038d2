#pragma once
// The planners index their vectors with the int ids of PlanGraph (nodes, edges, turns).
#include <cstddef>

namespace slamroute::rl {

/// An int id as a vector index.
inline std::size_t sz(int i) { return static_cast<std::size_t>(i); }

}  // namespace slamroute::rl
