#pragma once
// Synthetic city-like road graphs of a chosen size, for planning benchmarks and the paper's
// Table 3 (planning time vs number of nodes): a perturbed grid of two-way streets with a few
// streets removed (keeping it strongly connected) and random edge weights.
#include <cstdint>

#include "slamroute/core/RoadGraph.hpp"

namespace slamroute {

struct SyntheticCityConfig {
  int nodes = 100;                  ///< number of junctions (rounded to a near-square grid)
  double block_m = 150.0;           ///< mean block length [m]
  double jitter_m = 25.0;           ///< junction position noise [m]
  double removed_street_share = 0.15;  ///< share of streets left out (only where safe)
};

/// Deterministic for a given seed. Unrestricted turns (like a trace-built graph).
RoadGraph syntheticCity(const SyntheticCityConfig& cfg, std::uint64_t seed);

}  // namespace slamroute
