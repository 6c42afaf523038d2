#include "VoxelCells.hpp"

#include <stdexcept>

namespace slamroute::evaluate::slam {

VoxelCells::VoxelCells(double voxel_m) : inv_(static_cast<float>(1.0 / voxel_m)) {
  if (!(voxel_m > 0.0)) throw std::invalid_argument("VoxelCells: the voxel must be > 0 m");
}

void VoxelCells::add(const Cloud& pts) {
  for (const auto& p : pts) {
    Cell& c = cells_[voxelKey(p, inv_)];
    c.sum += p.cast<double>();
    ++c.n;
  }
}

void VoxelCells::remove(const Cloud& pts) {
  for (const auto& p : pts) {
    const auto it = cells_.find(voxelKey(p, inv_));
    if (it == cells_.end())
      throw std::logic_error("VoxelCells::remove: a point that was never added");
    if (--it->second.n == 0) {
      cells_.erase(it);
    } else {
      it->second.sum -= p.cast<double>();
    }
  }
}

Cloud VoxelCells::centroids() const {
  Cloud out;
  out.reserve(cells_.size());
  for (const auto& [key, c] : cells_) out.push_back((c.sum / c.n).cast<float>());
  return out;
}

}  // namespace slamroute::evaluate::slam
