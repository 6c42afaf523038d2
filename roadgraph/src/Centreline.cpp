// Street centrelines (paper §3.1 step 2): points are ordered by geodesic distance (Dijkstra over
// the cluster's neighbourhood graph) from one end and averaged in polyline_step_m bins; robust to
// GPS noise across the road and to curves.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

#include "Streets.hpp"

namespace slamroute::roadgraph::detail {

double arcPosition(const Polyline& pl, const Point3& p) {
  double best = std::numeric_limits<double>::infinity(), best_s = 0.0, s = 0.0;
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
    const Vec3 d = pl[i + 1] - pl[i];
    const double len = d.norm();
    const double t = len > 1e-9 ? std::clamp((p - pl[i]).dot(d) / (len * len), 0.0, 1.0) : 0.0;
    const double dist = (pl[i] + t * d - p).squaredNorm();
    if (dist < best) {
      best = dist;
      best_s = s + t * len;
    }
    s += len;
  }
  return best_s;
}

Point3 pointAtArc(const Polyline& pl, double arc) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
    const double len = (pl[i + 1] - pl[i]).norm();
    if (s + len >= arc && len > 1e-9) return pl[i] + (pl[i + 1] - pl[i]) * ((arc - s) / len);
    s += len;
  }
  return pl.back();
}

void geodesic(const std::vector<Point3>& pts, const PointGrid& grid, const std::vector<int>& label,
              int comp, double tol, int src, std::vector<double>& dist) {
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  dist[static_cast<std::size_t>(src)] = 0.0;
  pq.emplace(0.0, src);
  const double tol2 = tol * tol;
  while (!pq.empty()) {
    const auto [d, i] = pq.top();
    pq.pop();
    if (d > dist[static_cast<std::size_t>(i)]) continue;
    const Point3& p = pts[static_cast<std::size_t>(i)];
    grid.forEachNear(p, tol, tol, [&](int j) {
      if (label[static_cast<std::size_t>(j)] != comp) return;
      const double d2 = (pts[static_cast<std::size_t>(j)] - p).squaredNorm();
      if (d2 > tol2) return;
      const double nd = d + std::sqrt(d2);
      if (nd < dist[static_cast<std::size_t>(j)]) {
        dist[static_cast<std::size_t>(j)] = nd;
        pq.emplace(nd, j);
      }
    });
  }
}

Polyline binnedCentre(const std::vector<Point3>& sp, const std::vector<int>& members,
                      const std::vector<double>& d, double step_m) {
  double total = 0.0;
  for (int i : members)
    if (std::isfinite(d[static_cast<std::size_t>(i)]))
      total = std::max(total, d[static_cast<std::size_t>(i)]);
  const int nbins = std::max(1, static_cast<int>(std::ceil(total / step_m)));
  std::vector<Point3> bsum(static_cast<std::size_t>(nbins) + 1, Point3::Zero());
  std::vector<int> bcnt(static_cast<std::size_t>(nbins) + 1, 0);
  for (int i : members) {
    const double di = d[static_cast<std::size_t>(i)];
    if (!std::isfinite(di)) continue;
    const auto bin = static_cast<std::size_t>(std::min(nbins, static_cast<int>(di / step_m)));
    bsum[bin] += sp[static_cast<std::size_t>(i)];
    ++bcnt[bin];
  }
  Polyline centre;
  for (std::size_t k = 0; k < bsum.size(); ++k)
    if (bcnt[k] > 0) centre.push_back(bsum[k] / bcnt[k]);
  return centre;
}

void dropSpikes(Polyline& pl, double min_leg_m) {
  const double cos_back = std::cos(150.0 * std::numbers::pi / 180.0);
  for (std::size_t i = 1; i + 1 < pl.size();) {
    const Eigen::Vector2d in = (pl[i] - pl[i - 1]).head<2>(), out = (pl[i + 1] - pl[i]).head<2>();
    const bool long_legs = in.norm() >= min_leg_m && out.norm() >= min_leg_m;
    if (long_legs && in.dot(out) < cos_back * in.norm() * out.norm()) {
      pl.erase(pl.begin() + static_cast<std::ptrdiff_t>(i));
      i = std::max<std::size_t>(1, i - 1);  // the vertex before may now be the tip of a spike
    } else {
      ++i;
    }
  }
}

std::pair<Point3, Eigen::Vector2d> tipAndHeading(const Polyline& c, bool at_u, double reach) {
  const Polyline pl = at_u ? Polyline(c.rbegin(), c.rend()) : c;
  const Point3& tip = pl.back();
  Point3 back = pl.front();
  double run = 0.0;
  for (std::size_t i = pl.size() - 1; i > 0; --i) {
    run += (pl[i] - pl[i - 1]).head<2>().norm();
    back = pl[i - 1];
    if (run >= reach) break;
  }
  const Eigen::Vector2d d = (tip - back).head<2>();
  return {tip, d.norm() > 1e-6 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d::Zero()};
}

}  // namespace slamroute::roadgraph::detail
