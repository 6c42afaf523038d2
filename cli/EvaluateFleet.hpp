#pragma once
// `slamroute evaluate --drive FLEET_DIR`: every vehicle's evaluation, then the fleet merge.
#include <filesystem>
#include <functional>

#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Fleet.hpp"

namespace slamroute::cli {

/// Evaluates one drive folder into an output folder (the single-drive evaluation).
using EvaluateOne =
    std::function<void(const std::filesystem::path& drive, const std::filesystem::path& out)>;

/// OUT/vehicle_K: vehicle K's evaluation, made by `evaluate_one` (kept as it is when
/// `keep_vehicles` and OUT/vehicle_K/metrics.json exists); then the fleet merge and its files in
/// OUT (evaluate/Fleet.hpp writeFleetOutputs).
evaluate::FleetResult evaluateFleetFolder(const std::filesystem::path& drive,
                                          const std::filesystem::path& out,
                                          const evaluate::Config& cfg, bool keep_vehicles,
                                          const EvaluateOne& evaluate_one);

}  // namespace slamroute::cli
