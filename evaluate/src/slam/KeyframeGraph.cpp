#include "KeyframeGraph.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace slamroute::evaluate::slam {

void KeyframeGraph::keepCloudsOnDisk(const std::filesystem::path& dir) {
  if (!kfs_.empty())
    throw std::logic_error("KeyframeGraph::keepCloudsOnDisk: call it before the first keyframe");
  clouds_ = std::make_unique<CloudStore>(dir);
}

void KeyframeGraph::add(double t, int frame, const Pose3& T_world, const Cloud& edges,
                        const Cloud& planes, const Cloud& segmented, double imu_pitch_rad) {
  Keyframe kf;
  kf.imu_pitch_rad = imu_pitch_rad;
  kf.t = t;
  kf.frame = frame;
  kf.T_world = T_world;
  kf.edges = edges;
  kf.planes = planes;
  kf.cloud = clouds_->add(voxelFilter(segmented, cfg_.output.map_voxel_m));
  if (!kfs_.empty()) {
    driven_since_loop_ += (T_world.translation() - kfs_.back().T_world.translation()).norm();
    PoseGraphEdge e;
    e.from = static_cast<int>(kfs_.size()) - 1;
    e.to = e.from + 1;
    e.T_from_to = kfs_.back().T_world.inverse() * T_world;
    e.sigma_m = cfg_.loop.graph_odom_sigma_m;
    e.sigma_rad = cfg_.loop.graph_odom_sigma_rad;
    odom_edges_.push_back(e);
  }
  kfs_.push_back(std::move(kf));
  // Only the recent keyframes feed the local map: free the features of older ones.
  const std::size_t keep = static_cast<std::size_t>(std::max(cfg_.mapping.local_map_keyframes, 1));
  if (kfs_.size() > keep) {
    Keyframe& old = kfs_[kfs_.size() - 1 - keep];
    Cloud().swap(old.edges);
    Cloud().swap(old.planes);
  }
}

double KeyframeGraph::pathLength(int a, int b) const {
  double d = 0.0;
  for (int k = std::min(a, b); k < std::max(a, b); ++k)
    d += (kfs_[static_cast<std::size_t>(k + 1)].T_world.translation() -
          kfs_[static_cast<std::size_t>(k)].T_world.translation())
             .norm();
  return d;
}

void KeyframeGraph::closeLoop(const PoseGraphEdge& edge) {
  loop_edges_.push_back(edge);
  driven_since_loop_ = 0.0;
  optimize();
}

void KeyframeGraph::optimize() {
  std::vector<Pose3> poses;
  poses.reserve(kfs_.size());
  for (const auto& kf : kfs_) poses.push_back(kf.T_world);
  std::vector<PoseGraphEdge> edges = odom_edges_;
  edges.insert(edges.end(), loop_edges_.begin(), loop_edges_.end());
  PitchFactors pitch;
  if (estimatesPitchBias()) {
    constexpr double deg = std::numbers::pi / 180.0;
    pitch.sigma_rad = cfg_.loop.graph_imu_pitch_sigma_deg * deg;
    pitch.bias_sigma_rad = cfg_.loop.graph_pitch_bias_sigma_deg * deg;
    for (const auto& kf : kfs_) pitch.imu_pitch_rad.push_back(kf.imu_pitch_rad);
  }
  pitch_bias_rad_ = optimizePoseGraph(poses, edges, 0, pitch).pitch_bias_rad;
  for (std::size_t k = 0; k < kfs_.size(); ++k) kfs_[k].T_world = poses[k];
}

}  // namespace slamroute::evaluate::slam
