#pragma once
// Internal: the merged map and its completeness (FleetMap.cpp).
#include "slamroute/evaluate/Fleet.hpp"
#include "slamroute/evaluate/MapAccuracy.hpp"

namespace slamroute::evaluate {

/// Every stride-th scan of the vehicle at `poses`, voxel-filtered, world frame.
Cloud vehicleMap(const FleetVehicleInput& v, const Trajectory& poses, int stride, double voxel_m);
/// Sample points of the world's facades near the driven streets.
Cloud streetFacades(const Mesh& mesh, const std::vector<Trajectory>& ground_truths,
                    const FleetMergeOptions& opt);
/// Share of `facades` with a point of `map` within covered_m [%].
double coveredPct(const Cloud& facades, const Cloud& map, double covered_m);

}  // namespace slamroute::evaluate
