// LeGO-LOAM featureAssociation: curvature per ring, occlusion marking, edge/planar selection in
// sectors, plus the voxel filter used for feature clouds and maps.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate {
namespace {

struct RingPoint {
  Eigen::Vector3f p;
  float range;
  int col;
  bool ground;
};

void extractRing(const std::vector<RingPoint>& ring, const Config& cfg, FeatureSet& out,
                 Cloud& less_flat_all) {
  const int w = cfg.features.curvature_half_window;
  const int n = static_cast<int>(ring.size());
  if (n < 2 * w + 2) return;
  std::vector<float> curv(static_cast<std::size_t>(n), 0.0f);
  std::vector<std::uint8_t> picked(static_cast<std::size_t>(n), 0);
  std::vector<int> lbl(static_cast<std::size_t>(n), 0);  // 2 sharp, 1 less sharp, -1 flat
  for (int i = w; i < n - w; ++i) {
    float diff = -2.0f * w * ring[i].range;
    for (int k = -w; k <= w; ++k)
      if (k != 0) diff += ring[i + k].range;
    curv[i] = diff * diff;
  }
  // Occluded points and points on surfaces parallel to the beam are unreliable (LOAM §V-A).
  const float gap = static_cast<float>(cfg.features.occlusion_gap_m);
  for (int i = w; i < n - w - 1; ++i) {
    const float d1 = ring[i].range, d2 = ring[i + 1].range;
    if (std::abs(ring[i + 1].col - ring[i].col) < 10) {
      if (d1 - d2 > gap) {
        for (int k = 0; k <= w; ++k) picked[i - k] = 1;
      } else if (d2 - d1 > gap) {
        for (int k = 1; k <= w + 1 && i + k < n; ++k) picked[i + k] = 1;
      }
    }
    const float a = std::abs(ring[i - 1].range - d1), b = std::abs(d2 - d1);
    if (a > 0.02f * d1 && b > 0.02f * d1) picked[i] = 1;
  }
  auto markNeighbours = [&](int i) {
    picked[i] = 1;
    for (int l = 1; l <= w && i + l < n; ++l) {
      if (std::abs(ring[i + l].col - ring[i + l - 1].col) > 10) break;
      picked[i + l] = 1;
    }
    for (int l = 1; l <= w && i - l >= 0; ++l) {
      if (std::abs(ring[i - l].col - ring[i - l + 1].col) > 10) break;
      picked[i - l] = 1;
    }
  };
  const int start = w, end = n - w - 1;
  std::vector<int> order;
  for (int s = 0; s < cfg.features.feature_sectors; ++s) {
    const int sp = start + (end - start) * s / cfg.features.feature_sectors;
    const int ep = start + (end - start) * (s + 1) / cfg.features.feature_sectors - 1;
    if (sp >= ep) continue;
    order.resize(static_cast<std::size_t>(ep - sp + 1));
    std::iota(order.begin(), order.end(), sp);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return curv[a] < curv[b]; });
    int count = 0;
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      const int i = *it;
      if (curv[i] <= cfg.features.edge_curvature) break;
      if (picked[i] || ring[i].ground) continue;
      ++count;
      if (count <= cfg.features.sharp_per_sector) {
        lbl[i] = 2;
        out.sharp.push_back(ring[i].p);
        out.less_sharp.push_back(ring[i].p);
      } else if (count <= cfg.features.less_sharp_per_sector) {
        lbl[i] = 1;
        out.less_sharp.push_back(ring[i].p);
      } else {
        break;
      }
      markNeighbours(i);
    }
    count = 0;
    for (int i : order) {
      if (curv[i] >= cfg.features.surf_curvature) break;
      if (picked[i] || !ring[i].ground) continue;
      lbl[i] = -1;
      out.flat.push_back(ring[i].p);
      if (++count >= cfg.features.flat_per_sector) break;
      markNeighbours(i);
    }
    for (int i = sp; i <= ep; ++i)
      if (lbl[i] <= 0) less_flat_all.push_back(ring[i].p);
  }
}

}  // namespace

FeatureSet extractFeatures(const RangeImage& img, const Config& cfg) {
  FeatureSet out;
  Cloud less_flat_all;
  std::vector<RingPoint> ring;
  const int stride = std::max(1, cfg.features.ground_column_stride);
  for (int r = 0; r < img.rows; ++r) {
    ring.clear();
    for (int c = 0; c < img.cols; ++c) {
      const int i = img.idx(r, c);
      if (img.range[i] == 0.0f) continue;
      const bool g = img.ground[i] != 0;
      if (g) {
        if (c % stride != 0 && c > 5 && c < img.cols - 5) continue;  // LeGO subsamples ground
      } else if (img.label[i] <= 0) {
        continue;
      }
      ring.push_back({img.point[i], img.range[i], c, g});
      out.segmented.push_back(img.point[i]);
    }
    extractRing(ring, cfg, out, less_flat_all);
  }
  out.less_flat = voxelFilter(less_flat_all, cfg.features.less_flat_voxel_m);
  return out;
}

namespace {

using KeyIndex = std::pair<std::uint64_t, std::uint32_t>;

/// Stable sort by key, least significant 11 bits first; a digit all keys share is skipped (a
/// scan's keys differ in few of their bits). Stable with the indices starting in input order, it
/// gives the order std::sort of the (key, index) pairs gives, at a fraction of its cost.
void radixSortByKey(std::vector<KeyIndex>& keys) {
  constexpr int kBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kBits;
  std::vector<KeyIndex> tmp(keys.size());
  std::vector<std::size_t> count(kBuckets);
  for (int shift = 0; shift < 64; shift += kBits) {
    std::fill(count.begin(), count.end(), 0);
    for (const KeyIndex& k : keys) ++count[(k.first >> shift) & (kBuckets - 1)];
    if (count[(keys.front().first >> shift) & (kBuckets - 1)] == keys.size()) continue;
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (const KeyIndex& k : keys) tmp[count[(k.first >> shift) & (kBuckets - 1)]++] = k;
    keys.swap(tmp);
  }
}

/// (voxel, index) of every point, sorted: each voxel's points in input order.
std::vector<KeyIndex> sortedKeys(const Cloud& in, float inv) {
  std::vector<KeyIndex> keys;
  keys.reserve(in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    keys.emplace_back(voxelKey(in[i], inv), static_cast<std::uint32_t>(i));
  if (!keys.empty()) radixSortByKey(keys);
  return keys;
}

}  // namespace

Cloud transformed(const Cloud& c, const Pose3& T) {
  const Eigen::Matrix3f R = T.rotation().cast<float>();
  const Eigen::Vector3f t = T.translation().cast<float>();
  Cloud out;
  out.reserve(c.size());
  for (const auto& p : c) out.push_back(R * p + t);
  return out;
}

Eigen::AlignedBox3f transformedBox(const Eigen::AlignedBox3f& b, const Pose3& T) {
  Eigen::AlignedBox3f out;
  if (b.isEmpty()) return out;
  Cloud corners;
  for (int k = 0; k < 8; ++k)
    corners.push_back(b.corner(static_cast<Eigen::AlignedBox3f::CornerType>(k)));
  for (const auto& p : transformed(corners, T)) out.extend(p);
  return out;
}

Cloud voxelFilter(const Cloud& in, double voxel_m) {
  if (voxel_m <= 0.0 || in.empty()) return in;
  const auto keys = sortedKeys(in, static_cast<float>(1.0 / voxel_m));
  Cloud out;
  for (std::size_t a = 0; a < keys.size();) {
    std::size_t b = a;
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    while (b < keys.size() && keys[b].first == keys[a].first) sum += in[keys[b++].second];
    out.push_back(sum / static_cast<float>(b - a));
    a = b;
  }
  return out;
}

VoxelMerger::VoxelMerger(double voxel_m, std::size_t chunk_points)
    : voxel_m_(voxel_m), chunk_(std::max<std::size_t>(chunk_points, 1)) {}

void VoxelMerger::add(const Cloud& c) {
  buf_.insert(buf_.end(), c.begin(), c.end());
  if (voxel_m_ > 0.0 && buf_.size() >= chunk_) flush();
}

// Merges the buffer into the sorted cells: a voxel's sum goes on from where the earlier chunks
// left it, adding this chunk's points in input order, so every sum is formed exactly as
// voxelFilter forms it over the whole concatenation.
void VoxelMerger::flush() {
  if (buf_.empty()) return;
  const auto keys = sortedKeys(buf_, static_cast<float>(1.0 / voxel_m_));
  std::vector<Cell> merged;
  merged.reserve(cells_.size() + keys.size() / 2);
  std::size_t c = 0;
  for (std::size_t a = 0; a < keys.size();) {
    const std::uint64_t key = keys[a].first;
    while (c < cells_.size() && cells_[c].key < key) merged.push_back(cells_[c++]);
    Cell cell{key, Eigen::Vector3f::Zero(), 0};
    if (c < cells_.size() && cells_[c].key == key) cell = cells_[c++];
    for (; a < keys.size() && keys[a].first == key; ++a) {
      cell.sum += buf_[keys[a].second];
      ++cell.n;
    }
    merged.push_back(cell);
  }
  merged.insert(merged.end(), cells_.begin() + static_cast<std::ptrdiff_t>(c), cells_.end());
  cells_.swap(merged);
  Cloud().swap(buf_);
}

Cloud VoxelMerger::finish() {
  if (voxel_m_ <= 0.0) return std::move(buf_);
  flush();
  Cloud out;
  out.reserve(cells_.size());
  for (const Cell& cell : cells_) out.push_back(cell.sum / static_cast<float>(cell.n));
  std::vector<Cell>().swap(cells_);
  return out;
}

}  // namespace slamroute::evaluate
