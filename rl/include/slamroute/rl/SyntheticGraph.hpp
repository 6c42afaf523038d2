#pragma once
// Synthetic city-like road graphs with known structure, for tests and benchmarks.
#include <cstdint>

#include "slamroute/core/RoadGraph.hpp"

namespace slamroute::rl {

struct GridCitySpec {
  int rows = 3, cols = 3;          ///< junctions per side
  double spacing_m = 100.0;        ///< block size [m]
  double jitter_m = 0.0;           ///< random junction displacement [m]
  double one_way_fraction = 0.0;   ///< share of streets kept in one direction only
  bool forbid_u_turns = false;     ///< restricted turns: no U-turn except at dead ends
  double weight_min = 1.0;         ///< edge weights drawn uniformly in [weight_min, 1]
  std::uint64_t seed = 1;
};

/// rows x cols grid of two-way (or one-way) streets. Edge lengths are the straight distances.
RoadGraph gridCity(const GridCitySpec& spec);

}  // namespace slamroute::rl
