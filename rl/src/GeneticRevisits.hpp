#pragma once
// Private helper: the lower level of `aco-ga` (paper §3.2.2). A chromosome holds one bit per
// coverage leg of the ACO tour: 1 = drive a loop-closure revisit after that leg (to the place
// the switching walk considered there). Fitness: routes that keep C_k <= C_threshold all along
// come first, by total length; the others by length plus a penalty on how far they exceed it. The
// first chromosomes are the switching schedule and the exhaustive one (the paper's N1 and N2), so
// the result is never longer than switching when switching keeps the bound.
#include <cstdint>
#include <vector>

#include "RevisitWalk.hpp"
#include "slamroute/rl/CoverageConfig.hpp"

namespace slamroute::rl::detail {

struct GeneticResult {
  WalkResult best;
  int generations_run = 0, evaluations = 0;
  int improved_at_generation = 0;  ///< generation of the last improvement of the best
  double seed_length_m = 0.0;      ///< length of the switching schedule it started from [m]
};

/// `targets[j]`: the revisit edge after city index j (-1: none possible there);
/// `switching`: the switching walk's revisit positions (city indices).
GeneticResult geneticRevisits(const CoverageProblem& p, const std::vector<int>& targets,
                              const WalkResult& switching, const GeneticConfig& cfg,
                              std::uint64_t seed);

}  // namespace slamroute::rl::detail
