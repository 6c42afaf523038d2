#pragma once
// Paper §3.1 steps 2-3 (Fig. 2c-d): streets from the trace points left after removing the nodes,
// connected to their two nearest nodes (eqs. 1-2), with direction(s) of travel from the traces.
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/roadgraph/Roundabouts.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph {

struct GraphBuildStats {
  std::size_t trace_points = 0, voxels = 0, intersection_points = 0;
  std::size_t intersections = 0, dead_ends = 0, streets = 0, one_way_streets = 0;
  std::size_t unknown_direction_streets = 0, dropped_fragments = 0, isolated_nodes_dropped = 0;
  std::size_t merged_end_pairs = 0;     ///< groups of nearby dead ends made one node
  std::size_t passed_nodes = 0;         ///< street clusters split at a junction they run through
  std::size_t short_links = 0;          ///< streets between close junctions from vehicle passes
  std::size_t stop_line_junctions = 0;  ///< dead ends just short of a street made a T junction
  std::size_t bend_end_junctions = 0;   ///< dead ends beside a street's bend made a junction there
  std::size_t u_turn_streets = 0;  ///< U-shaped clusters (separate lanes) attached at their bend
  std::size_t roundabouts = 0;     ///< rings whose junctions replaced the nodes there
  std::size_t divided_node_pairs = 0;    ///< carriageway nodes of divided roads merged (pairs)
  std::size_t divided_streets = 0;       ///< carriageway pairs made one street
  std::size_t staggered_node_pairs = 0;  ///< T junctions on opposite sides merged (pairs)
  std::size_t turning_places = 0;        ///< streets split where vehicles turn round part-way along
  double seconds = 0.0;
};

/// What a graph node stands for; any kind but kIntersection is not an intersection.
enum NodeKind : char {
  kIntersection = 0,
  kDeadEnd = 1,       ///< a street's end, or where two met (a corner no vehicle drove round)
  kTurningPlace = 2,  ///< a bend part-way along a street where vehicles turn round
};

struct GraphBuildResult {
  RoadGraph graph;                ///< weights all 1 until assignDepthWeights
  std::vector<char> node_is_end;  ///< per graph node, its NodeKind (non-zero: not an intersection)
  GraphBuildStats stats;
  std::vector<Roundabout> roundabouts;  ///< found by detectRoundabouts, junctions among the nodes
};

/// Whole traces -> graph pipeline. Throws std::invalid_argument naming traces.source on bad
/// traces and std::runtime_error when no intersection is found.
GraphBuildResult graphFromTraces(const Traces& traces, const Config& cfg);

}  // namespace slamroute::roadgraph
