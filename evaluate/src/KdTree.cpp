// k-d tree behind the KdTree interface: nanoflann (header-only, Debian libnanoflann-dev) rather
// than PCL's KdTreeFLANN, which allocates on every query (with it, malloc/free took ~12 % of the
// SLAM time and the search ~60 %).
#include "slamroute/evaluate/KdTree.hpp"

#include <cmath>
#include <limits>
#include <nanoflann.hpp>

namespace slamroute::evaluate {
namespace {

/// nanoflann's dataset interface over the stored points.
struct PointsAdaptor {
  const std::vector<Eigen::Vector3f>* points = nullptr;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  float kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return (*points)[i][static_cast<int>(dim)];
  }
  template <class BBox>
  bool kdtree_get_bbox(BBox& /*bb*/) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointsAdaptor>,
                                                 PointsAdaptor, 3, std::uint32_t>;
constexpr std::size_t kLeafSize = 10;  ///< points per leaf (nanoflann's default)

}  // namespace

struct KdTree::Impl {
  std::vector<Eigen::Vector3f> points;
  PointsAdaptor adaptor;
  std::unique_ptr<Tree> tree;
};

KdTree::KdTree() : impl_(std::make_unique<Impl>()) {}
KdTree::~KdTree() = default;
KdTree::KdTree(KdTree&&) noexcept = default;
KdTree& KdTree::operator=(KdTree&&) noexcept = default;

void KdTree::build(const std::vector<Eigen::Vector3f>& points) {
  impl_ = std::make_unique<Impl>();
  n_ = points.size();
  if (points.empty()) return;
  impl_->points = points;
  impl_->adaptor.points = &impl_->points;
  impl_->tree = std::make_unique<Tree>(3, impl_->adaptor,
                                       nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize));
}

int KdTree::knn(const Eigen::Vector3f& q, int k, std::vector<int>& idx,
                std::vector<float>& sq_dist) const {
  return knnWithin(q, k, std::numeric_limits<float>::infinity(), idx, sq_dist);
}

int KdTree::knnWithin(const Eigen::Vector3f& q, int k, float max_sq_dist, std::vector<int>& idx,
                      std::vector<float>& sq_dist) const {
  idx.clear();
  sq_dist.clear();
  if (n_ == 0 || k <= 0) return 0;
  thread_local std::vector<std::uint32_t> found;
  const auto cap = static_cast<std::size_t>(k);
  found.resize(cap);
  sq_dist.resize(cap);
  nanoflann::KNNResultSet<float, std::uint32_t> result(cap);
  result.init(found.data(), sq_dist.data());
  // The result set takes only points closer than its last slot, which init sets to the largest
  // float: a bound there prunes every branch beyond it. The next float up keeps points at
  // exactly the bound.
  if (std::isfinite(max_sq_dist))
    sq_dist[cap - 1] = std::nextafter(max_sq_dist, std::numeric_limits<float>::infinity());
  impl_->tree->findNeighbors(result, q.data(), nanoflann::SearchParams());
  const std::size_t n = result.size();
  sq_dist.resize(n);
  idx.assign(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(n));
  return static_cast<int>(n);
}

}  // namespace slamroute::evaluate
