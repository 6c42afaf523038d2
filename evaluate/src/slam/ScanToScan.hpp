#pragma once
// Scan-to-scan odometry (LeGO-LOAM "featureAssociation", two-step: planar features fix z, roll
// and pitch, then edge features x, y and yaw) against the previous good scan.
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate::slam {

class ScanToScan {
 public:
  explicit ScanToScan(const Config& cfg) : cfg_(cfg) {}
  /// The scan the next one registers against (its less-sharp and less-flat features).
  void setPrevious(const FeatureSet& f) { prev_.build(f.less_sharp, f.less_flat); }
  /// Motion from the previous scan to this one, starting from the prediction `T_prev_pred`;
  /// a step that finds too few matches keeps what it started from.
  Pose3 align(const FeatureSet& f, const Pose3& T_prev_pred) const;

 private:
  const Config& cfg_;
  FeatureMap prev_;  ///< previous good scan's features, its body frame
};

}  // namespace slamroute::evaluate::slam
