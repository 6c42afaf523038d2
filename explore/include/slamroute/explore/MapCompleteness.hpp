#pragma once
// GP occupancy as a map-completeness measure of a drive (issue 29, item 4): the drive's scans at
// its poses (ground truth or SLAM estimate) go into the same occupancy grid the explorers share;
// within `street_radius_m` of the net's streets the measure is the share of cells still unknown
// and the share that are frontier cells (ground next to unknown), plus a picture of the GP
// frontier probability there. Lives in explore/ (which links evaluate for its plots), so the
// report code in cli/ calls it.
#include <cstddef>
#include <filesystem>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/explore/Config.hpp"
#include "slamroute/explore/OccupancyGrid.hpp"

namespace slamroute::explore {

struct MapCompleteness {
  std::size_t cells = 0;                   ///< grid cells within the radius of a street
  double unknown_share = 0.0;              ///< of those, never seen
  double frontier_share = 0.0;             ///< of those, frontier cells
  double mean_frontier_probability = 0.0;  ///< GP frontier probability (eq. 11) averaged there
};

/// The occupancy grid of a drive's scans at its sensor poses (the road mount_height_m below the
/// sensor): a pose enters when it lies at least spacing_m from the last one used (0: all) and a
/// scan has its time (within 1 ms; an estimate of a strided evaluation has fewer poses than
/// the drive has scans). Throws std::invalid_argument when no pose has a scan.
OccupancyGrid occupancyFromScans(const ScanSource& scans, const Trajectory& poses,
                                 const RoadGraph& g, const GridConfig& cfg, double spacing_m);

/// Cells within `street_radius_m` of any street of g, as a mask over the grid.
std::vector<bool> streetMask(const OccupancyGrid& grid, const RoadGraph& g, double street_radius_m);

MapCompleteness mapCompleteness(const OccupancyGrid& grid, const std::vector<bool>& mask,
                                const GpConfig& gp);

/// Top-down PNG of the GP frontier probability inside the mask (black outside, grey unknown,
/// white ground, blue obstacle; frontier probability in red on top), one pixel per cell, north up.
void writeFrontierProbabilityPng(const std::filesystem::path& path, const OccupancyGrid& grid,
                                 const std::vector<bool>& mask, const GpConfig& gp);

}  // namespace slamroute::explore
