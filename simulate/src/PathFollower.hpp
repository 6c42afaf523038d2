#pragma once
// A car that drives along a planar path: it moves only along its heading and turns at most
// kMaxCurvature per metre, steering by the path's own curvature plus a feedback on how far it is
// beside the path and how far its heading is off the path's direction (a critically damped
// linear law: lateral errors die out over ~kSettle_m). Where the path turns tighter than a car
// can (SUMO's U-turns between a street's two lanes 3 m apart, whose apex the smoothing tightens
// further), it takes the turn wider and steers back; a record that follows the path itself
// instead would slide the car sideways through the turn, which no wheel odometry sees.
#include <vector>

#include <Eigen/Core>

namespace slamroute::simulate {

class PathFollower {
 public:
  static constexpr double kMaxCurvature = 0.5;  ///< [rad/m], a 2 m turning radius
  static constexpr double kSettle_m = 1.5;      ///< the feedback's distance constant [m]

  /// `path`: at least two points, at parameter u = 0, step_m, 2 step_m, ... (a path resampled
  /// every step_m and then smoothed, so its points may lie closer); the car starts on its first
  /// point, heading along it.
  PathFollower(std::vector<Eigen::Vector2d> path, double step_m);

  /// Drives `distance_m` (>= 0) in steps of at most step_m.
  void drive(double distance_m);

  const Eigen::Vector2d& position() const { return p_; }
  double heading() const { return heading_; }
  /// Where the car is along the path: the distance along it of its nearest point, counted in
  /// steps of step_m (the path's parameter u) [m].
  double along() const { return u_; }
  /// The path's own length up to parameter u: shorter than u where the smoothing straightened
  /// what the path had been resampled from [m].
  double lengthAt(double u) const;

 private:
  void step(double ds);
  void project();
  double pathCurvature(double u) const;  ///< [rad/m]
  /// `v` (one value per path point) interpolated at parameter u, clamped to the path's ends.
  template <class T>
  T sampleAt(const std::vector<T>& v, double u) const;

  std::vector<Eigen::Vector2d> path_;
  double step_m_;
  std::vector<double> angle_;   ///< the path's direction at each point, unwrapped [rad]
  std::vector<double> length_;  ///< the path's length up to each point [m]
  Eigen::Vector2d p_;
  double heading_ = 0.0;
  double u_ = 0.0;
};

}  // namespace slamroute::simulate
