#include "slamroute/evaluate/MapOutput.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {

MapOutput::MapOutput(const std::filesystem::path& pcd, const Mesh* mesh, const Trajectory* gt,
                     double max_dt_s, double max_m, int image_px)
    : pcd_(pcd), mesh_(mesh), gt_(gt), max_dt_s_(max_dt_s), max_m_(max_m), image_px_(image_px) {}

void MapOutput::estimate(const Trajectory& est) {
  if (!mesh_ || !gt_) return;
  const std::vector<PosePair> pairs = associate(est, *gt_, max_dt_s_);
  if (!pairs.empty()) T_gt_est_ = alignUmeyama(pairs);
}

void MapOutput::begin(const Eigen::AlignedBox3f& bounds) {
  if (!mesh_) return;
  built_.emplace(*mesh_, max_m_, bounds);
  const Eigen::AlignedBox3f moved = transformedBox(bounds, T_gt_est_);
  aligned_.emplace(*mesh_, max_m_, moved);
  image_.emplace(moved, image_px_);
}

void MapOutput::add(const Cloud& part) {
  pcd_.add(part);
  if (!built_) return;
  built_->add(part);
  const Cloud moved = transformed(part, T_gt_est_);
  std::vector<float> dist;
  aligned_->add(moved, &dist);
  image_->add(moved, dist.data());
}

void MapOutput::commit() { pcd_.commit(); }

std::optional<MapAccuracy> MapOutput::accuracy() const {
  if (!built_) return std::nullopt;
  return built_->result();
}

std::optional<MapAccuracy> MapOutput::alignedAccuracy() const {
  if (!aligned_) return std::nullopt;
  return aligned_->result();
}

void MapOutput::writeImage(const std::filesystem::path& png) const {
  if (!image_) return;
  const MapAccuracy aligned = *alignedAccuracy();
  const double top = mapErrorImageTop(aligned.p95_m, max_m_);
  char title[200];
  std::snprintf(
      title, sizeof title,
      "SLAM map from above, aligned like the ATE: distance to the world surface (median %.2f m)",
      aligned.median_m);
  image_->write(png, title, top);
}

}  // namespace slamroute::evaluate
