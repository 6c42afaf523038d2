// Roundabouts from location traces (see Roundabouts.hpp for why the hollow cylinder misses them).
// 1. Circle fits: each vehicle's path, averaged over resample_m of travel, is fitted in sliding
//    windows of 20-64 m (algebraic least-squares circle); a window is a circling stretch when it
//    fits, its radius is in range and it turns monotonically about the centre by min_sweep_deg.
// 2. Rings: circling stretches with centres within centre_tolerance_m are grouped (densest first);
//    a group of >= min_vehicles vehicles is a ring candidate at the median centre and radius.
// 3. Ring test on all trace points near it: points within ring_width_m of the radius that move
//    along the ring (direction within 60 deg of the tangent) must fill >= min_occupied of its 36
//    sectors and circle in one sense; the middle (inside half the radius) must be empty. A bend
//    or two turning arcs of junctions fill part of a circle; a crossing has traffic in its middle.
// 4. Junctions: each vehicle's stays on the ring (consecutive points on it, moving along it in its
//    sense) start where it joins and end where it leaves (where it comes within join_width_m of
//    the radius, see ringJunctions). Joins and leaves are grouped along the ring (arm_gap_m);
//    each group of >= min_arm_vehicles is a junction, and a join and a leave closer than
//    junction_merge_m (a two-way arm) are one; a split arm keeps two.
#include "slamroute/roadgraph/Roundabouts.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>

#include "DensestFirst.hpp"
#include "Median.hpp"

namespace slamroute::roadgraph {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSectors = 36;
using detail::median;

struct Sample {
  Eigen::Vector2d xy;
  double z = 0.0;
};

/// Each vehicle's path as runs of points averaged over `step` metres of travel.
std::vector<std::vector<Sample>> resamplePaths(const Traces& tr,
                                               const std::vector<std::size_t>& order, double step,
                                               double max_gap_s, std::vector<int>& run_vehicle) {
  std::vector<std::vector<Sample>> runs;
  std::vector<Sample> cur;
  Eigen::Vector2d acc = Eigen::Vector2d::Zero();
  double acc_z = 0.0, travelled = 0.0;
  int n = 0;
  auto flush_run = [&](int vehicle) {
    if (cur.size() >= 6) {
      runs.push_back(std::move(cur));
      run_vehicle.push_back(vehicle);
    }
    cur.clear();
    acc.setZero();
    acc_z = travelled = 0.0;
    n = 0;
  };
  for (std::size_t k = 0; k < order.size(); ++k) {
    const TracePoint& p = tr.points[order[k]];
    if (k > 0) {
      const TracePoint& q = tr.points[order[k - 1]];
      if (q.vehicle != p.vehicle || std::abs(p.t - q.t) > max_gap_s)
        flush_run(q.vehicle);
      else
        travelled += (p.pos - q.pos).head<2>().norm();
    }
    acc += p.pos.head<2>();
    acc_z += p.pos.z();
    ++n;
    if (travelled >= step) {
      cur.push_back({acc / n, acc_z / n});
      acc.setZero();
      acc_z = travelled = 0.0;
      n = 0;
    }
  }
  if (!order.empty()) flush_run(tr.points[order.back()].vehicle);
  return runs;
}

struct CircleFit {
  Eigen::Vector2d centre;
  double radius = 0.0, rms = 0.0, sweep = 0.0;  // sweep signed, radians
};

/// Algebraic (Kasa) least-squares circle through s[i0, i0+len), in coordinates centred on the
/// window's mean (the nets' coordinates are ~1e5 m). False when degenerate or the radius is outside
/// [min_r, max_r] (most windows: straight roads); the residual and the turn about the centre are
/// only computed for the rest.
bool fitCircle(const std::vector<Sample>& s, std::size_t i0, std::size_t len, double min_r,
               double max_r, double max_rms, CircleFit& f) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (std::size_t i = i0; i < i0 + len; ++i) mean += s[i].xy;
  mean /= static_cast<double>(len);
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (std::size_t i = i0; i < i0 + len; ++i) {
    const Eigen::Vector2d p = s[i].xy - mean;
    const Eigen::Vector3d row(p.x(), p.y(), 1.0);
    A += row * row.transpose();
    b -= row * p.squaredNorm();
  }
  const Eigen::Vector3d sol = A.ldlt().solve(b);
  if (!sol.allFinite()) return false;
  const Eigen::Vector2d c(-0.5 * sol.x(), -0.5 * sol.y());
  const double r2 = c.squaredNorm() - sol.z();
  if (!(r2 >= min_r * min_r && r2 <= max_r * max_r)) return false;
  f.radius = std::sqrt(r2);
  f.centre = c + mean;
  double ss = 0.0;
  for (std::size_t i = i0; i < i0 + len; ++i) {
    const double res = (s[i].xy - f.centre).norm() - f.radius;
    ss += res * res;
  }
  f.rms = std::sqrt(ss / static_cast<double>(len));
  if (f.rms > max_rms) return false;
  // Monotone turn about the centre: every step turns the same way.
  double sweep = 0.0;
  int sign = 0;
  for (std::size_t i = i0 + 1; i < i0 + len; ++i) {
    const Eigen::Vector2d u = s[i - 1].xy - f.centre, v = s[i].xy - f.centre;
    const double da = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
    const int sg = da > 0 ? 1 : (da < 0 ? -1 : 0);
    if (sg == 0 || (sign != 0 && sg != sign)) return false;
    sign = sg;
    sweep += da;
  }
  f.sweep = sweep;
  return true;
}

struct Candidate {
  Point3 centre;  // z: mean height of the window
  double radius;
  int sense;
  int vehicle;
};

std::vector<Candidate> circlingStretches(const std::vector<std::vector<Sample>>& runs,
                                         const std::vector<int>& run_vehicle,
                                         const RoundaboutConfig& cfg) {
  std::vector<Candidate> out;
  const double min_sweep = cfg.min_sweep_deg * kPi / 180.0;
  for (const double window_m : {20.0, 32.0, 48.0, 64.0}) {
    const auto len = static_cast<std::size_t>(std::lround(window_m / cfg.resample_m));
    if (len < 5) continue;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const auto& s = runs[r];
      std::size_t i = 0;
      while (i + len <= s.size()) {
        CircleFit f;
        const bool ok =
            fitCircle(s, i, len, cfg.min_radius_m, cfg.max_radius_m, cfg.max_fit_rms_m, f) &&
            std::abs(f.sweep) >= min_sweep;
        if (ok) {
          double z = 0.0;
          for (std::size_t k = i; k < i + len; ++k) z += s[k].z;
          out.push_back({Point3(f.centre.x(), f.centre.y(), z / static_cast<double>(len)), f.radius,
                         f.sweep > 0 ? 1 : -1, run_vehicle[r]});
        }
        i += ok ? std::max<std::size_t>(1, len / 2) : 2;
      }
    }
  }
  return out;
}

/// Groups of circling stretches with close centres (densest seed first): ring candidates.
std::vector<Roundabout> ringCandidates(const std::vector<Candidate>& cands,
                                       const RoundaboutConfig& cfg, double half_h) {
  std::vector<Point3> centres;
  centres.reserve(cands.size());
  for (const auto& c : cands) centres.push_back(c.centre);
  const detail::DensestFirstParams grouping{cfg.centre_tolerance_m, cfg.centre_tolerance_m, half_h,
                                            /*regather_at_median=*/true};
  std::vector<Roundabout> out;
  for (const auto& group : detail::groupDensestFirst(centres, grouping)) {
    std::vector<double> radii;
    std::set<int> vehicles;
    int sense = 0;
    for (const int j : group.members) {
      const Candidate& cd = cands[static_cast<std::size_t>(j)];
      radii.push_back(cd.radius);
      vehicles.insert(cd.vehicle);
      sense += cd.sense;
    }
    if (static_cast<int>(vehicles.size()) < cfg.min_vehicles) continue;
    Roundabout rb;
    rb.centre = group.median;
    rb.radius_m = median(radii);
    rb.sense = sense >= 0 ? 1 : -1;
    rb.vehicles = static_cast<int>(vehicles.size());
    out.push_back(rb);
  }
  return out;
}

/// Where point p stands relative to ring rb: on it and moving along it in its sense.
struct RingPos {
  double d = 0.0, angle = 0.0;
  bool near = false, along = false, in_sense = false;
};
RingPos ringPos(const Roundabout& rb, const TracePoint& p, const Vec3& dir,
                const RoundaboutConfig& cfg, double half_h) {
  RingPos r;
  const Eigen::Vector2d v = p.pos.head<2>() - rb.centre.head<2>();
  r.d = v.norm();
  r.angle = std::atan2(v.y(), v.x());
  r.near = std::abs(r.d - rb.radius_m) <= cfg.ring_width_m &&
           std::abs(p.pos.z() - rb.centre.z()) <= half_h;
  const double dn = dir.head<2>().norm();
  if (r.near && dn > 1e-9 && r.d > 1e-9) {
    const Eigen::Vector2d radial = v / r.d, t = dir.head<2>() / dn;
    r.along = std::abs(radial.dot(t)) < 0.5;  // within 60 deg of the tangent
    r.in_sense = (radial.x() * t.y() - radial.y() * t.x()) * rb.sense > 0.0;
  }
  return r;
}

int sectorOf(double angle) {
  const int s = static_cast<int>(std::floor((angle + kPi) / (2 * kPi) * kSectors));
  return std::clamp(s, 0, kSectors - 1);
}

/// The ring test (step 3) of every candidate in one pass over the trace points: the candidates
/// are few, so each point looks up those within reach by x in a sorted list (no grid over all
/// points, whose memory would be that of the traces again).
std::vector<char> passRingTest(const std::vector<Roundabout>& rings, const Traces& tr,
                               const std::vector<Vec3>& travel, const RoundaboutConfig& cfg,
                               double half_h) {
  struct Counts {
    std::array<int, kSectors> sector{};
    std::size_t on = 0, inner = 0, along = 0, in_sense = 0;
  };
  std::vector<Counts> counts(rings.size());
  std::vector<std::pair<double, std::size_t>> by_x;  // (centre x, ring)
  for (std::size_t j = 0; j < rings.size(); ++j) by_x.emplace_back(rings[j].centre.x(), j);
  std::sort(by_x.begin(), by_x.end());
  const double reach = cfg.max_radius_m + cfg.ring_width_m;
  for (std::size_t k = 0; k < tr.points.size(); ++k) {
    const Point3& p = tr.points[k].pos;
    auto it =
        std::lower_bound(by_x.begin(), by_x.end(), std::make_pair(p.x() - reach, std::size_t{0}));
    for (; it != by_x.end() && it->first <= p.x() + reach; ++it) {
      const Roundabout& rb = rings[it->second];
      const double dy = p.y() - rb.centre.y();
      if (std::abs(dy) > rb.radius_m + cfg.ring_width_m) continue;
      Counts& c = counts[it->second];
      const RingPos r = ringPos(rb, tr.points[k], travel[k], cfg, half_h);
      if (r.d > rb.radius_m + cfg.ring_width_m || std::abs(p.z() - rb.centre.z()) > half_h)
        continue;
      if (r.d < 0.5 * rb.radius_m) ++c.inner;
      if (!r.near) continue;
      ++c.on;
      if (!r.along) continue;
      ++c.along;
      if (r.in_sense) ++c.in_sense;
      ++c.sector[static_cast<std::size_t>(sectorOf(r.angle))];
    }
  }
  std::vector<char> pass(rings.size(), 0);
  for (std::size_t j = 0; j < rings.size(); ++j) {
    const Counts& c = counts[j];
    if (c.on == 0 || c.along == 0) continue;
    const auto filled =
        std::count_if(c.sector.begin(), c.sector.end(), [](int n) { return n >= 3; });
    pass[j] =
        static_cast<double>(filled) >= cfg.min_occupied * kSectors &&
        static_cast<double>(c.in_sense) >= cfg.min_sense_share * static_cast<double>(c.along) &&
        static_cast<double>(c.inner) <= cfg.max_inner_share * static_cast<double>(c.on);
  }
  return pass;
}

/// Groups angles on the ring (radius r) whose neighbours are within gap_m of arc; returns the
/// median angle and size of each group.
std::vector<std::pair<double, int>> groupAngles(std::vector<double> a, double r, double gap_m) {
  std::vector<std::pair<double, int>> out;
  if (a.empty()) return out;
  for (double& x : a) x = std::fmod(x + 2 * kPi, 2 * kPi);
  std::sort(a.begin(), a.end());
  // Start after the widest gap, so no group straddles the start.
  std::size_t start = 0;
  double widest = -1.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double next = i + 1 < a.size() ? a[i + 1] : a[0] + 2 * kPi;
    if (next - a[i] > widest) {
      widest = next - a[i];
      start = (i + 1) % a.size();
    }
  }
  std::vector<double> u;
  for (std::size_t k = 0; k < a.size(); ++k) {
    double x = a[(start + k) % a.size()];
    if (!u.empty() && x < u.back()) x += 2 * kPi;
    u.push_back(x);
  }
  std::vector<double> group{u[0]};
  auto close = [&] {
    out.emplace_back(group[group.size() / 2], static_cast<int>(group.size()));
    group.clear();
  };
  for (std::size_t k = 1; k < u.size(); ++k) {
    if ((u[k] - u[k - 1]) * r > gap_m) close();
    group.push_back(u[k]);
  }
  close();
  return out;
}

/// Where the vehicles' stays on a ring join and leave it (angles about its centre).
struct Stays {
  std::vector<double> joins, leaves;
};

/// A stay runs from the vehicle's first to its last point along the ring (gaps <= 1 s: GPS noise
/// takes a point off the ring now and then); it joins where the vehicle, having entered the
/// ring's band, first came within join_width_m of the radius, and leaves where it last was that
/// close before leaving the band. Points along the ring alone place both a few metres into the
/// ring (the direction of travel turns onto the tangent over travel_span_m), moving the join and
/// the leave of one two-way arm apart as far as those of a split arm.
class StayTracker {
 public:
  StayTracker(const Roundabout& rb, const RoundaboutConfig& cfg)
      : rb_(rb), cfg_(cfg), min_sweep_(cfg.min_run_sweep_deg * kPi / 180.0) {}

  /// A new vehicle, or a time gap: no stay continues across it.
  void breakTrace() {
    close();
    in_band_ = false;
  }
  void add(const TracePoint& p, const RingPos& r) {
    if (!r.near) {
      in_band_ = false;
      left_band_ = in_stay_;
      return;
    }
    const bool core = std::abs(r.d - rb_.radius_m) <= cfg_.join_width_m;
    if (!in_band_) {
      in_band_ = true;
      reached_core_ = false;
      band_angle_ = r.angle;
    }
    if (core && !reached_core_) {
      reached_core_ = true;
      band_angle_ = r.angle;
    }
    if (r.along && r.in_sense) {
      continueStay(p, r);
    } else if (in_stay_ && !left_band_ && core) {
      leave_ = r.angle;
    }
  }
  Stays finish() {
    close();
    return std::move(stays_);
  }

 private:
  static constexpr double kMaxOffS = 1.0;  // a stay survives this long off the ring [s]

  void continueStay(const TracePoint& p, const RingPos& r) {
    if (in_stay_ && p.t - last_t_ <= kMaxOffS) {
      double da = r.angle - last_angle_;
      while (da > kPi) da -= 2 * kPi;
      while (da < -kPi) da += 2 * kPi;
      swept_ += da;
    } else {
      close();
      in_stay_ = true;
      join_ = band_angle_;
      swept_ = 0.0;
    }
    last_angle_ = leave_ = r.angle;
    last_t_ = p.t;
    left_band_ = false;
  }
  void close() {
    if (in_stay_ && std::abs(swept_) >= min_sweep_) {
      stays_.joins.push_back(join_);
      stays_.leaves.push_back(leave_);
    }
    in_stay_ = left_band_ = false;
  }

  const Roundabout& rb_;
  const RoundaboutConfig& cfg_;
  const double min_sweep_;
  Stays stays_;
  bool in_stay_ = false, in_band_ = false, left_band_ = false, reached_core_ = false;
  double band_angle_ = 0.0, join_ = 0.0, leave_ = 0.0, last_angle_ = 0.0, swept_ = 0.0;
  double last_t_ = 0.0;
};

Stays ringStays(const Roundabout& rb, const Traces& tr, const std::vector<std::size_t>& order,
                const std::vector<Vec3>& travel, const RoundaboutConfig& cfg, double max_gap_s,
                double half_h) {
  const double reach = rb.radius_m + cfg.ring_width_m;
  StayTracker stays(rb, cfg);
  int vehicle = -1;
  double prev_t = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const TracePoint& p = tr.points[order[k]];
    if (p.vehicle != vehicle || p.t - prev_t > max_gap_s) {
      stays.breakTrace();
      vehicle = p.vehicle;
    }
    prev_t = p.t;
    RingPos r;
    if ((p.pos.head<2>() - rb.centre.head<2>()).squaredNorm() <= reach * reach)
      r = ringPos(rb, p, travel[order[k]], cfg, half_h);
    stays.add(p, r);
  }
  return stays.finish();
}

/// Junction angles: groups of joins and of leaves, then a join and a leave close together
/// merged (weighted mean angle); the last and the first group may be neighbours across 0 / 2 pi.
std::vector<double> junctionAngles(const Stays& stays, const Roundabout& rb,
                                   const RoundaboutConfig& cfg) {
  std::vector<std::pair<double, int>> groups;
  for (const auto* list : {&stays.joins, &stays.leaves})
    for (const auto& g : groupAngles(*list, rb.radius_m, cfg.arm_gap_m))
      if (g.second >= cfg.min_arm_vehicles)
        groups.emplace_back(std::fmod(g.first + 2 * kPi, 2 * kPi), g.second);
  std::sort(groups.begin(), groups.end());
  const double merge_rad = cfg.junction_merge_m / rb.radius_m;
  std::vector<std::pair<double, double>> merged;  // angle (weighted), weight
  for (const auto& g : groups) {
    if (!merged.empty() && g.first - merged.back().first / merged.back().second <= merge_rad) {
      merged.back().first += g.first * g.second;
      merged.back().second += g.second;
    } else {
      merged.emplace_back(g.first * g.second, g.second);
    }
  }
  if (merged.size() >= 2) {
    const double first = merged.front().first / merged.front().second;
    const double last = merged.back().first / merged.back().second;
    if (first + 2 * kPi - last <= merge_rad) {
      merged.front().first += (last - 2 * kPi) * merged.back().second;
      merged.front().second += merged.back().second;
      merged.pop_back();
    }
  }
  std::vector<double> angles;
  for (const auto& m : merged) angles.push_back(m.first / m.second);
  return angles;
}

/// The ring's junctions from the vehicles' stays on it.
std::vector<Point3> ringJunctions(const Roundabout& rb, const Traces& tr,
                                  const std::vector<std::size_t>& order,
                                  const std::vector<Vec3>& travel, const RoundaboutConfig& cfg,
                                  double max_gap_s, double half_h) {
  const Stays stays = ringStays(rb, tr, order, travel, cfg, max_gap_s, half_h);
  std::vector<Point3> out;
  for (const double a : junctionAngles(stays, rb, cfg))
    out.emplace_back(rb.centre.x() + rb.radius_m * std::cos(a),
                     rb.centre.y() + rb.radius_m * std::sin(a), rb.centre.z());
  return out;
}

}  // namespace

void checkRoundaboutConfig(const RoundaboutConfig& cfg) {
  if (!(cfg.min_radius_m > 0 && cfg.max_radius_m >= cfg.min_radius_m && cfg.resample_m > 0 &&
        cfg.centre_tolerance_m > 0 && cfg.ring_width_m > 0 && cfg.join_width_m > 0 &&
        cfg.arm_gap_m > 0 && cfg.junction_merge_m >= 0 && cfg.absorb_margin_m >= 0))
    throw std::invalid_argument(
        "roadgraph.roundabouts: radii, resample_m, centre_tolerance_m, ring_width_m, join_width_m "
        "and arm_gap_m must be > 0, junction_merge_m and absorb_margin_m >= 0 (max_radius_m >= "
        "min_radius_m)");
}

std::vector<Roundabout> detectRoundabouts(const Traces& traces,
                                          const std::vector<std::size_t>& order,
                                          const std::vector<Vec3>& travel,
                                          const RoundaboutConfig& cfg, double max_gap_s,
                                          double half_height_m) {
  if (!cfg.enabled) return {};
  checkRoundaboutConfig(cfg);
  if (travel.size() != traces.points.size() || order.size() != traces.points.size())
    throw std::invalid_argument("detectRoundabouts: travel / order and trace points differ");
  std::vector<int> run_vehicle;
  const auto runs = resamplePaths(traces, order, cfg.resample_m, max_gap_s, run_vehicle);
  const auto cands = circlingStretches(runs, run_vehicle, cfg);
  std::vector<Roundabout> rings = ringCandidates(cands, cfg, half_height_m);
  if (rings.empty()) return rings;

  const std::vector<char> pass = passRingTest(rings, traces, travel, cfg, half_height_m);
  std::vector<Roundabout> accepted;
  for (std::size_t j = 0; j < rings.size(); ++j)
    if (pass[j]) accepted.push_back(rings[j]);
  // One ring per place: of two rings whose centres are within the larger radius, keep the one
  // more vehicles circle (an inner and an outer lane fit two circles).
  std::stable_sort(accepted.begin(), accepted.end(), [](const Roundabout& a, const Roundabout& b) {
    return a.vehicles > b.vehicles;
  });
  std::vector<Roundabout> out;
  for (const auto& rb : accepted) {
    const bool dup = std::any_of(out.begin(), out.end(), [&](const Roundabout& o) {
      return (o.centre.head<2>() - rb.centre.head<2>()).norm() < std::max(o.radius_m, rb.radius_m);
    });
    if (dup) continue;
    Roundabout r = rb;
    r.junctions = ringJunctions(r, traces, order, travel, cfg, max_gap_s, half_height_m);
    if (!r.junctions.empty()) out.push_back(std::move(r));
  }
  return out;
}

std::size_t mergeRoundaboutNodes(std::vector<Point3>& nodes, const std::vector<Roundabout>& rbs,
                                 const RoundaboutConfig& cfg, double half_height_m) {
  if (rbs.empty()) return 0;
  std::vector<Point3> kept;
  for (const auto& n : nodes) {
    const bool inside = std::any_of(rbs.begin(), rbs.end(), [&](const Roundabout& rb) {
      return (n.head<2>() - rb.centre.head<2>()).norm() <= rb.radius_m + cfg.absorb_margin_m &&
             std::abs(n.z() - rb.centre.z()) <= half_height_m;
    });
    if (!inside) kept.push_back(n);
  }
  const std::size_t removed = nodes.size() - kept.size();
  for (const auto& rb : rbs) kept.insert(kept.end(), rb.junctions.begin(), rb.junctions.end());
  nodes = std::move(kept);
  return removed;
}

}  // namespace slamroute::roadgraph
