// Centre votes (paper §3.1 step 1, "robust centre"): the least-squares crossing of the centre
// lines of the branches a point sees. The choices are documented in Intersections.cpp.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

#include "HollowCylinder.hpp"

namespace slamroute::roadgraph::detail {

namespace {

using Moments = Eigen::Matrix<double, 6, 1>;  // count, sum x, y, xx, xy, yy

Moments moment(const Eigen::Vector2d& d) {
  return Moments(1.0, d.x(), d.y(), d.x() * d.x(), d.x() * d.y(), d.y() * d.y());
}

/// Centroid and principal direction of a point set from its moments.
void principalLine(const Moments& m, Eigen::Vector2d& mean, Eigen::Vector2d& dir) {
  mean = Eigen::Vector2d(m[1], m[2]) / m[0];
  const double cxx = m[3] / m[0] - mean.x() * mean.x(), cxy = m[4] / m[0] - mean.x() * mean.y(),
               cyy = m[5] / m[0] - mean.y() * mean.y();
  const double th = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
  dir = Eigen::Vector2d(std::cos(th), std::sin(th));
}

/// One branch's line seen from c: the moments (relative to c) of its points, then of the points
/// between two cuts perpendicular to the arm (t in [inner radius, sqrt(outer^2 - half-width^2)]):
/// the ring cuts a wide arm obliquely when c is off its centre line, which tilts a plain
/// principal axis (by ~20 degrees for a 4-lane avenue seen from 6 m off-centre); straight cuts
/// do not.
struct BranchLine {
  Moments moments = Moments::Zero();
  Eigen::Vector2d mean, dir;
};

BranchLine cutBranchLine(const std::vector<Point3>& pts, const std::vector<int>& members,
                         const Point3& c, const NodeConfig& cfg) {
  BranchLine l;
  for (int i : members)
    l.moments += moment(pts[static_cast<std::size_t>(i)].head<2>() - c.head<2>());
  principalLine(l.moments, l.mean, l.dir);
  for (int iter = 0; iter < 2; ++iter) {
    const Eigen::Vector2d u = l.dir.dot(l.mean) >= 0 ? l.dir : Eigen::Vector2d(-l.dir);
    const Eigen::Vector2d nrm(-u.y(), u.x());
    double wmax = 0.0;
    for (int i : members)
      wmax = std::max(wmax,
                      std::abs(nrm.dot(pts[static_cast<std::size_t>(i)].head<2>() - c.head<2>())));
    const double t_lo = cfg.inner_radius_m;
    const double t_hi =
        std::sqrt(std::max(0.0, cfg.outer_radius_m * cfg.outer_radius_m - wmax * wmax));
    Moments cut = Moments::Zero();
    for (int i : members) {
      const Eigen::Vector2d d = pts[static_cast<std::size_t>(i)].head<2>() - c.head<2>();
      const double t = u.dot(d);
      if (t >= t_lo && t <= t_hi) cut += moment(d);
    }
    if (cut[0] < 4.0 || t_hi - t_lo < 3.0) break;  // too little left: keep the plain fit
    l.moments = cut;
    principalLine(l.moments, l.mean, l.dir);
  }
  return l;
}

/// Travel axes known: the arm runs where its vehicles drive (mean doubled-angle axis), which does
/// not depend on how the ring cuts a wide arm. Used when coherent (turning traffic only adds
/// spread); dir is left as it is otherwise.
void travelAxis(const std::vector<Eigen::Vector2d>& axes, const std::vector<int>& members,
                double min_coherence, Eigen::Vector2d& dir) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double w = 0.0;
  for (int i : members) {
    const Eigen::Vector2d& a = axes[static_cast<std::size_t>(i)];
    sum += a;
    w += a.norm();
  }
  if (!(w > 0.0) || sum.norm() < min_coherence * w) return;
  const double th = 0.5 * std::atan2(sum.y(), sum.x());
  dir = Eigen::Vector2d(std::cos(th), std::sin(th));
}

/// Straight-through pairs: centroids on opposite sides, within min_branch_angle_deg of a
/// straight line through c; closest to straight first. Per branch its partner, or -1.
std::vector<int> straightPartners(const std::vector<BranchLine>& lines, double min_angle_deg) {
  const std::size_t nb = lines.size();
  const double cos_straight = std::cos(min_angle_deg * M_PI / 180.0);
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> cand;
  for (std::size_t a = 0; a < nb; ++a)
    for (std::size_t b = a + 1; b < nb; ++b) {
      const double cs = -lines[a].mean.normalized().dot(lines[b].mean.normalized());
      if (cs > cos_straight) cand.push_back({-cs, {a, b}});
    }
  std::sort(cand.begin(), cand.end());
  std::vector<int> partner(nb, -1);
  for (const auto& [k, ab] : cand) {
    if (partner[ab.first] >= 0 || partner[ab.second] >= 0) continue;
    partner[ab.first] = static_cast<int>(ab.second);
    partner[ab.second] = static_cast<int>(ab.first);
  }
  return partner;
}

}  // namespace

/// Least-squares crossing (horizontal) of the principal lines of `members` (one point list per
/// branch) as seen from `c`. Opposite branches on one line (a road passing straight through:
/// centroids within min_branch_angle_deg of a straight line through c) are fitted as one line:
/// a single arm of a wide road is only ~15 m long and ~10 m wide inside the ring, so its own
/// axis can tilt by tens of degrees, while the through road's 50 m band fixes it well. False when
/// the lines are close to parallel (no stable crossing).
bool crossingOf(const std::vector<Point3>& pts, const std::vector<std::vector<int>>& members,
                const Point3& c, const NodeConfig& cfg, const std::vector<Eigen::Vector2d>* axes,
                Eigen::Vector2d& x) {
  const std::size_t nb = members.size();
  if (nb < 2) return false;
  std::vector<BranchLine> lines;
  for (std::size_t b = 0; b < nb; ++b) {
    lines.push_back(cutBranchLine(pts, members[b], c, cfg));
    if (axes) travelAxis(*axes, members[b], cfg.min_axis_coherence, lines.back().dir);
  }
  const std::vector<int> partner = straightPartners(lines, cfg.min_branch_angle_deg);
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
  for (std::size_t b = 0; b < nb; ++b) {
    Eigen::Vector2d m = lines[b].mean, u = lines[b].dir;
    // A straight-through pair: the line through both arms' points (their centroids are ~35 m
    // apart, so the principal axis is well defined; a road bending slightly through the junction
    // is fitted better by it than by the mean travel axis).
    if (partner[b] >= 0)
      principalLine(lines[b].moments + lines[static_cast<std::size_t>(partner[b])].moments, m, u);
    const Eigen::Matrix2d P = Eigen::Matrix2d::Identity() - u * u.transpose();
    A += P;
    rhs += P * m;
  }
  if (A.determinant() < 0.05 * static_cast<double>(nb)) return false;  // near-parallel
  x = A.ldlt().solve(rhs) + c.head<2>();
  return true;
}

/// Iterated crossing of the branches seen from `start` (at most `iters` re-evaluations, each
/// moving < max_jump from start). Returns false when no crossing could be formed; `out` holds the
/// last accepted position (start when none), z unchanged.
bool crossingFrom(const PointGrid& grid, const std::vector<Point3>& pts,
                  const std::vector<Eigen::Vector2d>* axes, const Point3& start,
                  const NodeConfig& cfg, Scratch& s, int iters, double max_jump, Point3& out) {
  out = start;
  bool any = false;
  for (int iter = 0; iter < iters; ++iter) {
    if (branchesAt(grid, pts, out, cfg, s, &s.members) < 2) break;
    Eigen::Vector2d x;
    if (!crossingOf(pts, s.members, out, cfg, axes, x)) break;
    if ((x - start.head<2>()).norm() > max_jump) break;  // implausible jump
    const bool done = (x - out.head<2>()).norm() < 0.05;
    out.head<2>() = x;
    any = true;
    if (done) break;
  }
  return any;
}

}  // namespace slamroute::roadgraph::detail
