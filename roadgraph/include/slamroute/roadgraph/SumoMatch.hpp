#pragma once
// Validation of a road graph against a SUMO net's true intersections, and the mapping of graph
// edges to the SUMO edges they cover (so routes on the graph can be driven in SUMO).
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/roadgraph/Config.hpp"

namespace slamroute::roadgraph {

struct TrueIntersection {
  std::string junction;
  Point3 pos = Point3::Zero();
};
/// Junctions with >= 3 distinct neighbouring junctions over passenger edges (either direction).
std::vector<TrueIntersection> trueIntersections(const SumoNet& net);

struct ValidationResult {
  std::size_t true_intersections = 0, detected_nodes = 0, matched_nodes = 0;
  double node_precision = 0.0, node_recall = 0.0, node_f1 = 0.0;
  std::size_t true_chains = 0, detected_streets = 0, matched_streets = 0, found_chains = 0;
  double edge_precision = 0.0, edge_recall = 0.0;
  std::vector<std::string> missed_junctions;  ///< true intersections without a detected node
  std::vector<int> false_nodes;               ///< detected intersection nodes without a match
  std::vector<std::string> node_junction;     ///< per graph node, matched SUMO junction or ""
  std::string toJson() const;                 ///< JSON object text
};
/// Compares the intersection nodes (node_is_end false) with the net's true intersections:
/// one-to-one greedy matching within cfg.match_radius_m. An undirected detected street matches
/// when its end nodes are matched to the two intersections of a real chain (chains pass through
/// junctions with exactly 2 neighbours).
ValidationResult validateAgainstNet(const RoadGraph& graph, const std::vector<char>& node_is_end,
                                    const SumoNet& net, const SumoMatchConfig& cfg);
/// The same scores against the net's places, where a divided road is one street with two
/// directions. One rule groups the net's junctions and the graph's intersection nodes into places:
/// two intersections (>= 3 distinct neighbours) joined by a street (through junctions with 2
/// neighbours) whose ends lie at most cfg.place_link_max_m apart are one place (the carriageway
/// crossings of a divided road, the corners of a junction box, staggered T junctions). Both graphs
/// are contracted onto their places; true intersections are places with >= 3 neighbouring places
/// and chains run through places with 2. A detected place matches a true one within
/// cfg.match_radius_m (closest two vertices); a street between two detected places matches when
/// they are matched to the ends of a chain, and a street inside one place is not counted.
/// detected_nodes and matched_nodes count places, false_nodes lists every node of an unmatched
/// place, node_junction names the matched place's junctions joined by '+'.
ValidationResult validateAgainstPlaces(const RoadGraph& graph, const std::vector<char>& node_is_end,
                                       const SumoNet& net, const SumoMatchConfig& cfg);

/// Fills RoadEdge::sumo_edges with the passenger SUMO edges along each edge, in driving order
/// (nearest lane in the edge's direction of travel). An end edge of a chain that arrives at u or
/// leaves v (cfg.stray_radius_m) is a stray match of a crossing road and dropped. Returns the
/// number of edges left unmapped.
std::size_t mapSumoEdges(RoadGraph& graph, const SumoNet& net, const SumoMatchConfig& cfg);

struct TurnStats {
  std::size_t candidate_turns = 0;  ///< (in edge, out edge) pairs at the graph's nodes
  std::size_t forbidden_turns = 0;  ///< of these, the ones SUMO does not lead through
};
/// Sets the graph's turn permissions (restricted_turns, allowed_next) from the net, after
/// mapSumoEdges: e -> f is allowed when SUMO leads from e's last SUMO edge to f's first one
/// over at most cfg.turn_max_detour_m of edges in between (plus the stretches between the node
/// and the two chains' ends), or they are the same SUMO edge.
/// An edge without SUMO edges keeps every turn except back onto its own street.
TurnStats turnsFromNet(RoadGraph& graph, const SumoNet& net, const SumoMatchConfig& cfg);

}  // namespace slamroute::roadgraph
