#pragma once
// Synthetic city-like road graphs with known structure, for tests and benchmarks.
#include <cstdint>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/rl/Config.hpp"

namespace slamroute::rl {

struct GridCitySpec {
  int rows = 3, cols = 3;         ///< junctions per side
  double spacing_m = 100.0;       ///< block size [m]
  double jitter_m = 0.0;          ///< random junction displacement [m]
  double one_way_fraction = 0.0;  ///< share of streets kept in one direction only
  bool forbid_u_turns = false;    ///< restricted turns: no U-turn except at dead ends
  double weight_min = 1.0;        ///< edge weights drawn uniformly in [weight_min, 1]
  std::uint64_t seed = 1;
};

/// rows x cols grid of two-way (or one-way) streets. Edge lengths are the straight distances.
RoadGraph gridCity(const GridCitySpec& spec);

/// The EIF motion noise the grid worlds standing for Gong & Lee's environments use (their
/// bounds in tests and bench_aco_ga were set for it): heading-dominated, so C_k grows with the
/// cube of the distance and a 100 m block matters. rl.eif's defaults are fitted to our SLAM on
/// a whole city instead (Config.hpp).
inline EifConfig gridWorldNoise() {
  EifConfig c;
  c.long_var_per_m = 1e-3;
  c.lat_var_per_m = 5e-4;
  c.heading_var_per_m = 2e-6;
  c.poor_weight_gain = 4.0;
  return c;
}

}  // namespace slamroute::rl
