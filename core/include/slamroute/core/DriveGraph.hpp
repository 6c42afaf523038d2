#pragma once
// The drivable road graph of a SUMO net for passenger cars: junctions are vertices, passenger
// edges are directed graph edges (a Boost.Graph adjacency_list), plus SUMO's turn permissions.
#include <boost/graph/adjacency_list.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "slamroute/core/SumoNet.hpp"

namespace slamroute {

struct DriveVertex {
  std::string junction_id;
  Point3 pos = Point3::Zero();
};
struct DriveEdge {
  std::size_t index = 0;  ///< position in DriveGraph::edges
  std::string sumo_edge;
  double length_m = 0.0;
  double speed_mps = 0.0;
  Polyline shape;
};

using DriveBGL =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS, DriveVertex, DriveEdge>;

struct DriveGraph {
  DriveBGL g;
  /// Edge list in net order; `edges[i]` is graph edge i (source, target vertex indices).
  struct EdgeRef {
    std::size_t u, v;
    std::string sumo_edge;
    double length_m;
  };
  std::vector<EdgeRef> edges;
  /// allowed_next[i] = indices of edges one may drive onto after edge i (SUMO <connection>s).
  std::vector<std::vector<std::size_t>> allowed_next;
  /// Vertices (and edges) in the largest strongly connected component over junctions (turn
  /// permissions ignored).
  std::vector<bool> in_lscc_vertex, in_lscc_edge;
  std::size_t lscc_vertices = 0, lscc_edges = 0;
  /// Edges in the largest set strongly connected under the turn permissions (allowed_next): the
  /// edges a car can drive onto and leave again legally. An edge to a junction at the map border
  /// where cars may not turn round is in the junction part but not in this one.
  std::vector<bool> in_legal_edge;
  std::size_t legal_edges = 0;

  /// SUMO edge id -> index into `edges`.
  std::unordered_map<std::string, std::size_t> edge_of;

  std::size_t numVertices() const { return boost::num_vertices(g); }
  std::size_t numEdges() const { return edges.size(); }

  /// Builds from a net: vertices are junctions touched by passenger edges, edges are passenger
  /// edges. Throws std::invalid_argument naming the net when it has no drivable edge.
  static DriveGraph fromNet(const SumoNet& net);
};

/// Summary printed by `slamroute network-info`.
struct NetworkInfo {
  std::size_t junctions = 0;        ///< non-internal junctions in the net
  std::size_t passenger_edges = 0;  ///< non-internal edges open to passenger cars
  std::size_t lscc_junctions = 0, lscc_edges = 0;
  double total_length_m = 0.0;  ///< sum of passenger edge lengths
  double lscc_length_m = 0.0;
};
NetworkInfo networkInfo(const SumoNet& net);

}  // namespace slamroute
