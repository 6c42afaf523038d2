#include "ScanToMap.hpp"

#include <algorithm>

namespace slamroute::evaluate::slam {

ScanToMap::ScanToMap(const Config& cfg)
    : cfg_(cfg), edge_cells_(cfg.mapping.edge_voxel_m), plane_cells_(cfg.mapping.surf_voxel_m) {}

void ScanToMap::rebuild(const KeyframeGraph& graph, bool force) {
  const Vec3 here = graph.back().T_world.translation();
  if (!force && (here - built_at_).norm() < cfg_.mapping.local_map_update_m) return;
  built_at_ = here;
  const std::vector<int> want = inReach(graph);
  if (force) {  // the keyframes' poses moved: start again
    in_map_.clear();
    edge_cells_.clear();
    plane_cells_.clear();
  }
  take(want);        // keyframes that left the reach
  put(graph, want);  // keyframes that came into it
  map_.build(edge_cells_.centroids(), plane_cells_.centroids());
}

std::vector<int> ScanToMap::inReach(const KeyframeGraph& graph) const {
  const MappingConfig& c = cfg_.mapping;
  const Vec3 here = graph.back().T_world.translation();
  std::vector<int> want;
  const int n = static_cast<int>(graph.size());
  for (int k = std::max(0, n - c.local_map_keyframes); k < n; ++k)
    if ((graph.at(static_cast<std::size_t>(k)).T_world.translation() - here).norm() <=
        c.local_map_radius_m)
      want.push_back(k);
  return want;
}

void ScanToMap::take(const std::vector<int>& keep) {
  for (auto it = in_map_.begin(); it != in_map_.end();) {
    if (std::binary_search(keep.begin(), keep.end(), it->first)) {
      ++it;
      continue;
    }
    edge_cells_.remove(it->second.edges);
    plane_cells_.remove(it->second.planes);
    it = in_map_.erase(it);
  }
}

void ScanToMap::put(const KeyframeGraph& graph, const std::vector<int>& want) {
  for (const int k : want) {
    if (in_map_.count(k)) continue;
    const Keyframe& kf = graph.at(static_cast<std::size_t>(k));
    InMap& m = in_map_[k];
    m.edges = transformed(kf.edges, kf.T_world);
    m.planes = transformed(kf.planes, kf.T_world);
    edge_cells_.add(m.edges);
    plane_cells_.add(m.planes);
  }
}

AlignOptions ScanToMap::options(const MotionModel& motion, const Prediction& step) const {
  const MappingConfig& c = cfg_.mapping;
  AlignOptions o;
  o.iterations = motion.hasOdometry() ? c.iterations : c.iterations_without_odometry;
  o.reassociate_every = c.reassociate_every;
  o.max_nn_m = c.max_nn_m;
  o.huber_m = c.huber_m;
  o.plane_max_dev_m = c.plane_max_dev_m;
  o.edge_weight = motion.hasOdometry() ? c.edge_weight : c.edge_weight_without_odometry;
  if (c.degeneracy_remap) o.degenerate_eig = c.degeneracy_min_eig;
  motion.addMotionPrior(o, step);
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
  const AlignResult r =
      alignFeatures(map_, capped(scan.src_edges, cap / 4), capped(scan.src_planes, cap), init, o);
  if (enoughMatches(r, c) && motion.plausibleStep(step.T_world, r.T_target_source, step))
    return r.T_target_source;
  return init;
}

}  // namespace slamroute::evaluate::slam
