#pragma once
// The mapping vehicle's recorded path made one a car can drive. SUMO moves its vehicles between a
// junction's internal lanes (and at the end of lane changes there) by up to ~1 m sideways per
// 0.1 s step; no car crabs so, and no wheel odometry or gyro would see it if one did. SUMO's own
// angle (the lane's direction) is no heading either: it jumps by up to ~100 deg within a step
// where the car enters a junction's internal lane.
#include "slamroute/core/Trajectory.hpp"

namespace slamroute::simulate {

/// Replaces SUMO's positions (x, y) by the path averaged along its own length, twice over a
/// window of +-`smoothing_m` (a triangular kernel 4 x `smoothing_m` wide), so a sideways jump is
/// spread over the next metres, and then driven by a car (PathFollower: it moves only along its
/// heading and turns at most 0.5 rad per metre, so it takes a U-turn tighter than that wider and
/// steers back). How far it drives from one pose to the next is how far the position along the
/// path, averaged over +-0.5 s, advanced (so the speed does not jump where a step was sideways).
/// SUMO's height and pitch are kept. Throws std::invalid_argument when smoothing_m is not > 0.
void makeDrivable(Trajectory& traj, double smoothing_m);

}  // namespace slamroute::simulate
