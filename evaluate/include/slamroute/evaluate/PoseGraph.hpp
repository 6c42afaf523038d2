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

/// The nodes' absolute pitch from a gravity-levelled IMU, which reads the true pitch plus one
/// constant bias b (an unknown with a Gaussian prior) plus white noise:
/// pitch(node k) = imu_pitch_k - b +- sigma. Relative edges alone let a chain pitch away from its
/// fixed first node, which explains a closure's height mismatch as well as a bias does; tied to
/// gravity at every node, the chain can explain it only by b.
struct PitchFactors {
  std::vector<double> imu_pitch_rad;  ///< per node, nose down > 0 (Ry); NaN: no reading
  double sigma_rad = 0.0;             ///< per reading; 0: no factors
  double bias_prior_rad = 0.0;
  double bias_sigma_rad = 0.0;  ///< 0: b held at the prior
};

struct PoseGraphResult {
  double initial_cost = 0, final_cost = 0;
  int iterations = 0;
  bool converged = false;
  double pitch_bias_rad = 0.0;  ///< b (the prior when not estimated) [rad]
};

/// Optimises `poses` (T_world_node) in place; node `fixed` is held constant.
PoseGraphResult optimizePoseGraph(std::vector<Pose3>& poses,
                                  const std::vector<PoseGraphEdge>& edges, int fixed = 0,
                                  const PitchFactors& pitch = {});

}  // namespace slamroute::evaluate
