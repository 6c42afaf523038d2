#pragma once
// Parameters of the simulate module, with the paper's defaults and units. YAML section "simulate:".
// Shared between the world/sensor part (world, lidar, depth) and the SUMO part (survey, drive).
#include "slamroute/simulate/DepthCameraConfig.hpp"
#include "slamroute/simulate/DriveConfig.hpp"
#include "slamroute/simulate/LidarConfig.hpp"
#include "slamroute/simulate/SurveyConfig.hpp"
#include "slamroute/simulate/WorldConfig.hpp"

namespace slamroute::simulate {

struct Config {
  WorldConfig world;        ///< procedural 3D city
  LidarConfig lidar;        ///< LiDAR geometry + noise
  DepthCameraConfig depth;  ///< depth camera
  SurveyConfig survey;      ///< survey drives (SUMO)
  DriveConfig drive;        ///< route drives (SUMO)
};

template <class V>
void visitFields(V& v, Config& c) {
  v.section("world", c.world);
  v.section("lidar", c.lidar);
  v.section("depth", c.depth);
  v.section("survey", c.survey);
  v.section("drive", c.drive);
}

}  // namespace slamroute::simulate
