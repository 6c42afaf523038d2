#pragma once
// Private: LEMON's symmetric TSP heuristics behind a plain interface. LemonTsp.cpp is compiled
// as C++17 because LEMON 1.3's ArrayMap uses std::allocator::construct/destroy (removed in C++20).
#include <vector>

namespace slamroute::rl::detail {

/// Tour over all nodes of d (symmetrised as (d_ij + d_ji)/2): Christofides (or greedy when
/// christofides is false) improved by 2-opt. Returns a node order (each node once).
std::vector<int> lemonTour(const std::vector<std::vector<double>>& d, bool christofides);

}  // namespace slamroute::rl::detail
