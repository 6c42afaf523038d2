#pragma once
// Exact nearest-neighbour search over a point cloud: a k-d tree of our own (src/KdTree.cpp says
// why not nanoflann's), behind a pimpl so the header stays light.
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace slamroute::evaluate {

/// The tree's squared distance (float, x + y + z in that order): whatever orders neighbours as
/// the tree does must form it the same way, to the last bit.
inline float treeSqDist(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  float r = 0;
  for (int d = 0; d < 3; ++d) {
    const float diff = a[d] - b[d];
    r += diff * diff;
  }
  return r;
}

class KdTree {
 public:
  KdTree();
  ~KdTree();
  KdTree(KdTree&&) noexcept;
  KdTree& operator=(KdTree&&) noexcept;
  void build(const std::vector<Eigen::Vector3f>& points);
  std::size_t size() const { return n_; }
  /// k nearest neighbours of q; fills idx / sq_dist (ascending; at equal distances the lower
  /// index first, so the answer does not depend on the tree's shape); returns how many.
  int knn(const Eigen::Vector3f& q, int k, std::vector<int>& idx,
          std::vector<float>& sq_dist) const;
  /// The same, among the points at most sqrt(max_sq_dist) from q: the same neighbours as knn
  /// whenever its k-th lies within the bound, found without visiting the farther branches.
  int knnWithin(const Eigen::Vector3f& q, int k, float max_sq_dist, std::vector<int>& idx,
                std::vector<float>& sq_dist) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::size_t n_ = 0;
};

}  // namespace slamroute::evaluate
