#include "slamroute/evaluate/MapTiles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace slamroute::evaluate {
namespace {

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if (a % b != 0 && (a < 0) != (b < 0)) --q;
  return q;
}

using Tile = std::pair<std::int64_t, std::int64_t>;  ///< (y, x) tile index: rows of tiles

/// Points a tile's merger sorts at once: 48 MB of points + 64 MB of keys (the default 2^24 took
/// 470 MB, half the peak of a 75 km run).
constexpr std::size_t kTileChunkPoints = std::size_t{1} << 22;

}  // namespace

std::size_t buildMapByTiles(CloudStore& clouds, const std::vector<MapKeyframe>& keyframes,
                            double voxel_m, double tile_m, MapSink& sink,
                            const std::function<void(std::size_t, std::size_t)>& progress) {
  const std::size_t n = keyframes.size();
  Eigen::AlignedBox3f bounds;
  std::vector<Eigen::AlignedBox3f> boxes(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::AlignedBox3f& b = clouds.box(keyframes[k].cloud);
    if (b.isEmpty()) continue;
    boxes[k] =
        transformedBox(b, keyframes[k].T_world);  // + rounding, covered by a voxel's margin below
    bounds.extend(boxes[k]);
  }
  if (voxel_m <= 0.0) {  // every point, keyframe by keyframe
    sink.begin(bounds);
    std::size_t points = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const Cloud c = transformed(clouds.get(keyframes[k].cloud), keyframes[k].T_world);
      clouds.release(keyframes[k].cloud);
      points += c.size();
      if (!c.empty()) sink.add(c);
      if (progress) progress(k + 1, n);
    }
    return points;
  }
  if (!(tile_m > 0.0)) throw std::invalid_argument("map tiles: tile size must be positive");
  const float inv = static_cast<float>(1.0 / voxel_m);
  const auto per_tile = std::max<std::int64_t>(1, std::llround(tile_m / voxel_m));  // voxels
  const auto tileOf = [&](float v) { return floorDiv(voxelIndex(v, inv), per_tile); };

  // The tiles each keyframe's box overlaps (+ one voxel), keyframes in order within a tile.
  std::map<Tile, std::vector<std::size_t>> tiles;
  for (std::size_t k = 0; k < n; ++k) {
    if (boxes[k].isEmpty()) continue;
    const auto lo = boxes[k].min(), hi = boxes[k].max();
    const std::int64_t x0 = floorDiv(voxelIndex(lo.x(), inv) - 1, per_tile);
    const std::int64_t x1 = floorDiv(voxelIndex(hi.x(), inv) + 1, per_tile);
    const std::int64_t y0 = floorDiv(voxelIndex(lo.y(), inv) - 1, per_tile);
    const std::int64_t y1 = floorDiv(voxelIndex(hi.y(), inv) + 1, per_tile);
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t x = x0; x <= x1; ++x) tiles[{y, x}].push_back(k);
  }
  std::vector<std::size_t> last_tile(n, 0);
  std::size_t index = 0;
  for (const auto& [tile, members] : tiles) {
    for (std::size_t k : members) last_tile[k] = index;
    ++index;
  }

  if (!bounds.isEmpty()) {
    const Eigen::Vector3f margin = Eigen::Vector3f::Constant(static_cast<float>(voxel_m));
    bounds = Eigen::AlignedBox3f(bounds.min() - margin, bounds.max() + margin);
  }
  sink.begin(bounds);
  std::size_t points = 0, placed = 0, input = 0;
  index = 0;
  for (const auto& [tile, members] : tiles) {
    VoxelMerger merger(voxel_m, kTileChunkPoints);
    for (std::size_t k : members) {
      const Cloud c = transformed(clouds.get(keyframes[k].cloud), keyframes[k].T_world);
      if (last_tile[k] == index) {
        clouds.release(keyframes[k].cloud);
        input += c.size();
      }
      Cloud part;
      for (const auto& p : c)
        if (tileOf(p.y()) == tile.first && tileOf(p.x()) == tile.second) part.push_back(p);
      placed += part.size();
      merger.add(part);
    }
    const Cloud map = merger.finish();
    points += map.size();
    if (!map.empty()) sink.add(map);
    ++index;
    if (progress) progress(index, tiles.size());
  }
  // Every point must have landed in exactly one tile (the boxes hold the clouds).
  if (placed != input)
    throw std::logic_error("map tiles: " + std::to_string(input - std::min(input, placed)) +
                           " points fell outside their keyframe's tiles");
  return points;
}

}  // namespace slamroute::evaluate
