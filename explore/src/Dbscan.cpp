// DBSCAN with a uniform bucket grid of cell eps for the neighbourhood queries.
#include "slamroute/explore/Dbscan.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>

namespace slamroute::explore {
namespace {

class Buckets {
 public:
  Buckets(const std::vector<Point2>& pts, double eps) : pts_(pts), eps_(eps) {
    for (std::size_t i = 0; i < pts.size(); ++i) cells_[key(pts[i])].push_back(static_cast<int>(i));
  }
  std::vector<int> near(int i) const {
    std::vector<int> out;
    const auto [cx, cy] = key(pts_[static_cast<std::size_t>(i)]);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find({cx + dx, cy + dy});
        if (it == cells_.end()) continue;
        for (int j : it->second)
          if ((pts_[static_cast<std::size_t>(j)] - pts_[static_cast<std::size_t>(i)]).norm() <=
              eps_)
            out.push_back(j);
      }
    return out;
  }

 private:
  std::pair<std::int64_t, std::int64_t> key(const Point2& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / eps_)),
            static_cast<std::int64_t>(std::floor(p.y() / eps_))};
  }
  const std::vector<Point2>& pts_;
  double eps_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<int>> cells_;
};

}  // namespace

DbscanResult dbscan(const std::vector<Point2>& points, double eps, int min_points) {
  if (!(eps > 0.0)) throw std::invalid_argument("dbscan: eps must be > 0");
  if (min_points < 1) throw std::invalid_argument("dbscan: min_points must be >= 1");
  constexpr int kUnvisited = -2;
  DbscanResult r;
  r.label.assign(points.size(), kUnvisited);
  const Buckets buckets(points, eps);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (r.label[i] != kUnvisited) continue;
    std::vector<int> seeds = buckets.near(static_cast<int>(i));
    if (static_cast<int>(seeds.size()) < min_points) {
      r.label[i] = -1;
      continue;
    }
    const int id = r.clusters++;
    r.label[i] = id;
    for (std::size_t k = 0; k < seeds.size(); ++k) {
      const auto j = static_cast<std::size_t>(seeds[k]);
      if (r.label[j] == -1) r.label[j] = id;  // noise reached from a core point: border
      if (r.label[j] != kUnvisited) continue;
      r.label[j] = id;
      const std::vector<int> more = buckets.near(static_cast<int>(j));
      if (static_cast<int>(more.size()) >= min_points)
        seeds.insert(seeds.end(), more.begin(), more.end());
    }
  }
  return r;
}

}  // namespace slamroute::explore
