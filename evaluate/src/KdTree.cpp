// k-d tree behind the KdTree interface. The SLAM rebuilds its local map's trees at every scan,
// so the build costs as much as the searches; this tree partitions the points themselves (with
// their input indices) rather than an index array into them, as nanoflann does, so every pass
// over a subtree and every leaf a search reads lies in consecutive memory. Splits follow the
// sliding midpoint rule (Maneewongvatana & Mount): the middle of the node's cell along its
// widest side, moved onto the nearest point when all points lie on one side of it.
#include "slamroute/evaluate/KdTree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

namespace slamroute::evaluate {
namespace {

constexpr std::uint32_t kLeafSize = 20;  ///< at most this many points per leaf

struct Entry {
  Eigen::Vector3f p;
  std::uint32_t index;  ///< in the input
};

struct Box {
  Eigen::Vector3f lo, hi;
};

struct Node {
  std::uint32_t a = 0, b = 0;  ///< leaf: entries [a, b); inner: the low and the high child
  float div_low = 0.0f;        ///< inner: the low child's largest value along dim
  float div_high = 0.0f;       ///< inner: the high child's smallest value along dim
  int dim = -1;                ///< -1: a leaf
};

struct Split {
  int dim = 0;
  float value = 0.0f;
  std::uint32_t n_low = 0;  ///< entries that go to the low child
};

/// The k best among the points closer than a bound, ascending by distance and, at equal
/// distances, by index: the answer a brute-force search sorted that way gives, whatever the
/// tree's shape.
class Best {
 public:
  Best(std::size_t k, float bound, std::uint32_t* idx, float* d2)
      : k_(k), bound_(bound), idx_(idx), d2_(d2) {}
  float worst() const { return n_ == k_ ? d2_[k_ - 1] : bound_; }
  void add(float d2, std::uint32_t index) {
    if (n_ == k_ ? !before(d2, index, k_ - 1) : !(d2 < bound_)) return;
    std::size_t i = std::min(n_, k_ - 1);
    for (; i > 0 && before(d2, index, i - 1); --i) {
      d2_[i] = d2_[i - 1];
      idx_[i] = idx_[i - 1];
    }
    d2_[i] = d2;
    idx_[i] = index;
    n_ = std::min(n_ + 1, k_);
  }
  std::size_t size() const { return n_; }

 private:
  bool before(float d2, std::uint32_t index, std::size_t i) const {
    return d2 < d2_[i] || (d2 == d2_[i] && index < idx_[i]);
  }
  std::size_t k_, n_ = 0;
  float bound_;
  std::uint32_t* idx_;
  float* d2_;
};

float squared(float d) { return d * d; }

}  // namespace

struct KdTree::Impl {
  std::vector<Entry> entries;
  std::vector<Node> nodes;  ///< nodes[0]: the root
  Box root;

  Box bounds(std::uint32_t first, std::uint32_t last) const;
  Split split(std::uint32_t first, std::uint32_t last, const Box& cell);
  std::uint32_t divide(std::uint32_t first, std::uint32_t last, Box& box);
  void search(std::uint32_t node, const Eigen::Vector3f& q, Eigen::Vector3f& gaps,
              Best& best) const;
};

KdTree::KdTree() : impl_(std::make_unique<Impl>()) {}
KdTree::~KdTree() = default;
KdTree::KdTree(KdTree&&) noexcept = default;
KdTree& KdTree::operator=(KdTree&&) noexcept = default;

void KdTree::build(const std::vector<Eigen::Vector3f>& points) {
  if (!impl_) impl_ = std::make_unique<Impl>();
  Impl& t = *impl_;
  n_ = points.size();
  t.entries.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) t.entries[i] = {points[i], static_cast<std::uint32_t>(i)};
  t.nodes.clear();
  if (n_ == 0) return;
  const auto n = static_cast<std::uint32_t>(n_);
  t.root = t.bounds(0, n);
  Box box = t.root;
  t.divide(0, n, box);
}

Box KdTree::Impl::bounds(std::uint32_t first, std::uint32_t last) const {
  Box b{entries[first].p, entries[first].p};
  for (std::uint32_t i = first + 1; i < last; ++i) {
    b.lo = b.lo.cwiseMin(entries[i].p);
    b.hi = b.hi.cwiseMax(entries[i].p);
  }
  return b;
}

/// `box` comes in as the node's cell and goes out as its points' bounding box.
std::uint32_t KdTree::Impl::divide(std::uint32_t first, std::uint32_t last, Box& box) {
  const auto id = static_cast<std::uint32_t>(nodes.size());
  nodes.emplace_back();
  if (last - first <= kLeafSize) {
    box = bounds(first, last);
    nodes[id] = {first, last, 0.0f, 0.0f, -1};
    return id;
  }
  const Split s = split(first, last, box);
  Box low = box, high = box;
  low.hi[s.dim] = s.value;
  high.lo[s.dim] = s.value;
  const std::uint32_t a = divide(first, first + s.n_low, low);
  const std::uint32_t b = divide(first + s.n_low, last, high);
  nodes[id] = {a, b, low.hi[s.dim], high.lo[s.dim], s.dim};
  box = {low.lo.cwiseMin(high.lo), low.hi.cwiseMax(high.hi)};
  return id;
}

/// Sliding midpoint: among the cell's widest sides, the one along which the points spread most;
/// its middle, clamped to the points; the points below it first, then those on it, then those
/// above, and the cut in that order as near the middle of the count as the values allow.
Split KdTree::Impl::split(std::uint32_t first, std::uint32_t last, const Box& cell) {
  const Eigen::Vector3f side = cell.hi - cell.lo;
  const float widest = side.maxCoeff();
  Split s;
  float spread = -1.0f, lo = 0.0f, hi = 0.0f;
  for (int d = 0; d < 3; ++d) {
    // All points in one place (no side has length): the first axis, for a split in the middle.
    const bool among_widest = widest > 0.0f ? side[d] > (1.0f - 1e-5f) * widest : d == 0;
    if (!among_widest) continue;
    float mn = entries[first].p[d], mx = mn;
    for (std::uint32_t i = first + 1; i < last; ++i) {
      mn = std::min(mn, entries[i].p[d]);
      mx = std::max(mx, entries[i].p[d]);
    }
    if (mx - mn > spread) std::tie(s.dim, spread, lo, hi) = std::tuple(d, mx - mn, mn, mx);
  }
  s.value = std::clamp((cell.lo[s.dim] + cell.hi[s.dim]) / 2, lo, hi);
  const auto begin = entries.begin() + first, end = entries.begin() + last;
  const auto below =
      std::partition(begin, end, [&](const Entry& e) { return e.p[s.dim] < s.value; });
  const auto on = std::partition(below, end, [&](const Entry& e) { return e.p[s.dim] <= s.value; });
  const auto n_below = static_cast<std::uint32_t>(below - begin);
  const auto n_up_to = static_cast<std::uint32_t>(on - begin);
  const std::uint32_t half = (last - first) / 2;
  s.n_low = n_below > half ? n_below : (n_up_to < half ? n_up_to : half);
  return s;
}

/// Visits the child on the query's side first, and the other only if its cell can still hold a
/// point as close as the k-th found. `gaps` are the query's squared distances to the current
/// cell per axis; their sum, formed in the order a point's distance is, never exceeds the
/// distance of a point in the cell even after rounding, so points tied with the k-th are
/// reached wherever they lie.
void KdTree::Impl::search(std::uint32_t node, const Eigen::Vector3f& q, Eigen::Vector3f& gaps,
                          Best& best) const {
  const Node& n = nodes[node];
  if (n.dim < 0) {
    for (std::uint32_t i = n.a; i < n.b; ++i)
      best.add(treeSqDist(q, entries[i].p), entries[i].index);
    return;
  }
  const float v = q[n.dim];
  const bool low_first = (v - n.div_low) + (v - n.div_high) < 0.0f;
  search(low_first ? n.a : n.b, q, gaps, best);
  const float gap = gaps[n.dim];
  gaps[n.dim] = squared(low_first ? v - n.div_high : v - n.div_low);
  float cell_d2 = 0.0f;
  for (int d = 0; d < 3; ++d) cell_d2 += gaps[d];
  if (cell_d2 <= best.worst()) search(low_first ? n.b : n.a, q, gaps, best);
  gaps[n.dim] = gap;
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
  // Points at exactly the bound are kept: the bound is the next float up.
  const float bound = std::isfinite(max_sq_dist)
                          ? std::nextafter(max_sq_dist, std::numeric_limits<float>::infinity())
                          : std::numeric_limits<float>::max();
  Best best(cap, bound, found.data(), sq_dist.data());
  const Box& r = impl_->root;
  Eigen::Vector3f gaps = Eigen::Vector3f::Zero();
  for (int d = 0; d < 3; ++d) {
    if (q[d] < r.lo[d]) gaps[d] = squared(q[d] - r.lo[d]);
    if (q[d] > r.hi[d]) gaps[d] = squared(q[d] - r.hi[d]);
  }
  impl_->search(0, q, gaps, best);
  const std::size_t n = best.size();
  sq_dist.resize(n);
  idx.resize(n);
  for (std::size_t i = 0; i < n; ++i) idx[i] = static_cast<int>(found[i]);
  return static_cast<int>(n);
}

}  // namespace slamroute::evaluate
