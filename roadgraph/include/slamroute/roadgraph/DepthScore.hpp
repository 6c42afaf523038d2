#pragma once
// Paper §3.1 step 4: LiDAR matching quality of a depth image from the spread of its normals
// (eqs. 3-4), and edge weights as the mean score of the frames along each edge.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/roadgraph/Config.hpp"

namespace slamroute::roadgraph {

struct DepthImage {
  int width = 0, height = 0;
  std::vector<std::uint16_t> mm;  ///< row-major depth [mm], 0 = no return
  std::uint16_t at(int x, int y) const {
    return mm[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(x)];
  }
};

/// Reads a 16-bit PNG. Throws std::runtime_error naming the file when missing, corrupt or not
/// single-channel 16-bit.
DepthImage readDepthPng(const std::filesystem::path& path);
/// Writes a 16-bit PNG atomically (tests, tools). Throws std::runtime_error naming the file.
void writeDepthPng(const std::filesystem::path& path, const DepthImage& img);

struct FrameScore {
  double score = 0.0;  ///< normalised entropy of the normal scatter eigenvalues, [0, 1]
  int normals = 0;     ///< normals that entered the score
  Vec3 eigenvalues = Vec3::Zero();  ///< of the normals' scatter matrix, descending, sum 1
};
/// Eq. 3 reprojection, eq. 4 normals, spread score (see DepthScore.cpp for the definition).
FrameScore scoreDepthImage(const DepthImage& img, const DepthConfig& cfg);

struct DepthFrame {
  long frame = 0;
  double t = 0.0;
  std::string vehicle;
  Point3 pos = Point3::Zero();  ///< camera position in the world [m]
  std::filesystem::path file;   ///< absolute path of the PNG
  int width = 0, height = 0;    ///< the camera's image size [px]; 0 when the index does not say
};
/// Reads depth/index.csv (columns by header name; needs x, y, z and file; width and height when
/// present). Throws naming the file.
std::vector<DepthFrame> readDepthIndex(const std::filesystem::path& index_csv);

struct WeightStats {
  std::size_t frames = 0, scored = 0, failed = 0, unassigned = 0;
  std::size_t streets = 0, streets_with_frames = 0;
  double mean_score = 0.0;
  double fallback_weight = 1.0;
};
/// Scores every frame (TBB, both cores), assigns each to the nearest street polyline, sets each
/// edge's weight to the mean score of its street's frames. Missing/corrupt frames are skipped with
/// a warning; streets without frames get the mean of all scored frames; with no scored frame at
/// all every edge gets cfg.fallback_weight (warning). Never throws for a bad frame.
WeightStats assignDepthWeights(RoadGraph& graph, const std::vector<DepthFrame>& frames,
                               const DepthConfig& cfg);

}  // namespace slamroute::roadgraph
