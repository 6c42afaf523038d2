#pragma once
// Relocalisation after a failed scan-to-map (not in LeGO-LOAM): yaw hypotheses over 360 deg
// around the prediction, or, before the speed is known, forward offsets. Every hypothesis gets a
// few coarse iterations; the one with the most inliers wins when it is not the prediction itself
// and clearly beats it, and is then refined.
#include <optional>

#include "FrontEnd.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Registration.hpp"

namespace slamroute::evaluate::slam {

struct Relocalisation {
  Pose3 T_world = Pose3::Identity();
  int inliers = 0;
};

/// The recovered pose, or nullopt when no hypothesis clearly beats the failed registration
/// (`failed_inliers`) and the prediction. `fine`: the scan-to-map's options, used without their
/// motion prior.
std::optional<Relocalisation> relocalise(const FeatureMap& local_map, const PreparedScan& scan,
                                         const Pose3& pred, bool have_velocity,
                                         const AlignOptions& fine, int failed_inliers,
                                         const Config& cfg);

}  // namespace slamroute::evaluate::slam
