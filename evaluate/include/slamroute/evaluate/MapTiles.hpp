#pragma once
// The SLAM map (every keyframe's cloud at its optimised pose, voxel-filtered) built tile by tile
// and handed to a sink, so that neither the map nor its voxel cells are ever whole in memory:
// a 75 km drive's map is 40.7 M points, and merging it at once peaked at 2.7 GB
// (bench/RESULTS.md "SLAM memory"). A tile holds the voxels of a square of
// cfg.output.map_tile_m; each voxel's points are summed in keyframe order, so every map point is
// bit for bit the one voxelFilter gives over all clouds joined (the order of the points is tile by
// tile).
#include <Eigen/Geometry>
#include <cstddef>
#include <functional>
#include <vector>

#include "slamroute/core/Trajectory.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/CloudStore.hpp"
#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate {

/// Where the map goes, one part (tile) at a time.
class MapSink {
 public:
  virtual ~MapSink() = default;
  /// Called once before begin() with the trajectory estimate the map is built on.
  virtual void estimate(const Trajectory& est) { (void)est; }
  /// Called once before the first part with a box that holds every map point (empty: no points).
  virtual void begin(const Eigen::AlignedBox3f& bounds) { (void)bounds; }
  virtual void add(const Cloud& part) = 0;
};

/// The sink that keeps the whole map (tests, small drives).
class CollectedMap : public MapSink {
 public:
  void add(const Cloud& part) override { map.insert(map.end(), part.begin(), part.end()); }
  Cloud map;
};

/// A keyframe for the map: its cloud's number in the store (body frame) and its pose.
struct MapKeyframe {
  int cloud = -1;
  Pose3 T_world = Pose3::Identity();
};

/// Builds the map of `keyframes` at `voxel_m` in tiles of `tile_m` (rounded to whole voxels) and
/// gives it to `sink` tile by tile; each keyframe's cloud is read from `clouds` once per tile its
/// box overlaps and released after its last tile. `voxel_m` <= 0: every point, keyframe by
/// keyframe. `progress(done, total)` after each tile. Returns the number of map points.
std::size_t buildMapByTiles(CloudStore& clouds, const std::vector<MapKeyframe>& keyframes,
                            double voxel_m, double tile_m, MapSink& sink,
                            const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace slamroute::evaluate
