#pragma once
// Roundabouts from location traces (roadgraph step 1b, Roundabouts.cpp). The hollow cylinder
// cannot see them: around a roundabout every trace point's 10-25 m ring holds the circulating
// lane, which links all arms into one cluster, so no point sees three branches (Ingolstadt's
// three-arm roundabout had no node within 90 m). In the traces a roundabout is vehicles circling
// one centre, all in one sense, round an empty middle; its junctions are where they join and
// leave the ring.
#include <cstddef>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph {

struct Roundabout {
  Point3 centre = Point3::Zero();
  double radius_m = 0.0;  ///< centre to the circulating lane [m]
  int sense = 1;          ///< +1 counter-clockwise (right-hand traffic), -1 clockwise
  int vehicles = 0;       ///< vehicles whose paths fit the circle over min_sweep_deg
  /// Where vehicles join or leave the ring, counter-clockwise from +x: a two-way arm joining at
  /// one point gives one junction, a split arm (separate entry and exit lanes) two.
  std::vector<Point3> junctions;
};

/// Throws std::invalid_argument (one line: the roadgraph.roundabouts keys and their limits).
void checkRoundaboutConfig(const RoundaboutConfig& cfg);

/// Finds roundabouts (checks cfg first). `order`: trace point indices by vehicle, then time;
/// `travel`: per trace point its unit direction of travel (zero when unknown, see
/// travelDirections); `max_gap_s`: a vehicle's trace breaks at larger time gaps; `half_height_m`:
/// points farther in z from the ring are not on it (an overpass). Deterministic.
std::vector<Roundabout> detectRoundabouts(const Traces& traces,
                                          const std::vector<std::size_t>& order,
                                          const std::vector<Vec3>& travel,
                                          const RoundaboutConfig& cfg, double max_gap_s,
                                          double half_height_m);

/// Replaces the hollow-cylinder nodes within radius + absorb_margin_m of a roundabout's centre
/// by the roundabout's junctions (appended after the remaining nodes). Returns the nodes removed.
std::size_t mergeRoundaboutNodes(std::vector<Point3>& nodes, const std::vector<Roundabout>& rbs,
                                 const RoundaboutConfig& cfg, double half_height_m);

}  // namespace slamroute::roadgraph
