#include "VoxelCells.hpp"

#include <stdexcept>

namespace slamroute::evaluate::slam {

VoxelCells::VoxelCells(double voxel_m) : inv_(static_cast<float>(1.0 / voxel_m)) {
  if (!(voxel_m > 0.0)) throw std::invalid_argument("VoxelCells: the voxel must be > 0 m");
}

void VoxelCells::add(const Cloud& pts) {
  for (const auto& p : pts) {
    const auto [it, fresh] = slot_of_.try_emplace(voxelKey(p, inv_), 0u);
    if (fresh) {
      if (free_.empty()) {
        it->second = static_cast<std::uint32_t>(cells_.size());
        cells_.emplace_back();
      } else {
        it->second = free_.back();
        free_.pop_back();
      }
    }
    Cell& c = cells_[it->second];
    c.sum += p.cast<double>();
    ++c.n;
  }
}

void VoxelCells::remove(const Cloud& pts) {
  for (const auto& p : pts) {
    const auto it = slot_of_.find(voxelKey(p, inv_));
    if (it == slot_of_.end())
      throw std::logic_error("VoxelCells::remove: a point that was never added");
    Cell& c = cells_[it->second];
    if (--c.n == 0) {
      c.sum.setZero();
      free_.push_back(it->second);
      slot_of_.erase(it);
    } else {
      c.sum -= p.cast<double>();
    }
  }
}

void VoxelCells::clear() {
  cells_.clear();
  free_.clear();
  slot_of_.clear();
}

Cloud VoxelCells::centroids() const {
  Cloud out;
  out.reserve(slot_of_.size());
  for (const Cell& c : cells_)
    if (c.n > 0) out.push_back((c.sum / c.n).cast<float>());
  return out;
}

}  // namespace slamroute::evaluate::slam
