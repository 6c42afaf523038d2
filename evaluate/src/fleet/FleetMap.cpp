// The merged map and its completeness: the share of the world's street facades (vertical
// triangles of world.ply within facade_street_m of a driven street) that has a map point within
// covered_m.
#include <algorithm>
#include <cmath>
#include <random>

#include "FleetInternal.hpp"
#include "FleetMap.hpp"
#include "slamroute/evaluate/KdTree.hpp"

namespace slamroute::evaluate {

Cloud vehicleMap(const FleetVehicleInput& v, const Trajectory& poses, int stride, double voxel_m) {
  Cloud map;
  for (std::size_t i = 0; i < v.scans->size(); i += static_cast<std::size_t>(stride)) {
    const Cloud part =
        transformed(bodyCloud(*v.scans, poses, i, voxel_m), poseNearest(poses, v.scans->time(i)));
    map.insert(map.end(), part.begin(), part.end());
  }
  return voxelFilter(map, voxel_m);
}

namespace {

/// Points on the vertical triangles (|normal z| < 0.3), about one per spacing^2, deterministic.
Cloud facadeSamples(const Mesh& mesh, double spacing_m) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  Cloud out;
  for (const auto& f : mesh.faces) {
    const Eigen::Vector3f a = mesh.vertices[static_cast<std::size_t>(f[0])];
    const Eigen::Vector3f ab = mesh.vertices[static_cast<std::size_t>(f[1])] - a;
    const Eigen::Vector3f ac = mesh.vertices[static_cast<std::size_t>(f[2])] - a;
    const Eigen::Vector3f n = ab.cross(ac);
    const float area = 0.5f * n.norm();
    if (area <= 0.f || std::abs(n.z()) > 0.3f * n.norm()) continue;
    const int count = static_cast<int>(std::ceil(area / (spacing_m * spacing_m)));
    for (int i = 0; i < count; ++i) {
      float s = u(rng), t = u(rng);
      if (s + t > 1.f) s = 1.f - s, t = 1.f - t;
      out.push_back(a + s * ab + t * ac);
    }
  }
  return out;
}

/// The ground-truth positions, flattened to z = 0, every ~2 m.
std::vector<Eigen::Vector3f> streetPoints(const std::vector<Trajectory>& gts) {
  std::vector<Eigen::Vector3f> pts;
  for (const auto& gt : gts) {
    Eigen::Vector3f last(1e9f, 1e9f, 0.f);
    for (const auto& p : gt) {
      const Eigen::Vector3f q(static_cast<float>(p.T_world_body.translation().x()),
                              static_cast<float>(p.T_world_body.translation().y()), 0.f);
      if ((q - last).norm() < 2.f) continue;
      pts.push_back(q);
      last = q;
    }
  }
  return pts;
}

bool within(const KdTree& tree, const Eigen::Vector3f& q, double r, std::vector<int>& idx,
            std::vector<float>& d2) {
  return tree.knn(q, 1, idx, d2) == 1 && d2[0] <= r * r;
}

}  // namespace

Cloud streetFacades(const Mesh& mesh, const std::vector<Trajectory>& ground_truths,
                    const FleetMergeOptions& opt) {
  KdTree streets;
  streets.build(streetPoints(ground_truths));
  std::vector<int> idx;
  std::vector<float> d2;
  Cloud kept;
  for (const auto& p : facadeSamples(mesh, opt.facade_sample_m))
    if (within(streets, Eigen::Vector3f(p.x(), p.y(), 0.f), opt.facade_street_m, idx, d2))
      kept.push_back(p);
  return kept;
}

double coveredPct(const Cloud& facades, const Cloud& map, double covered_m) {
  if (facades.empty() || map.empty()) return 0.0;
  KdTree tree;
  tree.build(map);
  std::vector<int> idx;
  std::vector<float> d2;
  std::size_t hit = 0;
  for (const auto& p : facades) hit += within(tree, p, covered_m, idx, d2) ? 1 : 0;
  return 100.0 * static_cast<double>(hit) / static_cast<double>(facades.size());
}

}  // namespace slamroute::evaluate
