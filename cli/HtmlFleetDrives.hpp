#pragma once
// The fleet's trajectories for report.html's slider: every vehicle's merged SLAM trajectory
// under the one alignment of all vehicles onto their ground truths (the alignment of the fleet's
// common ATE, evaluate's FleetAte.cpp), so the page shows the errors the merged map has.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "HtmlLayers.hpp"

namespace slamroute::cli {

/// Per vehicle of the fleet drive `drive_dir` (fleet.json): {"id", "drive": driveLayer} with
/// eval_dir/merged_<folder>.tum as the estimate; an empty array when the drive or a vehicle's
/// merged trajectory is missing (the fleet was not evaluated).
nlohmann::json fleetDriveLayers(const std::filesystem::path& drive_dir,
                                const std::filesystem::path& eval_dir, const MapFrame& f);

}  // namespace slamroute::cli
