#pragma once
// Feature registration (LOAM point-to-line / point-to-plane, Gauss-Newton on SE(3) with a DoF
// mask for LeGO-LOAM's two-step odometry) and point-to-plane ICP for loop closure.
#include <cstdint>
#include <optional>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/KdTree.hpp"

namespace slamroute::evaluate {

/// Perturbation order: [rx ry rz tx ty tz] in the source (body) frame.
enum Dof : unsigned { kRoll = 1, kPitch = 2, kYaw = 4, kX = 8, kY = 16, kZ = 32, kAllDof = 63 };

/// Target of a feature registration: edge and planar clouds with their k-d trees.
struct FeatureMap {
  Cloud edges, planes;
  KdTree edge_tree, plane_tree;
  void build(Cloud edge_cloud, Cloud plane_cloud);
  bool empty() const { return edges.empty() && planes.empty(); }
};

struct AlignOptions {
  int iterations = 10;
  double max_nn_m = 1.0;  ///< all 5 neighbours of a correspondence within this [m]
  double huber_m = 0.1;
  double plane_max_dev_m = 0.2;  ///< all neighbours within this of their fitted plane [m]
  double edge_weight = 1.0;      ///< weight of the point-to-line residuals (planes: 1)
  unsigned dof_mask = kAllDof;
  double degenerate_eig = 0.0;  ///< > 0: freeze directions with lambda/rows below this
  double inlier_m = 0.1;        ///< residuals below this count as inliers (hypothesis score) [m]
  /// Search the nearest neighbours and fit lines / planes every n-th iteration only, and keep
  /// them fixed in between (LOAM's odometry re-associates every 5th iteration). 1 = every one.
  int reassociate_every = 1;
  /// Optional prior on the result (e.g. the wheel odometry's prediction, target frame): adds
  /// prior_weight[i] * e_i^2 to the cost, e = [rotation vector, translation] of prior^-1 * T in
  /// the body frame, order [rx ry rz tx ty tz]. The LiDAR residuals are in metres with unit
  /// weight, so a weight is (residual sigma / prior sigma)^2. It only matters where the
  /// features leave a direction weak (a long wall: along the street). Zero weights: no prior.
  Pose3 prior = Pose3::Identity();
  Eigen::Matrix<double, 6, 1> prior_weight = Eigen::Matrix<double, 6, 1>::Zero();
  /// > 0: the prior on that DoF fades out as the features' own information on it (diagonal of
  /// the normal equations per residual) rises to this, so it acts only where the scan cannot
  /// hold the DoF (a bridge deck between uniform parapets: along the street). 0: always.
  Eigen::Matrix<double, 6, 1> prior_fade_info = Eigen::Matrix<double, 6, 1>::Zero();
};

struct AlignResult {
  Pose3 T_target_source = Pose3::Identity();
  int iterations = 0;
  int edge_matches = 0;
  int plane_matches = 0;
  int inliers = 0;  ///< correspondences of the last iteration with a residual below inlier_m
  double min_eig_translation = 0;  ///< smallest eigenvalue of the normalised translation block
  bool converged = false;
};

/// Minimises point-to-line (edges) and point-to-plane (planes) distances from source features,
/// moved by T_target_source, to the target (LOAM eqs. (2)-(3)).
AlignResult alignFeatures(const FeatureMap& target, const Cloud& src_edges, const Cloud& src_planes,
                          const Pose3& init, const AlignOptions& opt);

struct IcpResult {
  Pose3 T_target_source = Pose3::Identity();
  double fitness_m2 = 0;    ///< mean squared distance of inliers to their nearest target point
  double inlier_ratio = 0;  ///< share of source points with a target point within the final radius
  int iterations = 0;
  bool converged = false;
};

/// Point-to-plane ICP target: k-d tree and normals (8 neighbours) built once, so that several
/// alignments against it (a loop closure's ambiguity check) share them.
class IcpTarget {
 public:
  explicit IcpTarget(Cloud target);
  /// The correspondence radius shrinks from max_corr_m to max_corr_m / 3.
  IcpResult align(const Cloud& source, const Pose3& init, int iterations, double max_corr_m) const;
  /// What the matched planes tell about the translation at T: the mean of n n^T over the source
  /// points whose nearest target point within max_corr_m has a normal (zero when none does). A
  /// street whose facades all run one way leaves its direction along the street near zero.
  Mat3 translationInformation(const Cloud& source, const Pose3& T, double max_corr_m) const;

 private:
  Cloud cloud_;
  KdTree tree_;
  std::vector<Vec3> normals_;  ///< zero where the neighbours show no clear plane
};

/// Weakest over strongest eigenvalue of the horizontal block of a translation information
/// (IcpTarget::translationInformation): near 0 where ICP cannot tell where along a street it is.
double horizontalConditioning(const Mat3& info);

/// A match is accepted when its fitness is below max_fitness_m2 and enough points matched.
struct IcpAcceptance {
  double max_fitness_m2 = 0.09;
  double min_inlier_ratio = 0.5;
  bool operator()(const IcpResult& r) const {
    return r.fitness_m2 < max_fitness_m2 && r.inlier_ratio >= min_inlier_ratio;
  }
};

/// Where to look for a rival of the match ICP found: a local minimum it stopped in (one facade
/// further along a row of look-alike facades), or a street ICP cannot pin down along its length
/// (a bridge between uniform parapets, where ICP stays wherever it starts).
struct IcpAmbiguity {
  std::vector<double> along_m;   ///< start offsets along the match's heading (both signs) [m]
  std::vector<double> across_m;  ///< ... and across it [m]
  double separation_m = 1.5;     ///< a rival ends at least this far from the match [m]
  double inlier_margin = 0.0;    ///< a better fit matches this much more of the source's points
  /// A rival whose inlier ratio reaches this share of the match's, and whose fitness is at most
  /// the match's over this share, fits as well: the match is ambiguous. 1 or more = off
  double rival_share = 1.0;
  int iterations = 30;
  double max_corr_m = 2.0;
  IcpAcceptance accept;
};

/// The restart that comes closest to the match (IcpAmbiguity).
struct IcpRival {
  double apart_m = 0.0;  ///< how far from the match it ended [m]
  /// min(its inlier ratio / the match's, the match's fitness / its fitness): 1 = as good
  double share = 0.0;
  bool better = false;  ///< more of the points (by inlier_margin) and a lower fitness
};

/// ICP from `match` shifted by each offset of `amb`; of the results that end more than
/// amb.separation_m away and are accepted, the one that fits better, else the one with the
/// highest share; share 0 when there is none.
IcpRival strongestRival(const IcpTarget& target, const Cloud& source, const IcpResult& match,
                        const IcpAmbiguity& amb);

/// The match is not unique: the rival fits better, or as well (amb.rival_share).
inline bool ambiguousMatch(const IcpRival& r, const IcpAmbiguity& amb) {
  return r.better || r.share >= amb.rival_share;
}

/// The one place `source` fits around `match`: the match when no rival fits as well; when a
/// rival fits better (ICP from a drifted start stopped on the wrong features), the best fit of
/// all the rival starts, when no rival of its own fits as well; none when ambiguous.
std::optional<IcpResult> uniqueMatch(const IcpTarget& target, const Cloud& source,
                                     const IcpResult& match, const IcpAmbiguity& amb);

}  // namespace slamroute::evaluate
