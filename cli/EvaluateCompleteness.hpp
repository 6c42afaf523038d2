#pragma once
// GP occupancy as a map-completeness measure of an evaluated drive (issue 29): the drive's scans
// at the SLAM estimate go into explore's occupancy grid; within explore.completeness_radius_m of
// the net's streets, the unknown and frontier shares and the mean GP frontier probability join
// metrics.json ("map_completeness") and OUT/frontier_probability.png shows them.
// Computed here, not in evaluate: explore links evaluate (its plots), so evaluate cannot call
// explore; evaluate only owns the figures' typed form and their place in metrics.json.
#include <filesystem>

#include "slamroute/core/Scan.hpp"
#include "slamroute/evaluate/EvaluationResult.hpp"
#include "slamroute/explore/Config.hpp"

namespace slamroute::cli {

inline constexpr const char* kFrontierPng = "frontier_probability.png";

/// For a simulated drive (world.yaml names its net): sets r.map_completeness from OUT/estimate.tum
/// and `scans`, rewrites OUT/metrics.json and writes OUT/frontier_probability.png. A drive without
/// world.yaml (no net to measure near) is left as it is.
void addMapCompleteness(const std::filesystem::path& drive, const ScanSource& scans,
                        const std::filesystem::path& out, const explore::Config& cfg,
                        evaluate::EvaluationResult& r);

}  // namespace slamroute::cli
