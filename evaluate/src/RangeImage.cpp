// LeGO-LOAM imageProjection: range image, ground removal and range-image clustering.
#include "slamroute/evaluate/RangeImage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace slamroute::evaluate {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

RangeImage projectScan(const Scan& scan, const LidarSpec& spec, const Config& cfg) {
  RangeImage img;
  img.rows = spec.channels;
  img.cols = spec.horizontal_samples;
  if (img.rows < 2 || img.cols < 8) throw std::invalid_argument("projectScan: bad LidarSpec size");
  img.vfov_down_rad = spec.vfov_down_deg * kDeg;
  img.vres_rad = (spec.vfov_up_deg - spec.vfov_down_deg) * kDeg / (img.rows - 1);
  img.hres_rad = 2.0 * std::numbers::pi / img.cols;
  const std::size_t n = static_cast<std::size_t>(img.rows) * img.cols;
  img.range.assign(n, 0.0f);
  img.point.assign(n, Eigen::Vector3f::Zero());
  img.ground.assign(n, 0);
  img.label.assign(n, RangeImage::kNoLabel);
  const double min_r = std::max(cfg.features.min_range_m, spec.min_range_m);
  for (const ScanPoint& p : scan.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    const double r = std::sqrt(double(p.x) * p.x + double(p.y) * p.y + double(p.z) * p.z);
    if (r < min_r || r > spec.max_range_m) continue;
    int row;
    if (cfg.features.use_ring_field && p.ring >= 0 && p.ring < img.rows) {
      row = cfg.features.ring_zero_is_bottom ? p.ring : img.rows - 1 - p.ring;
    } else {
      const double elev = std::atan2(double(p.z), std::hypot(double(p.x), double(p.y)));
      row = static_cast<int>(std::lround((elev - img.vfov_down_rad) / img.vres_rad));
      if (row < 0 || row >= img.rows) continue;
    }
    const double az = std::atan2(double(p.y), double(p.x));  // (-pi, pi]
    int col = static_cast<int>(std::floor((az + std::numbers::pi) / img.hres_rad));
    col = ((col % img.cols) + img.cols) % img.cols;
    const int i = img.idx(row, col);
    if (img.range[i] > 0.0f && img.range[i] <= r) continue;  // keep the nearest return
    if (img.range[i] == 0.0f) ++img.valid_points;
    img.range[i] = static_cast<float>(r);
    img.point[i] = Eigen::Vector3f(p.x, p.y, p.z);
  }
  return img;
}

void segmentGround(RangeImage& img, const Config& cfg) {
  // Beams below ground_max_elevation_deg can see the road (LeGO-LOAM groundScanInd).
  const int ground_rows = std::clamp(
      static_cast<int>(std::floor(
          (cfg.features.ground_max_elevation_deg * kDeg - img.vfov_down_rad) / img.vres_rad)) +
          1,
      0, img.rows - 1);
  const double max_angle = cfg.features.ground_angle_deg * kDeg;
  const double mount = cfg.features.sensor_mount_angle_deg * kDeg;
  for (int c = 0; c < img.cols; ++c) {
    for (int r = 0; r < ground_rows; ++r) {
      const int lo = img.idx(r, c), up = img.idx(r + 1, c);
      if (img.range[lo] == 0.0f || img.range[up] == 0.0f) continue;
      const Eigen::Vector3f d = img.point[up] - img.point[lo];
      const double angle = std::atan2(d.z(), std::hypot(d.x(), d.y())) - mount;
      if (std::abs(angle) <= max_angle) img.ground[lo] = img.ground[up] = 1;
    }
  }
}

void clusterRangeImage(RangeImage& img, const Config& cfg) {
  const double theta = cfg.features.segment_theta_deg * kDeg;
  const double sin_h = std::sin(img.hres_rad), cos_h = std::cos(img.hres_rad);
  const double sin_v = std::sin(img.vres_rad), cos_v = std::cos(img.vres_rad);
  std::vector<int> queue;
  queue.reserve(4096);
  int next_label = 1;
  for (int r0 = 0; r0 < img.rows; ++r0) {
    for (int c0 = 0; c0 < img.cols; ++c0) {
      const int i0 = img.idx(r0, c0);
      if (img.range[i0] == 0.0f || img.ground[i0] || img.label[i0] != RangeImage::kNoLabel)
        continue;
      const int label = next_label;
      queue.clear();
      queue.push_back(i0);
      img.label[i0] = label;
      std::vector<bool> row_hit(static_cast<std::size_t>(img.rows), false);
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const int i = queue[q];
        const int r = i / img.cols, c = i % img.cols;
        row_hit[static_cast<std::size_t>(r)] = true;
        const int nbr[4][2] = {{r - 1, c}, {r + 1, c}, {r, c - 1}, {r, c + 1}};
        for (int k = 0; k < 4; ++k) {
          const int rr = nbr[k][0];
          if (rr < 0 || rr >= img.rows) continue;
          const int cc = (nbr[k][1] + img.cols) % img.cols;
          const int j = img.idx(rr, cc);
          if (img.range[j] == 0.0f || img.ground[j] || img.label[j] != RangeImage::kNoLabel)
            continue;
          const double d1 = std::max(img.range[i], img.range[j]);
          const double d2 = std::min(img.range[i], img.range[j]);
          const bool vertical = k < 2;
          const double s = vertical ? sin_v : sin_h, co = vertical ? cos_v : cos_h;
          const double beta = std::atan2(d2 * s, d1 - d2 * co);
          if (beta > theta) {
            img.label[j] = label;
            queue.push_back(j);
          }
        }
      }
      int rows_spanned = 0;
      for (bool b : row_hit) rows_spanned += b ? 1 : 0;
      const int size = static_cast<int>(queue.size());
      const bool keep = size >= cfg.features.min_cluster_points ||
                        (size >= cfg.features.min_line_cluster_points &&
                         rows_spanned >= cfg.features.min_cluster_rings);
      if (keep) {
        ++next_label;
      } else {
        for (int i : queue) img.label[i] = RangeImage::kOutlier;
      }
    }
  }
  img.clusters = next_label - 1;
}

}  // namespace slamroute::evaluate
