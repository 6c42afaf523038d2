// Fleet strategy: DBSCAN segments -> Hungarian over groups (K-means splits) -> K-means waypoints.
#include "FleetStrategy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slamroute/core/Hungarian.hpp"
#include "slamroute/core/KMeans.hpp"
#include "slamroute/explore/Dbscan.hpp"
#include "slamroute/explore/KnownPaths.hpp"

namespace slamroute::explore {
namespace {

struct Target {
  Point2 pos;
  int edge;
};
using Segment = std::vector<Target>;

/// Frontier points on open streets; without any, the midpoints of the open streets.
std::vector<Target> targetPoints(const FleetView& f, int k) {
  std::vector<Target> pts;
  for (const FrontierPoint& fp : f.streets.frontierPoints())
    if (f.open(fp.edge, k)) pts.push_back({fp.pos, fp.edge});
  if (!pts.empty()) return pts;
  for (int e = 0; e < f.pg.m; ++e)
    if (f.open(e, k)) pts.push_back({f.streets.midpoint(e), e});
  return pts;
}

/// DBSCAN segments; noise points become segments of their own (nothing is left unexplored).
std::vector<Segment> segmentsOf(const std::vector<Target>& pts, const FleetConfig& cfg) {
  std::vector<Point2> xy;
  for (const auto& t : pts) xy.push_back(t.pos);
  const DbscanResult db = dbscan(xy, cfg.dbscan_eps_m, cfg.dbscan_min_points);
  std::vector<Segment> segs(static_cast<std::size_t>(db.clusters));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (db.label[i] >= 0)
      segs[static_cast<std::size_t>(db.label[i])].push_back(pts[i]);
    else
      segs.push_back({pts[i]});
  }
  return segs;
}

std::vector<Point2> positions(const Segment& s) {
  std::vector<Point2> xy;
  for (const auto& t : s) xy.push_back(t.pos);
  return xy;
}

Point2 centreOf(const Segment& s) {
  Point2 c = Point2::Zero();
  for (const auto& t : s) c += t.pos;
  return c / static_cast<double>(s.size());
}

/// Splits the largest segment in two by K-means until there are `groups` segments.
void splitLargest(std::vector<Segment>& segs, int groups, std::uint64_t seed) {
  while (static_cast<int>(segs.size()) < groups) {
    auto big = std::max_element(segs.begin(), segs.end(), [](const Segment& a, const Segment& b) {
      return a.size() < b.size();
    });
    if (big->size() < 2) return;
    KMeansOptions o;
    o.seed = seed;
    const KMeansResult km = kMeans(positions(*big), 2, o);
    Segment a, b;
    for (std::size_t i = 0; i < big->size(); ++i) (km.label[i] == 0 ? a : b).push_back((*big)[i]);
    *big = std::move(a);
    segs.push_back(std::move(b));
  }
}

/// Waypoints inside a segment for the m members of a group: K-means centres snapped to the
/// nearest point; the waypoint nearest their mean goes to the leader (index 0 of the result).
std::vector<Target> waypoints(const Segment& s, int m, std::uint64_t seed) {
  const int n = std::min<int>(m, static_cast<int>(s.size()));
  KMeansOptions o;
  o.seed = seed;
  const KMeansResult km = kMeans(positions(s), n, o);
  std::vector<Target> wp;
  for (const Point2& c : km.centre) {
    auto it = std::min_element(s.begin(), s.end(), [&](const Target& a, const Target& b) {
      return (a.pos - c).squaredNorm() < (b.pos - c).squaredNorm();
    });
    wp.push_back(*it);
  }
  Point2 mean = Point2::Zero();
  for (const auto& w : wp) mean += w.pos;
  mean /= static_cast<double>(wp.size());
  auto lead = std::min_element(wp.begin(), wp.end(), [&](const Target& a, const Target& b) {
    return (a.pos - mean).squaredNorm() < (b.pos - mean).squaredNorm();
  });
  std::iter_swap(wp.begin(), lead);
  return wp;
}

class FleetStrategy : public Strategy {
 public:
  FleetStrategy(const FleetConfig& cfg, int group_size, std::uint64_t seed)
      : cfg_(cfg), group_size_(group_size), seed_(seed) {}

  Decision decide(const FleetView& f, int k) override {
    const std::vector<Target> pts = targetPoints(f, k);
    if (pts.empty()) return {};
    const int K = static_cast<int>(f.vehicles.size());
    const int groups = (K + group_size_ - 1) / group_size_, g = k / group_size_;
    std::vector<Segment> segs = segmentsOf(pts, cfg_);
    splitLargest(segs, groups, seed_);
    const int seg = segmentOfGroup(f, segs, groups, g);
    if (seg < 0) return nearestOpen(f, k);
    const Target wp = waypointOf(f, segs[static_cast<std::size_t>(seg)], g, k);
    return towards(f, k, wp);
  }

 private:
  /// Hungarian assignment of groups to segments, cost D_ij / W_j (leader to segment centre).
  int segmentOfGroup(const FleetView& f, const std::vector<Segment>& segs, int groups,
                     int g) const {
    std::vector<std::vector<double>> cost(static_cast<std::size_t>(groups));
    for (int i = 0; i < groups; ++i) {
      const Point2 leader = f.vehicles[static_cast<std::size_t>(i * group_size_)].pos;
      for (const Segment& s : segs)
        cost[static_cast<std::size_t>(i)].push_back((centreOf(s) - leader).norm() /
                                                    static_cast<double>(s.size()));
    }
    return hungarianAssignment(cost).columnOfRow[static_cast<std::size_t>(g)];
  }

  /// The member's waypoint: the leader takes the central one, followers by Hungarian on distance.
  Target waypointOf(const FleetView& f, const Segment& s, int g, int k) const {
    const int first = g * group_size_;
    const int members = std::min<int>(group_size_, static_cast<int>(f.vehicles.size()) - first);
    const std::vector<Target> wp = waypoints(s, members, seed_);
    if (k == first || wp.size() == 1) return wp.front();
    std::vector<std::vector<double>> cost;
    for (int v = first + 1; v < first + members; ++v) {
      cost.emplace_back();
      for (std::size_t w = 1; w < wp.size(); ++w)
        cost.back().push_back((wp[w].pos - f.vehicles[static_cast<std::size_t>(v)].pos).norm());
    }
    const int col = hungarianAssignment(cost).columnOfRow[static_cast<std::size_t>(k - first - 1)];
    return col < 0 ? wp.front() : wp[static_cast<std::size_t>(col) + 1];
  }

  /// Path to the waypoint's street, or to the open street nearest the waypoint when that one is
  /// not reachable over known streets.
  Decision towards(const FleetView& f, int k, const Target& wp) const {
    const KnownPaths paths(f.pg, f.vehicles[static_cast<std::size_t>(k)].edge,
                           [&](int e) { return f.streets.known(e); });
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (int e = 0; e < f.pg.m; ++e) {
      if (!f.open(e, k) || !std::isfinite(paths.distance(e))) continue;
      const double d = e == wp.edge ? -1.0 : (f.streets.midpoint(e) - wp.pos).norm();
      if (d < best_d) {
        best_d = d;
        best = e;
      }
    }
    if (best < 0) return {};
    return {paths.pathTo(best)->edges, best};
  }

  FleetConfig cfg_;
  int group_size_;
  std::uint64_t seed_;
};

}  // namespace

std::unique_ptr<Strategy> makeFleetStrategy(const FleetConfig& cfg, int group_size,
                                            std::uint64_t seed) {
  return std::make_unique<FleetStrategy>(cfg, group_size, seed);
}

}  // namespace slamroute::explore
