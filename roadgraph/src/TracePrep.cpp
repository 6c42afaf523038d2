// Trace preparation for the hollow-cylinder test (paper §3.1 step 1): the direction of travel
// of every trace point and the thinning of the points to one centroid per voxel. The choices are
// documented in Intersections.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "slamroute/roadgraph/Intersections.hpp"

namespace slamroute::roadgraph {

Downsampled downsample(const std::vector<Point3>& pts, double voxel_m,
                       const std::vector<Vec3>* travel) {
  if (!(voxel_m > 0.0)) throw std::invalid_argument("roadgraph.nodes.downsample_m must be > 0");
  if (travel && travel->size() != pts.size())
    throw std::invalid_argument("downsample: travel directions and points differ in number");
  Downsampled out;
  out.voxel_of.resize(pts.size());
  std::unordered_map<std::uint64_t, int> index;
  index.reserve(pts.size() / 2 + 16);
  std::vector<int> count;
  auto q = [&](double v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / voxel_m))) &
           0x1FFFFFu;
  };
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::uint64_t key = (q(pts[i].x()) << 42) | (q(pts[i].y()) << 21) | q(pts[i].z());
    auto [it, inserted] = index.emplace(key, static_cast<int>(out.points.size()));
    if (inserted) {
      out.points.push_back(Point3::Zero());
      count.push_back(0);
      if (travel) out.axes.push_back(Eigen::Vector2d::Zero());
    }
    out.points[static_cast<std::size_t>(it->second)] += pts[i];
    if (travel) {
      const Vec3& d = (*travel)[i];
      const double n2 = d.x() * d.x() + d.y() * d.y();
      if (n2 > 1e-12)
        out.axes[static_cast<std::size_t>(it->second)] +=
            Eigen::Vector2d(d.x() * d.x() - d.y() * d.y(), 2.0 * d.x() * d.y()) / n2;
    }
    ++count[static_cast<std::size_t>(it->second)];
    out.voxel_of[i] = it->second;
  }
  for (std::size_t v = 0; v < out.points.size(); ++v) out.points[v] /= count[v];
  return out;
}

std::vector<Vec3> travelDirections(const Traces& traces, double span_m, double max_gap_s) {
  return travelDirections(traces, byVehicleThenTime(traces), span_m, max_gap_s);
}

std::vector<Vec3> travelDirections(const Traces& traces, const std::vector<std::size_t>& order,
                                   double span_m, double max_gap_s) {
  const auto& P = traces.points;
  if (order.size() != P.size())
    throw std::invalid_argument("travelDirections: order and trace points differ in number");
  auto linked = [&](std::size_t a, std::size_t b) {  // consecutive in order, same run
    return P[a].vehicle == P[b].vehicle && std::abs(P[b].t - P[a].t) <= max_gap_s;
  };
  const double span2 = span_m * span_m;
  const std::size_t max_steps = 200;  // bounds the search at very slow speeds
  std::vector<Vec3> dir(P.size(), Vec3::Zero());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Point3& p = P[order[k]].pos;
    std::size_t ahead = k, behind = k;
    for (std::size_t s = 0;
         s < max_steps && ahead + 1 < order.size() && linked(order[ahead], order[ahead + 1]); ++s) {
      ++ahead;
      if ((P[order[ahead]].pos - p).head<2>().squaredNorm() >= span2) break;
    }
    for (std::size_t s = 0; s < max_steps && behind > 0 && linked(order[behind - 1], order[behind]);
         ++s) {
      --behind;
      if ((P[order[behind]].pos - p).head<2>().squaredNorm() >= span2) break;
    }
    Vec3 d = P[order[ahead]].pos - P[order[behind]].pos;
    d.z() = 0.0;
    if (d.norm() >= span_m) dir[order[k]] = d.normalized();
  }
  return dir;
}

}  // namespace slamroute::roadgraph
