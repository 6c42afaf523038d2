#pragma once
// Internal to roadgraph: paper §3.1 steps 2-3, streets from the trace points left after removing
// the nodes and their neighbourhoods. GraphBuilder.cpp runs the steps; each file documents its
// choices.
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "PointGrid.hpp"
#include "ShortLinks.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/Intersections.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph::detail {

struct Street {
  std::vector<int> members;        ///< indices into the street point subset
  Polyline centre;                 ///< ordered A -> B, without node positions
  int a = -1, b = -1;              ///< end points (subset indices)
  int u = -1, v = -1;              ///< node ids (end nodes appended after intersections)
  int comp = -1;                   ///< street cluster label, -1 for a short link
  int link_fwd = 0, link_bwd = 0;  ///< short link: vehicles driving u -> v and v -> u
};

/// The (downsampled) trace points outside every node's cleared disk, clustered
/// (StreetClusters.cpp).
struct StreetPoints {
  std::vector<Point3> pts;
  std::vector<int> subset_of;           ///< per voxel, its index in pts, or -1 (cleared)
  std::vector<int> label;               ///< per point of pts, its cluster
  std::vector<std::vector<int>> comps;  ///< per cluster, its points
};
StreetPoints clearNodeNeighbourhoods(const std::vector<Point3>& voxels,
                                     const std::vector<Point3>& nodes, const EdgeConfig& ec,
                                     double half_h);

/// Graph nodes while streets are attached: intersections [0, n_inter), then end nodes.
struct GraphNodes {
  std::vector<Point3> pos;
  std::vector<char> is_end;  ///< per node: a dead end (not an intersection)
  std::size_t n_inter = 0;
};

/// One street per cluster (or per branch, split at a junction it runs through), attached to its
/// two nearest nodes (eqs. 1-2); dead ends get end nodes appended to `nodes` (StreetClusters.cpp).
/// `order`: trace point indices by vehicle, then time; `voxel_of`: per trace point, its voxel.
std::vector<Street> attachStreets(const StreetPoints& sp, const Traces& traces,
                                  const std::vector<std::size_t>& order,
                                  const std::vector<int>& voxel_of, GraphNodes& nodes,
                                  const EdgeConfig& ec, double half_h, GraphBuildStats& st);

/// What attaching a street cluster needs to know (StreetClusters.cpp, PassedNodes.cpp).
struct StreetContext {
  const StreetPoints& spts;
  const PointGrid& sp_grid;  ///< over spts.pts
  const Traces& traces;
  const std::vector<std::size_t>& order;  ///< trace point indices by vehicle, then time
  const std::vector<int>& voxel_of;       ///< per trace point, its voxel
  const std::vector<Point3>& nodes;       ///< intersections [0, n_inter), then end nodes
  const PointGrid& node_grid;             ///< over the intersection nodes
  std::size_t n_inter;
  const EdgeConfig& ec;
  double half_h;
};
/// Splits street cluster `c` (its members and geodesic ends a, b in `s`, attached to nodes na, nb;
/// -1: a dead end) at a junction it runs through, appending one street per branch (u = -1 for a
/// branch ending at a dead end); false when it does not (PassedNodes.cpp).
bool splitAtPassedNode(const StreetContext& ctx, int c, const Street& s, int na, int nb,
                       std::vector<Street>& streets, GraphBuildStats& st);

/// Dead ends within `radius` of each other become one node (EndNodes.cpp).
void mergeNearbyEnds(std::vector<Point3>& nodes, const std::vector<char>& is_end, double radius,
                     double half_h, std::vector<Street>& streets, GraphBuildStats& st);

/// Dead ends whose street runs straight at another street a few metres on (its vehicles' routes
/// end at the stop line) become a T junction on that street, which is split there
/// (StopLineEnds.cpp).
void joinStopLineEnds(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                      const EdgeConfig& ec, double half_h, GraphBuildStats& st);

/// Streets between junctions whose street the clearing removed, from drives between them
/// (ShortLinks.cpp); appended to `streets` with straight node-to-node polylines in `polys`.
void addShortLinks(const Passages& passages, const std::vector<Point3>& nodes, const EdgeConfig& ec,
                   std::vector<Street>& streets, std::vector<Polyline>& polys, GraphBuildStats& st);

/// Calls fn(street, first, last) for every run: a vehicle's consecutive trace points (positions
/// first < last in `order`) on one street, with no time gap > max_gap_s (StreetDirections.cpp).
void forEachRun(const Traces& traces, const std::vector<std::size_t>& order,
                const std::vector<int>& street_of_point, double max_gap_s,
                const std::function<void(int, std::size_t, std::size_t)>& fn);

/// Splits street k at arc position `arc` along its centreline into u -> node (kept at k) and
/// node -> v (appended); its points go to the part they lie along (StreetSplit.cpp).
void splitStreet(std::vector<Street>& streets, std::size_t k, double arc, int node,
                 const std::vector<Point3>& sp);

/// Streets ending at node n.
int degreeOf(const std::vector<Street>& streets, int n);
/// A point on a street: its index, arc position along the centreline and the point.
struct PointOnStreet {
  std::size_t street = 0;
  double arc = 0.0;
  Point3 at = Point3::Zero();
};
/// Every dead end (a node only street k ends at) is offered to `find` with its tip and heading
/// over `heading_m`; where `find` names a point on another street, that street is split there at
/// a new intersection and street k ends at it. Returns how many ends were joined (StreetSplit.cpp).
int joinDeadEnds(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                 double heading_m,
                 const std::function<std::optional<PointOnStreet>(std::size_t, const Point3&,
                                                                  const Eigen::Vector2d&)>& find);
/// A new intersection node at p: inserted after the intersections, the end nodes move up one.
int insertIntersection(GraphNodes& gn, std::vector<Street>& streets, const Point3& p);

/// Dead ends where survey vehicles set off beside a bend of another street, on the straight
/// continuation of one of its legs, become a junction at the bend (BendEnds.cpp).
void joinBendEnds(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                  const EdgeConfig& ec, double half_h, GraphBuildStats& st);

/// Where vehicles turn round part-way along a street (a bend where a two-way street meets a
/// one-way one), a node of kind kTurningPlace splits the street (TurningPlaces.cpp).
/// `street_of_point`: per trace point, its street (-1: none).
void splitAtTurningPlaces(GraphNodes& gn, std::vector<Street>& streets, const StreetPoints& spts,
                          const Traces& traces, const std::vector<std::size_t>& order,
                          const std::vector<int>& street_of_point, const EdgeConfig& ec,
                          GraphBuildStats& st);

/// Per street, the runs of travel seen u -> v (fwd) and v -> u (bwd) (StreetDirections.cpp).
struct TravelCounts {
  std::vector<int> fwd, bwd;
};
TravelCounts countDirections(const Traces& traces, const std::vector<std::size_t>& order,
                             const std::vector<int>& street_of_point,
                             const std::vector<Street>& streets, const std::vector<Polyline>& polys,
                             const Passages& passages, const EdgeConfig& ec);

// Centreline.cpp
/// Arc-length position of the projection of p on a polyline.
double arcPosition(const Polyline& pl, const Point3& p);
/// The point `arc` metres along a polyline (the inverse of arcPosition on it).
Point3 pointAtArc(const Polyline& pl, double arc);
/// The tip of centreline c at its u end (or v end) and its heading out of the street there, from
/// the point `reach` back along it (zero when the street is a point).
std::pair<Point3, Eigen::Vector2d> tipAndHeading(const Polyline& c, bool at_u, double reach);
/// Geodesic (Dijkstra) distances from `src` within one street cluster; dist is indexed by subset
/// index and only entries of the cluster's members are touched.
void geodesic(const std::vector<Point3>& pts, const PointGrid& grid, const std::vector<int>& label,
              int comp, double tol, int src, std::vector<double>& dist);
/// Centreline of `members` ordered by `d` (geodesic distance from one end): centroids of
/// step_m bins.
Polyline binnedCentre(const std::vector<Point3>& sp, const std::vector<int>& members,
                      const std::vector<double>& d, double step_m);
/// Removes spikes from a street's polyline: a vertex where it turns back by more than 150 deg
/// between two legs of at least min_leg_m each. A bin of points the geodesic order reached the
/// long way round (past the far end and back through other streets) has its centroid near the
/// other end of the street, so the line runs there and back.
void dropSpikes(Polyline& pl, double min_leg_m);

}  // namespace slamroute::roadgraph::detail
