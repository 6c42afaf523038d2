#pragma once
// Scan-to-map registration (LeGO-LOAM "mapOptimization"): the scan's features against a local
// map of the recent keyframes' features near the vehicle, updated as the vehicle moves.
#include <map>
#include <vector>

#include "FrontEnd.hpp"
#include "KeyframeGraph.hpp"
#include "MotionModel.hpp"
#include "VoxelCells.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate::slam {

class ScanToMap {
 public:
  explicit ScanToMap(const Config& cfg);

  /// Updates the local map around the newest keyframe after mapping.local_map_update_m of
  /// motion: the last mapping.local_map_keyframes keyframes within mapping.local_map_radius_m.
  /// `force`: at once and from scratch (after a loop closure moved the keyframes).
  void rebuild(const KeyframeGraph& graph, bool force);
  const FeatureMap& localMap() const { return map_; }

  /// Registration options of the fine stage: with odometry its prior and mapping.iterations,
  /// without it mapping.iterations_without_odometry.
  AlignOptions options(const MotionModel& motion, const Prediction& step) const;
  /// Where the fine registration starts: `init`, or a coarse registration with a wide radius
  /// from it when scans are far apart and the speed is known (a stride-2 turn can leave the
  /// prediction several degrees off) and its result is plausible.
  Pose3 coarse(const PreparedScan& scan, const Pose3& init, const AlignOptions& fine,
               const MotionModel& motion, const Prediction& step) const;
  /// The fine registration from `start`.
  AlignResult align(const PreparedScan& scan, const Pose3& start, const AlignOptions& fine) const {
    return alignFeatures(map_, scan.src_edges, scan.src_planes, start, fine);
  }
  /// The planar features alone (an open street: they still fix height, roll and pitch).
  AlignResult alignPlanes(const PreparedScan& scan, const Pose3& start,
                          const AlignOptions& o) const {
    return alignFeatures(map_, {}, scan.src_planes, start, o);
  }

 private:
  /// A keyframe's features in the world frame, as they went into the cells.
  struct InMap {
    Cloud edges, planes;
  };
  std::vector<int> inReach(const KeyframeGraph& graph) const;
  void take(const std::vector<int>& keep);
  void put(const KeyframeGraph& graph, const std::vector<int>& want);

  const Config& cfg_;
  VoxelCells edge_cells_, plane_cells_;   ///< the local map's voxels (mapping.*_voxel_m)
  std::map<int, InMap> in_map_;           ///< keyframe index -> its part of the local map
  FeatureMap map_;                        ///< world frame
  Vec3 built_at_ = Vec3::Constant(1e18);  ///< where the local map was last rebuilt
};

}  // namespace slamroute::evaluate::slam
