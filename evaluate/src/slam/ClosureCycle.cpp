#include "ClosureCycle.hpp"

namespace slamroute::evaluate::slam {

ClosureCycle closureCycle(const KeyframeGraph& graph, const LoopClosure& before, int old_kf,
                          const Pose3& T_world_new) {
  const Keyframe& old_before = graph.at(static_cast<std::size_t>(before.from_keyframe));
  const Keyframe& new_before = graph.at(static_cast<std::size_t>(before.to_keyframe));
  // Old keyframe of `before`, its measured relative pose, then the chain of new keyframes since.
  const Pose3 carried =
      old_before.T_world * before.T_old_new * new_before.T_world.inverse() * graph.back().T_world;
  ClosureCycle c;
  c.error_m = (carried.translation() - T_world_new.translation()).norm();
  const int newest = static_cast<int>(graph.size()) - 1;
  c.chain_m =
      graph.pathLength(before.from_keyframe, old_kf) + graph.pathLength(before.to_keyframe, newest);
  return c;
}

bool consistentCycle(const ClosureCycle& cycle, const LoopConfig& cfg) {
  if (cfg.consistency_m < 0) return true;
  return cycle.error_m <= cfg.consistency_m + cfg.consistency_per_m * cycle.chain_m;
}

}  // namespace slamroute::evaluate::slam
