#pragma once
// The k nearest neighbours of a query point that moves a little between searches (a source point
// of a registration as the pose settles), found again without a tree search while the last
// answer must still hold. Exact, not approximate: the same neighbours in the same order as the
// tree search (at equal distances the lower index first).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/KdTree.hpp"

namespace slamroute::evaluate {

template <int K>
class KeptNeighbours {
 public:
  /// The K nearest points of `cloud` (the points `tree` was built on) to q among those at most
  /// sqrt(max_sq_dist) away, ascending, as KdTree::knnWithin(q, K, ...) gives them; returns how
  /// many (K when all were found).
  int find(const KdTree& tree, const Cloud& cloud, const Eigen::Vector3f& q, float max_sq_dist,
           std::vector<int>& idx, std::vector<float>& sq_dist) {
    reused_ = reuse(cloud, q, idx, sq_dist);
    if (reused_) return sq_dist.back() <= max_sq_dist ? K : K - 1;
    const int n = tree.knnWithin(q, K + 1, max_sq_dist, idx, sq_dist);
    // Every point but the K found is at least as far as the (K+1)-th, or beyond the bound.
    searched_at_ = q;
    clear_m_ = std::sqrt(static_cast<double>(n > K ? sq_dist.back() : max_sq_dist));
    if (n > K) {
      idx.pop_back();
      sq_dist.pop_back();
    }
    valid_ = n >= K;
    if (valid_) std::copy(idx.begin(), idx.end(), indices_.begin());
    return std::min(n, K);
  }
  /// Whether the last find() answered without a tree search.
  bool reused() const { return reused_; }

 private:
  /// The kept K are still the K nearest when each is nearer to q than any other point can be:
  /// those were at least clear_m_ from searched_at_, which lies |q - searched_at_| from q.
  bool reuse(const Cloud& cloud, const Eigen::Vector3f& q, std::vector<int>& idx,
             std::vector<float>& sq_dist) const {
    if (!valid_) return false;
    constexpr double kSlackM = 1e-4;  // far above the float rounding of the distances
    const double limit = clear_m_ - (q - searched_at_).cast<double>().norm() - kSlackM;
    std::array<std::pair<float, int>, K> near{};
    for (std::size_t j = 0; j < near.size(); ++j) {
      const int i = indices_[j];
      near[j] = {treeSqDist(q, cloud[static_cast<std::size_t>(i)]), i};
      if (!(std::sqrt(static_cast<double>(near[j].first)) < limit)) return false;
    }
    std::sort(near.begin(), near.end());  // by distance, then index: as the tree orders them
    idx.resize(near.size());
    sq_dist.resize(near.size());
    for (std::size_t j = 0; j < near.size(); ++j) std::tie(sq_dist[j], idx[j]) = near[j];
    return true;
  }

  std::array<int, K> indices_{};
  bool valid_ = false;
  bool reused_ = false;
  Eigen::Vector3f searched_at_ = Eigen::Vector3f::Zero();
  double clear_m_ = 0;
};

}  // namespace slamroute::evaluate
