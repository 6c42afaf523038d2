#pragma once
// The mapping vehicle's body on its suspension: where the LiDAR really is. SUMO gives a 2D path
// (and a lane height); the body stands on the world's road surface at its four wheels (camber,
// swell and roughness tilt it) and moves on a damped spring per axis — pitch, roll and heave —
// driven by the road under the wheels and by the inertia of braking, accelerating and cornering.
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/simulate/DriveConfig.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {

/// Throws std::invalid_argument naming the first bad field of drive.body.
void validate(const VehicleBodyConfig& c);

/// True sensor poses along a drive. `path`: T_world_sensor as a rigid function of the 2D path
/// (vehicleBodyPose: the sensor `mount_height_m` straight above SUMO's reference point, the
/// middle of the front bumper, heading along the motion). Returns poses at the same times with
/// the body's pitch, roll and height on the road, the sensor fixed to the body (`mount_height_m`
/// above the road at the front bumper when the body is level). Where no surface lies under a
/// wheel the lane height from `path` is used.
Trajectory vehicleSensorPoses(const Trajectory& path, const World& world,
                              const VehicleBodyConfig& c, double mount_height_m);

}  // namespace slamroute::simulate
