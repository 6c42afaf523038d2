#pragma once
// Keyframe pose graph optimised with Ceres (odometry + loop-closure edges).
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute::evaluate {

struct PoseGraphEdge {
  int from = 0, to = 0;
  Pose3 T_from_to = Pose3::Identity();
  double sigma_m = 0.05;
  double sigma_rad = 0.005;
  /// > 0: a Cauchy loss of this scale on the residual in sigmas, so an edge that disagrees with
  /// the rest by many sigmas pulls little (a wrong loop closure); 0: least squares
  double cauchy_sigmas = 0.0;
};

struct PoseGraphResult {
  double initial_cost = 0, final_cost = 0;
  int iterations = 0;
  bool converged = false;
};

/// Optimises `poses` (T_world_node) in place; node `fixed` is held constant.
PoseGraphResult optimizePoseGraph(std::vector<Pose3>& poses,
                                  const std::vector<PoseGraphEdge>& edges, int fixed = 0);

}  // namespace slamroute::evaluate
