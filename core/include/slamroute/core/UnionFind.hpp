#pragma once
// Disjoint sets over 0..n-1 (union-find with path halving).
#include <cstddef>
#include <vector>

namespace slamroute {

/// Each set's representative is its smallest member, so the roots do not depend on the order
/// of the unions (callers that iterate over roots stay deterministic).
class UnionFind {
 public:
  explicit UnionFind(std::size_t n = 0) { reset(n); }
  /// n singleton sets.
  void reset(std::size_t n) {
    parent_.resize(n);
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<int>(i);
  }
  int find(int a) {
    while (parent_[index(a)] != a) {
      int& up = parent_[index(a)];
      up = parent_[index(up)];
      a = up;
    }
    return a;
  }
  /// Joins the sets of a and b; false when they were one set already.
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[index(a < b ? b : a)] = a < b ? a : b;
    return true;
  }
  /// Number of sets.
  int count() {
    int roots = 0;
    for (std::size_t i = 0; i < parent_.size(); ++i)
      roots += find(static_cast<int>(i)) == static_cast<int>(i) ? 1 : 0;
    return roots;
  }

 private:
  static std::size_t index(int a) { return static_cast<std::size_t>(a); }
  std::vector<int> parent_;
};

}  // namespace slamroute
