#include "ScanToScan.hpp"

namespace slamroute::evaluate::slam {

Pose3 ScanToScan::align(const FeatureSet& f, const Pose3& T_prev_pred) const {
  AlignOptions o;
  o.iterations = cfg_.odometry.iterations;
  o.max_nn_m = cfg_.odometry.max_nn_m;
  o.huber_m = cfg_.mapping.huber_m;
  o.plane_max_dev_m = cfg_.mapping.plane_max_dev_m;
  Pose3 T = T_prev_pred;
  if (!cfg_.odometry.two_step) {
    const AlignResult r = alignFeatures(prev_, f.sharp, f.flat, T, o);
    if (r.edge_matches + r.plane_matches >= cfg_.mapping.min_plane_features) T = r.T_target_source;
    return T;
  }
  o.dof_mask = kZ | kRoll | kPitch;
  const AlignResult planar = alignFeatures(prev_, {}, f.flat, T, o);
  if (planar.plane_matches >= cfg_.mapping.min_plane_features) T = planar.T_target_source;
  o.dof_mask = kX | kY | kYaw;
  const AlignResult edges = alignFeatures(prev_, f.sharp, {}, T, o);
  if (edges.edge_matches >= cfg_.mapping.min_edge_features) T = edges.T_target_source;
  return T;
}

}  // namespace slamroute::evaluate::slam
