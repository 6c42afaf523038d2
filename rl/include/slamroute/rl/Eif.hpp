#pragma once
// Extended information filter over the vehicle pose (x, y, heading): the uncertainty model
// behind the paper's uncertainty reward R_U = det(L(1:3, 1:3)) (eq. 6).
//
// The state is kept in information form: L (3x3 information matrix; the pose block *is* the
// whole matrix here). Only L matters for R_U, so the information vector is not tracked.
//  - Driving an edge (prediction): x' = x + d cos(h), y' = y + d sin(h), h' = h + dh with
//    Jacobian F; L' = (F L^-1 F^T + Q)^-1 (the EIF prediction). Q grows linearly with the
//    length driven, rotated into the driving direction (along/cross track), and is scaled by
//    1 + poor_weight_gain * (1 - w) for an edge of normalised LiDAR-matching weight w: on a
//    feature-poor street the scan matching drifts faster.
//  - Arriving at an already visited node (loop closure): the map there holds the estimate of
//    that node's earlier visit, L_node; registering against it adds information
//    (L_node^-1 + R_lc)^-1 to L (the cross-correlation between the two is ignored, a
//    conservative-enough approximation for planning).
// det(L) under/overflows quickly along long routes, so everything is in log-det:
// logDetCov() = -log det L. Driving never lowers it (det F = 1, Q > 0); a closure never raises it.
#include <Eigen/Core>

#include "slamroute/rl/Config.hpp"

namespace slamroute::rl {

using Info3 = Eigen::Matrix3d;

/// Motion model of one edge, precomputed (see header comment).
struct EdgeMotion {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d Q = Eigen::Matrix3d::Zero();
};

/// Loop-closure registration noise R_lc (covariance of x, y, heading).
Eigen::Matrix3d closureNoise(const EifConfig& cfg);

/// d: length driven [m], heading [rad], weight in [0,1].
EdgeMotion edgeMotion(const EifConfig& cfg, double length_m, double heading_rad, double weight);

class PoseEif {
 public:
  explicit PoseEif(const EifConfig& cfg);
  void reset();
  /// Prediction over one driven edge.
  void drive(const EdgeMotion& mo);
  /// Loop closure against the stored information of a visited node.
  void closeLoop(const Info3& node_info);
  const Info3& info() const { return L_; }
  /// log det of the pose covariance = -log det L.
  double logDetCov() const;
  /// log det of the information matrix (log of the paper's R_U).
  double logDetInfo() const { return -logDetCov(); }

 private:
  Info3 L_, L0_;
  Eigen::Matrix3d R_lc_;
};

}  // namespace slamroute::rl
