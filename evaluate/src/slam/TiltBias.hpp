#pragma once
// The IMU's pitch bias, measured at loop closures. The scan-to-map keeps the pose level with
// the local map, and the IMU levelling (OdometryConfig::imu_tilt_weight) pulls the map's tilt
// to the IMU's, bias included: the estimate then climbs or sinks by the bias times the distance
// driven, whatever the heading (a car drives forward; pitch error e lifts it by -sin(e) per
// metre, pitch positive nose down). No scan can tell a biased pitch from a slope, but a closure
// can: it brings the car back to a height it had before. Each closure's height correction over
// the path since the drift last restarted is the bias left in effect there; the estimate is the
// median of the recent closures' implied biases, which a false or poorly placed closure does
// not move.
#include <deque>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/Config.hpp"

namespace slamroute::evaluate::slam {

class TiltBias {
 public:
  explicit TiltBias(const OdometryConfig& cfg) : cfg_(cfg) {}

  /// A new keyframe at `position` (as estimated when added): the path grows.
  void addKeyframe(const Vec3& position);
  /// An accepted closure from keyframe `old_kf` to the newest one, which it moves up by
  /// `correction_z_m` (the closure's height minus the estimate's) [m].
  void addClosure(int old_kf, double correction_z_m);
  /// The pitch bias to take off the IMU's readings [rad]; 0 until enough closures.
  double pitchBias() const { return bias_rad_; }
  /// Takes a bias estimated elsewhere (the pose graph's) from now on [rad].
  void assume(double bias_rad) { bias_rad_ = bias_rad; }

 private:
  const OdometryConfig& cfg_;
  std::vector<double> path_m_;     ///< per keyframe: path from the first one [m]
  std::vector<double> bias_path_;  ///< per keyframe: integral of the bias in effect over it [rad m]
  Vec3 last_ = Vec3::Zero();
  int anchor_ = 0;                  ///< the newest keyframe of the last closure: drift restarts
  std::deque<double> implied_rad_;  ///< the recent closures' implied biases
  double bias_rad_ = 0.0;
};

}  // namespace slamroute::evaluate::slam
