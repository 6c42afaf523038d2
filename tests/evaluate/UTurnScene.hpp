#pragma once
// A U-turn in a street of the synthetic city, for the loop closure's submap checks.
#include <numbers>
#include <vector>

#include "SyntheticScene.hpp"

namespace slamroute::evaluate::test {

/// Keyframe poses of a U-turn in the street x = 0 of cityScene, between the junctions at y = 0
/// and y = 40, 4 m apart: south on x = -2, one turning at y = 16, back north on x = 2.
inline std::vector<Pose3> uTurnInAStreet() {
  const double q = 0.5 * std::numbers::pi;
  std::vector<Pose3> kfs;
  for (double y = 36; y >= 20; y -= 4) kfs.push_back(poseXYZYaw(-2, y, 1.8, -q));
  kfs.push_back(poseXYZYaw(0, 16, 1.8, 0));
  for (double y = 20; y <= 36; y += 4) kfs.push_back(poseXYZYaw(2, y, 1.8, q));
  return kfs;
}

constexpr int kUTurnKeyframe = 5;  ///< uTurnInAStreet's keyframe turning

/// Where a later drive north through that street is when it revisits the U-turn: 5 m short of it.
inline Pose3 uTurnRevisit() { return poseXYZYaw(2, 11, 1.8, 0.5 * std::numbers::pi); }

}  // namespace slamroute::evaluate::test
