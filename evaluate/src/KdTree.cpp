// The only PCL k-d tree translation unit of the module.
#include "slamroute/evaluate/KdTree.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

namespace slamroute::evaluate {

struct KdTree::Impl {
  pcl::KdTreeFLANN<pcl::PointXYZ> tree{false};  // unsorted is faster; we sort below when needed
};

KdTree::KdTree() : impl_(std::make_unique<Impl>()) {}
KdTree::~KdTree() = default;
KdTree::KdTree(KdTree&&) noexcept = default;
KdTree& KdTree::operator=(KdTree&&) noexcept = default;

void KdTree::build(const std::vector<Eigen::Vector3f>& points) {
  impl_ = std::make_unique<Impl>();
  n_ = points.size();
  if (points.empty()) return;
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    (*cloud)[i] = pcl::PointXYZ(points[i].x(), points[i].y(), points[i].z());
  impl_->tree.setSortedResults(true);
  impl_->tree.setInputCloud(cloud);
}

int KdTree::knn(const Eigen::Vector3f& q, int k, std::vector<int>& idx,
                std::vector<float>& sq_dist) const {
  idx.clear();
  sq_dist.clear();
  if (n_ == 0 || k <= 0) return 0;
  pcl::PointXYZ p(q.x(), q.y(), q.z());
  idx.resize(static_cast<std::size_t>(k));
  sq_dist.resize(static_cast<std::size_t>(k));
  const int found = impl_->tree.nearestKSearch(p, k, idx, sq_dist);
  idx.resize(static_cast<std::size_t>(std::max(found, 0)));
  sq_dist.resize(idx.size());
  return found;
}

}  // namespace slamroute::evaluate
