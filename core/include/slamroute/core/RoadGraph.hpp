#pragma once
// The road graph every planner works on, and its file format graph.json:
//   {"nodes":[{"id","x","y","z"}], "edges":[{"id","u","v","length","weight","polyline":[[x,y,z]…],
//    "sumo_edges":[…], "street"}], "turns": {"<edge id>": [allowed next edge ids…]},
//    "metadata":{…}}
// Edges are directed (u -> v). A two-way street is two edges sharing `street`.
// Node and edge ids equal their index in the vectors.
// Turn permissions: when `restricted_turns` is true, allowed_next[e] lists the edges one may drive
// after e (from a SUMO net's <connection>s); otherwise every edge leaving v(e) is allowed.
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/core/Types.hpp"

namespace slamroute {

struct SumoNet;

struct RoadNode {
  int id = 0;
  Point3 pos = Point3::Zero();
  std::string sumo_junction;  ///< when built from / matched to a SUMO net
};

struct RoadEdge {
  int id = 0;
  int u = 0, v = 0;  ///< node ids, travel from u to v
  double length_m = 0.0;
  double weight = 1.0;  ///< LiDAR matching quality score from depth images (paper R_A)
  Polyline polyline;    ///< ordered centreline from u to v
  std::vector<std::string> sumo_edges;  ///< SUMO edges driven along this edge, in order
  int street = -1;                      ///< undirected street id shared by both directions
};

struct RoadGraph {
  std::vector<RoadNode> nodes;
  std::vector<RoadEdge> edges;
  bool restricted_turns = false;
  std::vector<std::vector<int>> allowed_next;  ///< per edge, when restricted_turns
  std::string metadata_json = "{}";            ///< free-form JSON object (validation scores, …)

  std::vector<std::vector<int>> outEdges() const;  ///< per node, ids of edges leaving it
  /// Edges allowed after `edge` (turn permissions or, unrestricted, all edges leaving v).
  std::vector<int> nextEdges(int edge) const;
  double totalLength() const;
  /// Throws std::invalid_argument (naming `where`) on dangling ids or a bad turn table.
  void validate(const std::string& where) const;

  /// Drivable passenger graph of a net: one node per junction, one edge per SUMO edge, SUMO turn
  /// permissions. With lscc_only, only the largest strongly connected part is kept.
  static RoadGraph fromSumoNet(const SumoNet& net, bool lscc_only = true);

  static RoadGraph readJson(const std::filesystem::path& path);
  void writeJson(const std::filesystem::path& path) const;
  void writeGeoJson(const std::filesystem::path& path) const;
  void writeGraphML(const std::filesystem::path& path) const;
  /// Top-down PNG, edges coloured by `attribute` ("weight", "length" or a per-edge vector given
  /// in `values`), a colour bar with the value range. width in pixels.
  void renderPng(const std::filesystem::path& path, const std::string& attribute = "weight",
                 const std::vector<double>& values = {}, int width_px = 1200) const;
};

}  // namespace slamroute
