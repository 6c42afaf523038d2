#pragma once
// The keyframe graph: keyframe poses with their features (recent ones, for the local map) and
// clouds (all, for loop closure and the map), odometry edges between consecutive keyframes and
// loop edges, optimised with Ceres when a loop closes (paper §3.3, LeGO-LOAM "mapOptimization").
#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "slamroute/evaluate/CloudStore.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/PoseGraph.hpp"

namespace slamroute::evaluate::slam {

struct Keyframe {
  double t = 0;
  int frame = 0;
  Pose3 T_world = Pose3::Identity();
  Cloud edges, planes;  ///< body frame, voxel-filtered; freed once out of the local map's reach
  int cloud = -1;       ///< in the CloudStore: body frame, segmented points at output.map_voxel_m
  double imu_pitch_rad = std::numeric_limits<double>::quiet_NaN();  ///< at t; NaN: no IMU
};

class KeyframeGraph {
 public:
  explicit KeyframeGraph(const Config& cfg) : cfg_(cfg), clouds_(std::make_unique<CloudStore>()) {}
  /// Keeps the clouds in an unnamed file in `dir` (CloudStore); call before the first keyframe.
  void keepCloudsOnDisk(const std::filesystem::path& dir);

  /// Appends a keyframe and its odometry edge from the previous one.
  void add(double t, int frame, const Pose3& T_world, const Cloud& edges, const Cloud& planes,
           const Cloud& segmented, double imu_pitch_rad = std::numeric_limits<double>::quiet_NaN());
  /// Adds a loop edge and re-optimises every keyframe pose.
  void closeLoop(const PoseGraphEdge& edge);
  /// Re-optimises every keyframe pose (with the IMU pitch factors when
  /// loop.graph_imu_pitch_sigma_deg > 0) and re-estimates the IMU pitch bias.
  void optimize();
  bool estimatesPitchBias() const { return cfg_.loop.graph_imu_pitch_sigma_deg > 0; }
  /// The IMU pitch bias of the last optimisation (0 before it or when not estimated) [rad].
  double pitchBiasRad() const { return pitch_bias_rad_; }

  std::size_t size() const { return kfs_.size(); }
  bool empty() const { return kfs_.empty(); }
  const Keyframe& at(std::size_t k) const { return kfs_[k]; }
  const Keyframe& back() const { return kfs_.back(); }
  const CloudStore& clouds() const { return *clouds_; }
  CloudStore& clouds() { return *clouds_; }
  /// Keyframe path between keyframes a and b, either order [m].
  double pathLength(int a, int b) const;
  /// Keyframe path since the last loop closure [m].
  double drivenSinceLoop() const { return driven_since_loop_; }

 private:
  const Config& cfg_;
  std::vector<Keyframe> kfs_;
  std::unique_ptr<CloudStore> clouds_;
  std::vector<PoseGraphEdge> odom_edges_, loop_edges_;
  double driven_since_loop_ = 0.0;
  double pitch_bias_rad_ = 0.0;
};

}  // namespace slamroute::evaluate::slam
