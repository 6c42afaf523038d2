#pragma once
// Internals of runSurvey shared by Survey.cpp (simulation) and SurveyDepth.cpp (depth frames).
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/Config.hpp"

namespace slamroute {
struct SumoNet;
}

namespace slamroute::simulate {

/// Where and when a survey vehicle takes a depth frame.
struct DepthShot {
  double t = 0.0;
  std::string vehicle;
  std::string sumo_edge;
  Pose3 T_world_body = Pose3::Identity();  ///< camera body: x forward, y left, z up
};

/// Builds the world, renders one depth image per shot and writes DIR/NNNNNN.png,
/// DIR/index.csv and DIR/frame_edges.csv (DIR is created even without shots).
void writeDepthFrames(const std::filesystem::path& dir, const SumoNet& net, const Config& cfg,
                      std::uint64_t seed, const std::vector<DepthShot>& shots);

}  // namespace slamroute::simulate
