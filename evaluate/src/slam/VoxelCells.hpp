#pragma once
// A voxel grid of running centroids that clouds can be added to and taken out of again. The local
// map moves with the vehicle by adding the keyframe that comes into reach and taking out the one
// that leaves, instead of re-filtering the clouds of all its ~40 keyframes at every update.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate::slam {

class VoxelCells {
 public:
  /// voxel_m > 0: cells as voxelFilter bins them (voxelKey).
  explicit VoxelCells(double voxel_m);

  void add(const Cloud& pts);
  /// Takes out points added before (the same values), emptying cells they alone filled.
  void remove(const Cloud& pts);
  void clear();
  /// One centroid per occupied voxel, in the cells' (deterministic) order.
  Cloud centroids() const;
  std::size_t size() const { return slot_of_.size(); }

 private:
  /// Double sums: a voxel's centroid after many adds and removes stays within float rounding.
  struct Cell {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;  ///< 0: a free slot
  };
  float inv_;
  // The cells lie in one array (slots reused when emptied) and the hash only maps a voxel to its
  // slot: the map's centroids are read at every local-map update, and walking a contiguous
  // array is several times faster than walking the hash's nodes.
  std::vector<Cell> cells_;
  std::vector<std::uint32_t> free_;
  std::unordered_map<std::uint64_t, std::uint32_t> slot_of_;
};

}  // namespace slamroute::evaluate::slam
