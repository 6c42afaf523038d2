// Gauss-Newton feature registration (LOAM point-to-line / point-to-plane) and point-to-plane ICP.
// The pose is updated on the right, T <- T * Exp(delta), so the perturbation lives in the source
// (body) frame and LeGO-LOAM's split into z/roll/pitch and x/y/yaw is a mask on delta.
#include "slamroute/evaluate/Registration.hpp"

#include "KeptNeighbours.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace slamroute::evaluate {
namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Row6 = Eigen::Matrix<double, 1, 6>;

struct Normal {
  Mat6 H = Mat6::Zero();
  Vec6 g = Vec6::Zero();
  double rows = 0;  ///< number of constrained directions, for normalising H
  /// One scalar residual r along unit direction n (world/target frame) for body point p.
  void add(const Mat3& R, const Vec3& p, const Vec3& n, double r, double huber,
           double weight = 1.0) {
    const Vec3 nb = R.transpose() * n;  // direction in the body frame
    Row6 J;
    J.head<3>() = p.cross(nb).transpose();  // d r / d(rotation): n^T R (-[p]x)
    J.tail<3>() = nb.transpose();
    const double w = weight * (std::abs(r) <= huber ? 1.0 : huber / std::abs(r));
    H += w * J.transpose() * J;
    g += w * J.transpose() * r;
    rows += 1;
  }
  /// Solves the masked normal equations; returns delta (zeros in masked-out DoF). Directions
  /// whose normalised eigenvalue (lambda / rows) is below `degenerate_eig` are not updated
  /// (Zhang, Kaess & Singh 2016 "solution remapping", as in LOAM/LeGO-LOAM): in a degenerate
  /// stretch those DoF keep the prediction instead of following noise.
  Vec6 solve(unsigned mask, double degenerate_eig = 0.0) const {
    std::array<int, 6> act{};
    int m = 0;
    for (int i = 0; i < 6; ++i)
      if (mask & (1u << i)) act[static_cast<std::size_t>(m++)] = i;
    Eigen::MatrixXd A(m, m);
    Eigen::VectorXd b(m);
    for (int i = 0; i < m; ++i) {
      b(i) = -g(act[static_cast<std::size_t>(i)]);
      for (int j = 0; j < m; ++j)
        A(i, j) = H(act[static_cast<std::size_t>(i)], act[static_cast<std::size_t>(j)]);
    }
    A.diagonal().array() += 1e-6 * (1.0 + A.diagonal().array());
    Eigen::VectorXd x = A.ldlt().solve(b);
    if (degenerate_eig > 0 && rows > 0) {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A);
      Eigen::VectorXd keep = Eigen::VectorXd::Ones(m);
      for (int i = 0; i < m; ++i) keep(i) = es.eigenvalues()(i) / rows < degenerate_eig ? 0.0 : 1.0;
      x = es.eigenvectors() * keep.asDiagonal() * es.eigenvectors().transpose() * x;
    }
    Vec6 d = Vec6::Zero();
    for (int i = 0; i < m; ++i)
      if (std::isfinite(x(i))) d(act[static_cast<std::size_t>(i)]) = x(i);
    return d;
  }
  double minEigTranslation() const {
    if (rows <= 0) return 0.0;
    const Mat3 Ht = H.block<3, 3>(3, 3) / rows;
    return Eigen::SelfAdjointEigenSolver<Mat3>(Ht, Eigen::EigenvaluesOnly).eigenvalues()(0);
  }
};

void applyDelta(Pose3& T, const Vec6& d) {
  Pose3 D = Pose3::Identity();
  const double angle = d.head<3>().norm();
  if (angle > 1e-12) D.linear() = Eigen::AngleAxisd(angle, d.head<3>() / angle).toRotationMatrix();
  D.translation() = d.tail<3>();
  T = T * D;
  // re-orthonormalise against drift
  T.linear() = Eigen::Quaterniond(T.rotation()).normalized().toRotationMatrix();
}

/// Prior residual e = log(prior^-1 * T) per DoF with weight w (faded by the features' own
/// information where `fade` says so); its Jacobian with respect to the right perturbation is the
/// identity to first order.
void addPrior(Normal& ne, const Pose3& prior, const Pose3& T, Vec6 w, const Vec6& fade) {
  for (int i = 0; i < 6; ++i)
    if (fade(i) > 0 && ne.rows > 0)
      w(i) *= std::clamp(1.0 - ne.H(i, i) / ne.rows / fade(i), 0.0, 1.0);
  const Pose3 E = prior.inverse() * T;
  const Eigen::AngleAxisd aa(E.rotation());
  Vec6 e;
  e.head<3>() = aa.angle() * aa.axis();
  e.tail<3>() = E.translation();
  for (int i = 0; i < 6; ++i) {
    if (!(w(i) > 0)) continue;
    ne.H(i, i) += w(i);
    ne.g(i) += w(i) * e(i);
  }
}

/// PCA of the neighbours: mean and eigen-decomposition (ascending eigenvalues).
struct Pca {
  Vec3 mean;
  Eigen::SelfAdjointEigenSolver<Mat3> es;
};
Pca pca(const Cloud& cloud, const std::vector<int>& idx) {
  Vec3 mean = Vec3::Zero();
  for (int i : idx) mean += cloud[static_cast<std::size_t>(i)].cast<double>();
  mean /= static_cast<double>(idx.size());
  Mat3 cov = Mat3::Zero();
  for (int i : idx) {
    const Vec3 d = cloud[static_cast<std::size_t>(i)].cast<double>() - mean;
    cov += d * d.transpose();
  }
  cov /= static_cast<double>(idx.size());
  Pca out{mean, {}};
  out.es.computeDirect(cov);
  return out;
}

}  // namespace

void FeatureMap::build(Cloud edge_cloud, Cloud plane_cloud) {
  edges = std::move(edge_cloud);
  planes = std::move(plane_cloud);
  edge_tree.build(edges);
  plane_tree.build(planes);
}

namespace {

/// A found correspondence: source point p (body frame) and the target's line (dir) or plane
/// (normal) through `mean`. Kept for `reassociate_every` iterations.
struct Corr {
  Vec3 p, mean, axis;
};

constexpr int kFitNeighbours = 5;

/// A line or plane fitted to target neighbours.
struct Shape {
  bool ok = false;  ///< the neighbours lie on a line / plane
  Vec3 mean = Vec3::Zero(), axis = Vec3::Zero();
};

/// A source point's fitted shape, kept with the neighbours it came from: when a later
/// association finds the same neighbours (the usual case once the pose settles), the shape is
/// the same and is not computed again.
struct Fit {
  KeptNeighbours<kFitNeighbours> near;
  std::array<int, kFitNeighbours> shape_from{-1, -1, -1, -1, -1};
  Shape shape;
};

Shape lineFit(const Cloud& cloud, const std::vector<int>& idx) {
  const Pca s = pca(cloud, idx);
  const Vec3 ev = s.es.eigenvalues();
  Shape f;
  f.ok = ev(2) >= 3.0 * ev(1);  // else the neighbours are not on a line
  f.mean = s.mean;
  f.axis = s.es.eigenvectors().col(2);
  return f;
}

Shape planeFit(const Cloud& cloud, const std::vector<int>& idx, double max_dev_m) {
  const Pca s = pca(cloud, idx);
  Shape f;
  f.mean = s.mean;
  f.axis = s.es.eigenvectors().col(0);
  f.ok = true;
  for (int i : idx)
    f.ok =
        f.ok && std::abs(f.axis.dot(cloud[static_cast<std::size_t>(i)].cast<double>() - s.mean)) <
                    max_dev_m;
  return f;
}

/// Correspondences of one feature kind at pose (R, t): the neighbours of each source point in
/// `tree` (over `target`) and their fit, taken from `fits` when the neighbours are the same.
template <class FitFn>
void associateKind(const KdTree& tree, const Cloud& target, const Cloud& src, const Mat3& R,
                   const Vec3& t, float max_d2, std::vector<Fit>& fits, std::vector<Corr>& out,
                   FitFn fit) {
  out.clear();
  if (target.size() < static_cast<std::size_t>(kFitNeighbours)) return;
  fits.resize(src.size());
  std::vector<int> idx;
  std::vector<float> d2;
  for (std::size_t i = 0; i < src.size(); ++i) {
    const Vec3 p = src[i].cast<double>();
    const Vec3 q = R * p + t;
    Fit& f = fits[i];
    if (f.near.find(tree, target, q.cast<float>(), max_d2, idx, d2) < kFitNeighbours) continue;
    if (!std::equal(idx.begin(), idx.end(), f.shape_from.begin())) {
      f.shape = fit(idx);
      std::copy(idx.begin(), idx.end(), f.shape_from.begin());
    }
    if (f.shape.ok) out.push_back({p, f.shape.mean, f.shape.axis});
  }
}

/// Nearest-neighbour line fits for the edges and plane fits for the planar points at pose (R, t).
struct Associator {
  const FeatureMap& target;
  const Cloud& src_edges;
  const Cloud& src_planes;
  std::vector<Fit> edge_fits, plane_fits;

  void operator()(const Mat3& R, const Vec3& t, const AlignOptions& opt, std::vector<Corr>& lines,
                  std::vector<Corr>& planes) {
    const auto max_d2 = static_cast<float>(opt.max_nn_m * opt.max_nn_m);
    associateKind(target.edge_tree, target.edges, src_edges, R, t, max_d2, edge_fits, lines,
                  [&](const std::vector<int>& idx) { return lineFit(target.edges, idx); });
    associateKind(target.plane_tree, target.planes, src_planes, R, t, max_d2, plane_fits, planes,
                  [&](const std::vector<int>& idx) {
                    return planeFit(target.planes, idx, opt.plane_max_dev_m);
                  });
  }
};

}  // namespace

AlignResult alignFeatures(const FeatureMap& target, const Cloud& src_edges, const Cloud& src_planes,
                          const Pose3& init, const AlignOptions& opt) {
  AlignResult res;
  Pose3 T = init;
  std::vector<Corr> lines, planes;
  const int every = std::max(1, opt.reassociate_every);
  Normal last;
  bool force = false;
  const bool has_prior = (opt.prior_weight.array() > 0).any();
  Associator associate{target, src_edges, src_planes, {}, {}};
  for (int it = 0; it < opt.iterations; ++it) {
    const Mat3 R = T.rotation();
    const Vec3 t = T.translation();
    const bool fresh = force || it % every == 0;
    if (fresh) associate(R, t, opt, lines, planes);
    force = false;
    Normal ne;
    int inliers = 0;
    for (const Corr& c : lines) {
      const Vec3 e = R * c.p + t - c.mean;
      const Vec3 perp = e - c.axis * c.axis.dot(e);
      // Point-to-line distance (LOAM eq. 2) as two orthogonal scalar residuals.
      const Vec3 u = c.axis.unitOrthogonal();
      const Vec3 v = c.axis.cross(u);
      ne.add(R, c.p, u, u.dot(perp), opt.huber_m, opt.edge_weight);
      ne.add(R, c.p, v, v.dot(perp), opt.huber_m, opt.edge_weight);
      if (perp.norm() < opt.inlier_m) ++inliers;
    }
    for (const Corr& c : planes) {
      const double r = c.axis.dot(R * c.p + t - c.mean);
      ne.add(R, c.p, c.axis, r, opt.huber_m);  // point-to-plane (LOAM eq. 3)
      if (std::abs(r) < opt.inlier_m) ++inliers;
    }
    res.edge_matches = static_cast<int>(lines.size());
    res.plane_matches = static_cast<int>(planes.size());
    res.inliers = inliers;
    res.iterations = it + 1;
    last = ne;
    if (ne.rows < 6) break;
    if (has_prior) addPrior(ne, opt.prior, T, opt.prior_weight, opt.prior_fade_info);
    const Vec6 d = ne.solve(opt.dof_mask, opt.degenerate_eig);
    applyDelta(T, d);
    if (d.head<3>().norm() < 1e-5 && d.tail<3>().norm() < 1e-4) {
      // Converged on correspondences found at an earlier pose: look again once before stopping.
      if (!fresh && it + 1 < opt.iterations) {
        force = true;
        continue;
      }
      res.converged = true;
      break;
    }
  }
  res.T_target_source = T;
  res.min_eig_translation = last.minEigTranslation();
  return res;
}

IcpTarget::IcpTarget(Cloud target) : cloud_(std::move(target)) {
  if (cloud_.size() < 8) return;
  tree_.build(cloud_);
  // Target normals from 8 neighbours; points without a clear plane keep a zero normal.
  normals_.assign(cloud_.size(), Vec3::Zero());
  std::vector<int> idx;
  std::vector<float> d2;
  for (std::size_t i = 0; i < cloud_.size(); ++i) {
    if (tree_.knn(cloud_[i], 8, idx, d2) < 8) continue;
    const Pca s = pca(cloud_, idx);
    const Vec3 ev = s.es.eigenvalues();
    if (ev(0) < 0.2 * ev(1)) normals_[i] = s.es.eigenvectors().col(0);
  }
}

IcpResult IcpTarget::align(const Cloud& source, const Pose3& init, int iterations,
                           double max_corr_m) const {
  IcpResult res;
  res.T_target_source = init;
  if (source.empty() || cloud_.size() < 8) return res;
  const KdTree& tree = tree_;
  const std::vector<Vec3>& normals = normals_;
  const Cloud& target = cloud_;
  std::vector<int> idx;
  std::vector<float> d2;
  // Each source point's nearest target point, found again without a search while it must be the
  // same (most iterations move the points by millimetres).
  std::vector<KeptNeighbours<1>> nearest(source.size());
  Pose3 T = init;
  for (int it = 0; it < iterations; ++it) {
    const double frac = iterations > 1 ? static_cast<double>(it) / (iterations - 1) : 1.0;
    const double corr = max_corr_m * (1.0 - frac * 2.0 / 3.0);
    const float corr2 = static_cast<float>(corr * corr);
    Normal ne;
    const Mat3 R = T.rotation();
    for (std::size_t i = 0; i < source.size(); ++i) {
      const Vec3 p = source[i].cast<double>();
      const Vec3 q = R * p + T.translation();
      if (nearest[i].find(tree, target, q.cast<float>(), corr2, idx, d2) < 1) continue;
      const Vec3& n = normals[static_cast<std::size_t>(idx[0])];
      if (n.isZero()) continue;
      ne.add(R, p, n, n.dot(q - target[static_cast<std::size_t>(idx[0])].cast<double>()), corr);
    }
    res.iterations = it + 1;
    if (ne.rows < 6) break;
    const Vec6 d = ne.solve(kAllDof);
    applyDelta(T, d);
    if (d.head<3>().norm() < 1e-6 && d.tail<3>().norm() < 1e-5 && frac > 0.5) {
      res.converged = true;
      break;
    }
  }
  res.T_target_source = T;
  // Fitness as in PCL's getFitnessScore, restricted to inliers within the final radius.
  const double final_corr = max_corr_m / 3.0;
  const auto final_corr2 = static_cast<float>(final_corr * final_corr);
  double sum = 0;
  int inl = 0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    const Vec3 q = T * source[i].cast<double>();
    if (nearest[i].find(tree, target, q.cast<float>(), final_corr2, idx, d2) < 1 ||
        d2[0] > final_corr * final_corr)
      continue;
    sum += d2[0];
    ++inl;
  }
  res.fitness_m2 = inl > 0 ? sum / inl : 1e9;
  res.inlier_ratio = static_cast<double>(inl) / static_cast<double>(source.size());
  if (res.iterations == iterations) res.converged = true;
  return res;
}

Mat3 IcpTarget::translationInformation(const Cloud& source, const Pose3& T,
                                       double max_corr_m) const {
  Mat3 info = Mat3::Zero();
  if (cloud_.size() < 8) return info;
  std::vector<int> idx;
  std::vector<float> d2;
  int matched = 0;
  for (const auto& pf : source) {
    const Vec3 q = T * pf.cast<double>();
    const auto max_corr2 = static_cast<float>(max_corr_m * max_corr_m);
    if (tree_.knnWithin(q.cast<float>(), 1, max_corr2, idx, d2) < 1 ||
        d2[0] > max_corr_m * max_corr_m)
      continue;
    const Vec3& n = normals_[static_cast<std::size_t>(idx[0])];
    if (n.isZero()) continue;
    info += n * n.transpose();
    ++matched;
  }
  return matched > 0 ? Mat3(info / matched) : info;
}

double horizontalConditioning(const Mat3& info) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(info.topLeftCorner<2, 2>());
  const Eigen::Vector2d ev = es.eigenvalues();  // ascending
  return ev(1) > 0.0 ? std::max(0.0, ev(0)) / ev(1) : 0.0;
}

namespace {

/// The starts of the rival search around `T`: along its heading and across it, both signs.
std::vector<Pose3> rivalStarts(const Pose3& T, const IcpAmbiguity& amb) {
  Vec3 along = T.rotation().col(0);
  along.z() = 0.0;
  if (along.norm() < 1e-6) return {};
  along.normalize();
  const Vec3 across(-along.y(), along.x(), 0.0);
  std::vector<Vec3> shifts;
  for (const double d : amb.along_m) shifts.insert(shifts.end(), {d * along, -d * along});
  for (const double d : amb.across_m) shifts.insert(shifts.end(), {d * across, -d * across});
  std::vector<Pose3> starts;
  for (const Vec3& shift : shifts) {
    Pose3 init = T;
    init.translation() += shift;
    starts.push_back(init);
  }
  return starts;
}

/// `r` fits better than `than`: more of the points (by the margin) and a lower fitness.
bool fitsBetter(const IcpResult& r, const IcpResult& than, const IcpAmbiguity& amb) {
  return r.inlier_ratio >= than.inlier_ratio + amb.inlier_margin && r.fitness_m2 < than.fitness_m2;
}

}  // namespace

namespace {

/// ICP from every rival start around `T` (rivalStarts), in their order.
std::vector<IcpResult> rivalFits(const IcpTarget& target, const Cloud& source, const Pose3& T,
                                 const IcpAmbiguity& amb) {
  std::vector<IcpResult> fits;
  for (const Pose3& init : rivalStarts(T, amb))
    fits.push_back(target.align(source, init, amb.iterations, amb.max_corr_m));
  return fits;
}

/// The first fit that fits better than `match`, else the one closest to fitting as well.
IcpRival strongestOf(const std::vector<IcpResult>& fits, const IcpResult& match,
                     const IcpAmbiguity& amb) {
  IcpRival strongest;
  const Pose3& T = match.T_target_source;
  for (const IcpResult& r : fits) {
    IcpRival rival;
    rival.apart_m = (r.T_target_source.translation() - T.translation()).norm();
    if (rival.apart_m <= amb.separation_m || !amb.accept(r)) continue;
    rival.share = std::min(r.inlier_ratio / std::max(match.inlier_ratio, 1e-12),
                           match.fitness_m2 / std::max(r.fitness_m2, 1e-12));
    rival.better = fitsBetter(r, match, amb);
    if (rival.better) return rival;
    if (rival.share > strongest.share) strongest = rival;
  }
  return strongest;
}

}  // namespace

IcpRival strongestRival(const IcpTarget& target, const Cloud& source, const IcpResult& match,
                        const IcpAmbiguity& amb) {
  return strongestOf(rivalFits(target, source, match.T_target_source, amb), match, amb);
}

std::optional<IcpResult> uniqueMatch(const IcpTarget& target, const Cloud& source,
                                     const IcpResult& match, const IcpAmbiguity& amb) {
  const std::vector<IcpResult> fits = rivalFits(target, source, match.T_target_source, amb);
  const IcpRival rival = strongestOf(fits, match, amb);
  if (!rival.better) {
    if (ambiguousMatch(rival, amb)) return std::nullopt;
    return match;
  }
  // ICP from a drifted start stopped on the wrong features. The first better rival may be
  // another wrong place: the best fit of every start is the one to test.
  IcpResult best = match;
  for (const IcpResult& r : fits)
    if (amb.accept(r) && fitsBetter(r, best, amb)) best = r;
  if (ambiguousMatch(strongestRival(target, source, best, amb), amb)) return std::nullopt;
  return best;
}

}  // namespace slamroute::evaluate
