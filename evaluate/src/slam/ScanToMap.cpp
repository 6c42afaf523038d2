#include "ScanToMap.hpp"

#include <algorithm>

namespace slamroute::evaluate::slam {

void ScanToMap::rebuild(const KeyframeGraph& graph, bool force) {
  const MappingConfig& c = cfg_.mapping;
  const Vec3 here = graph.back().T_world.translation();
  if (!force && (here - built_at_).norm() < c.local_map_update_m) return;
  built_at_ = here;
  Cloud edges, planes;
  const int n = static_cast<int>(graph.size());
  for (int k = n - 1; k >= 0 && k >= n - c.local_map_keyframes; --k) {
    const Keyframe& kf = graph.at(static_cast<std::size_t>(k));
    if ((kf.T_world.translation() - here).norm() > c.local_map_radius_m) continue;
    const Cloud e = transformed(kf.edges, kf.T_world), p = transformed(kf.planes, kf.T_world);
    edges.insert(edges.end(), e.begin(), e.end());
    planes.insert(planes.end(), p.begin(), p.end());
  }
  map_.build(voxelFilter(edges, c.edge_voxel_m), voxelFilter(planes, c.surf_voxel_m));
}

AlignOptions ScanToMap::options(const MotionModel& motion, const Prediction& step) const {
  const MappingConfig& c = cfg_.mapping;
  AlignOptions o;
  o.iterations = c.iterations;
  o.reassociate_every = c.reassociate_every;
  o.max_nn_m = c.max_nn_m;
  o.huber_m = c.huber_m;
  o.plane_max_dev_m = c.plane_max_dev_m;
  if (c.degeneracy_remap) o.degenerate_eig = c.degeneracy_min_eig;
  motion.addOdometryPrior(o, step);
  return o;
}

Pose3 ScanToMap::coarse(const PreparedScan& scan, const Pose3& init, const AlignOptions& fine,
                        const MotionModel& motion, const Prediction& step) const {
  // Only for frame intervals above 0.15 s: at 10 Hz it is not needed and can settle on a wrong
  // minimum after a heading jump.
  const MappingConfig& c = cfg_.mapping;
  if (!(c.coarse_nn_m > 0 && motion.hasVelocity() && step.scale > 1.5)) return init;
  const int cap = std::max(50, cfg_.relocalise.max_points);
  AlignOptions o = fine;
  o.max_nn_m = c.coarse_nn_m;
  o.iterations = cfg_.relocalise.iterations;
  o.degenerate_eig = 0;
  const AlignResult r = alignFeatures(map_, capped(scan.src_edges, cap / 4), capped(scan.src_planes, cap), init, o);
  if (r.edge_matches >= c.min_edge_features && r.plane_matches >= c.min_plane_features &&
      motion.plausibleStep(step.T_world, r.T_target_source, step))
    return r.T_target_source;
  return init;
}

}  // namespace slamroute::evaluate::slam
