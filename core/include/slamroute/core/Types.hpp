#pragma once
// Core geometric types shared by every module.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace slamroute {

using Point3 = Eigen::Vector3d;
using Point2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Pose3 = Eigen::Isometry3d;  ///< rigid transform; name instances T_target_source
using Polyline = std::vector<Point3>;

/// Length of a polyline in metres (3D).
double polylineLength(const Polyline& pl);

}  // namespace slamroute
