#pragma once
// Seeded K-means on plane points (k-means++ seeding, then Lloyd iterations). Same points, k
// and seed give the same result, bit for bit: the random draws use only the raw output of
// std::mt19937_64, never a standard distribution (whose algorithm the library may change).
#include <cstdint>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute {

struct KMeansResult {
  std::vector<int> label;      ///< per point: its cluster in [0, k)
  std::vector<Point2> centre;  ///< per cluster: weighted mean of its points
  double inertia = 0.0;        ///< sum of weight * squared distance to the own centre (m^2)
  int iterations = 0;          ///< Lloyd iterations run
};

struct KMeansOptions {
  std::uint64_t seed = 1;
  int maxIterations = 100;
  std::vector<double> weight;  ///< per point, > 0; empty means all 1
};

/// Clusters points into k groups. Every cluster keeps at least one point (an emptied cluster
/// takes the point farthest from its centre). Throws std::invalid_argument when k < 1,
/// k > points.size() or weights do not match.
KMeansResult kMeans(const std::vector<Point2>& points, int k, const KMeansOptions& options = {});

}  // namespace slamroute
