#pragma once
// What a car can do between two scans: the bounds the SLAM front end checks a registration
// against before it believes it (evaluate/src/Slam.cpp).
#include <optional>

#include "slamroute/core/OdometrySpec.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/Config.hpp"

namespace slamroute::evaluate {

/// Rotation angle of a pose [rad].
double rotationAngle(const Pose3& T);

/// The motion `m` scaled to the share `f` of itself (rotation angle and translation scaled alike;
/// exact for a constant turn rate and speed up to the small-angle chord error).
Pose3 scaledMotion(const Pose3& m, double f);

/// Highest turn rate a car can drive at `speed_mps` [rad/s]: lateral acceleration over speed,
/// capped by cfg.odometry.max_step_change_deg per 0.1 s.
double maxTurnRate(const Config& cfg, double speed_mps);

/// A registration that moves the pose far from the prediction within one frame interval `dt` [s]
/// is a failure (wrong correspondences, e.g. a passing car filling half the view), not motion: a
/// car's heading can change at most by its highest turn rate at the current speed.
bool plausible(const Pose3& pred, const Pose3& result, const Config& cfg, double dt,
               double speed_mps);

/// With wheel odometry + gyro the prediction itself is a measurement, good to centimetres and a
/// fraction of a degree over one scan interval: a registration may move it at most
/// cfg.odometry.wheel_translation_slack_m in x/y and cfg.odometry.wheel_rotation_slack_deg in yaw
/// per 0.1 s, or it slid along a featureless street or locked onto a few stray edges.
bool plausibleWithOdometry(const Pose3& pred, const Pose3& result, const Config& cfg, double dt);

/// A loop closure that moves the new keyframe by `correction_m` after `driven_m` metres since the
/// last accepted closure is believable when the odometry can have drifted that far:
/// correction <= cfg.loop.max_correction_m + cfg.loop.correction_per_m * driven (always true when
/// loop_max_correction_m < 0).
bool plausibleLoopCorrection(double correction_m, double driven_m, const Config& cfg);

/// The pose with its roll and pitch (Z-Y-X Euler angles) moved the share `w` of the way to an
/// IMU's gravity-levelled roll and pitch [rad]; heading and position kept. LeGO-LOAM does the same
/// with its IMU after each scan-to-map step: the LiDAR alone cannot tell a tilted map from a
/// tilted road, so a pitch error taken on a ramp would otherwise stay for good.
Pose3 levelled(const Pose3& T, double roll_rad, double pitch_rad, double w);

/// Yaw sigma of the scan-to-map's prior towards the odometry, per 0.1 s [deg]: from the gyro's
/// noise figures when the drive states them (cfg.odometry.prior_sigma_deg scaled by the root sum
/// of squares of the gyro's noise and bias over that of the reference gyro it was tuned for, at
/// least cfg.odometry.prior_min_sigma_deg), else cfg.odometry.prior_sigma_deg. A configured 0
/// (prior off) stays 0.
double yawPriorSigmaDeg(const Config& cfg, const std::optional<OdometrySpec>& spec);

}  // namespace slamroute::evaluate
