#pragma once
// Shared by the drive tests: the drive set-up, distances to lane shapes, the edges of
// pose_edges.csv.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/Config.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::test {

/// The simulate config of the drive tests: the default one with the VLP-16 preset.
inline simulate::Config vlp16Config() {
  simulate::Config cfg;
  cfg.lidar.preset = "vlp16";
  return cfg;
}

/// A drive of `route` on the shipped net `net` (below networks/) into `out`; no world.ply.
inline simulate::DriveOptions testDrive(const std::string& net, const std::filesystem::path& route,
                                        const std::filesystem::path& out, std::uint64_t seed) {
  simulate::DriveOptions o;
  o.net = std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks" / net;
  o.route_file = route;
  o.out_dir = out;
  o.seed = seed;
  o.write_world_mesh = false;
  return o;
}

/// Horizontal distance from p to a polyline.
inline double distToPolyline(const Point3& p, const Polyline& pl) {
  double best = 1e18;
  for (std::size_t i = 1; i < pl.size(); ++i) {
    const Eigen::Vector2d a = pl[i - 1].head<2>(), b = pl[i].head<2>(), q = p.head<2>();
    const double len2 = (b - a).squaredNorm();
    const double s = len2 > 0 ? std::clamp((q - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + s * (b - a) - q).norm());
  }
  return best;
}

/// The distinct edges of a drive folder's pose_edges.csv, in order.
inline std::vector<std::string> drivenEdges(const std::filesystem::path& dir) {
  std::ifstream in(dir / drive_files::kPoseEdges);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> seq;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string idx, t, edge;
    std::getline(ss, idx, ',');
    std::getline(ss, t, ',');
    std::getline(ss, edge, ',');
    if (seq.empty() || seq.back() != edge) seq.push_back(edge);
  }
  return seq;
}

}  // namespace slamroute::test
