#pragma once
// Pairwise consistency of loop closures (the idea of PCM, Mangelson et al. 2018, on consecutive
// closures): a new closure and the one accepted before it, joined by the keyframe chain between
// their old keyframes and the one between their new keyframes, form a cycle. On two true
// closures it ends where it started, up to the drift of those chains; a match one facade along a
// row of look-alikes breaks it by that offset, however well it fits.
#include "KeyframeGraph.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate::slam {

struct ClosureCycle {
  double error_m = 0.0;  ///< from where the cycle puts the newest keyframe to the match [m]
  double chain_m = 0.0;  ///< keyframe path of the two chains [m]
};

/// The cycle of `before` (an accepted closure) with a match that puts the newest keyframe of
/// `graph` at `T_world_new` against old keyframe `old_kf`.
ClosureCycle closureCycle(const KeyframeGraph& graph, const LoopClosure& before, int old_kf,
                          const Pose3& T_world_new);

/// The cycle closes within loop.consistency_m + loop.consistency_per_m x its chains (always
/// true when loop.consistency_m < 0).
bool consistentCycle(const ClosureCycle& cycle, const LoopConfig& cfg);

}  // namespace slamroute::evaluate::slam
