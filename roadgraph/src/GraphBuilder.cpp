// Paper §3.1: traces -> road graph. The steps, each in its own file:
// 1. Nodes: hollow-cylinder intersection points merged into junctions (Intersections.cpp); at
//    roundabouts, which the cylinder cannot see, the ring's junctions instead (Roundabouts.cpp).
// 2. Streets: the trace points left after removing the nodes' neighbourhoods, clustered, each
//    cluster attached to its two nearest nodes, eqs. 1-2 (StreetClusters.cpp), with its centreline
//    (Centreline.cpp); dead ends that nearly touch are one node (EndNodes.cpp); a dead end that
//    stops just short of a street it runs at is a T junction on that street (StopLineEnds.cpp),
//    one that starts beside a street's bend in line with one of its legs a junction at the bend
//    (BendEnds.cpp);
//    a street is split where vehicles turn round part-way along it (TurningPlaces.cpp).
// 3. Links between junctions too close for a street to survive the clearing, from vehicles that
//    drive from one straight into the other (ShortLinks.cpp).
// 4. Direction(s) of travel from each vehicle's runs along a street (StreetDirections.cpp): a
//    street with runs in one direction only is one-way (one directed edge); with both, or with no
//    usable run (then logged), it is two-way (two RoadEdges sharing `street`).
#include "slamroute/roadgraph/GraphBuilder.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "DividedRoads.hpp"
#include "ShortLinks.hpp"
#include "Streets.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/roadgraph/Intersections.hpp"
#include "slamroute/roadgraph/Roundabouts.hpp"

namespace slamroute::roadgraph {
namespace {

using detail::Street;

/// The RoadGraph of the streets: one directed edge per direction of travel seen (both when none
/// was); nodes without edges are dropped (a planner must reach every node).
void assembleGraph(const std::vector<Point3>& nodes, const std::vector<char>& is_end,
                   const std::vector<Street>& streets, const std::vector<Polyline>& polys,
                   const detail::TravelCounts& runs, const EdgeConfig& ec, GraphBuildResult& out) {
  auto& st = out.stats;
  const std::vector<int>& fwd = runs.fwd;
  const std::vector<int>& bwd = runs.bwd;
  std::vector<int> degree(nodes.size(), 0);
  for (const auto& s : streets) {
    ++degree[static_cast<std::size_t>(s.u)];
    ++degree[static_cast<std::size_t>(s.v)];
  }
  std::vector<int> new_id(nodes.size(), -1);
  RoadGraph& g = out.graph;
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    if (degree[j] == 0) {
      ++st.isolated_nodes_dropped;
      continue;
    }
    new_id[j] = static_cast<int>(g.nodes.size());
    RoadNode rn;
    rn.id = new_id[j];
    rn.pos = nodes[j];
    g.nodes.push_back(rn);
    out.node_is_end.push_back(is_end[j]);
  }
  st.intersections =
      static_cast<std::size_t>(std::count(out.node_is_end.begin(), out.node_is_end.end(), 0));
  for (std::size_t k = 0; k < streets.size(); ++k) {
    const int u = new_id[static_cast<std::size_t>(streets[k].u)];
    const int v = new_id[static_cast<std::size_t>(streets[k].v)];
    bool f = fwd[k] >= ec.min_direction_runs, b = bwd[k] >= ec.min_direction_runs;
    if (!f && !b) {
      ++st.unknown_direction_streets;
      f = b = true;  // no usable evidence: assume two-way
    } else if (f != b) {
      ++st.one_way_streets;
    }
    auto add = [&](int from, int to, Polyline pl) {
      RoadEdge e;
      e.id = static_cast<int>(g.edges.size());
      e.u = from;
      e.v = to;
      e.length_m = polylineLength(pl);
      e.polyline = std::move(pl);
      e.street = static_cast<int>(k);
      g.edges.push_back(std::move(e));
    };
    if (f) add(u, v, polys[k]);
    if (b) add(v, u, Polyline(polys[k].rbegin(), polys[k].rend()));
  }
}

/// The traces prepared once for every step: vehicle order, travel directions, 2 m voxels.
struct PreparedTraces {
  std::vector<std::size_t> order;
  std::vector<Vec3> travel;
  Downsampled ds;
};

PreparedTraces prepareTraces(const Traces& traces, const Config& cfg, GraphBuildStats& st) {
  PreparedTraces p;
  std::vector<Point3> raw;
  raw.reserve(traces.points.size());
  for (const auto& q : traces.points) raw.push_back(q.pos);
  p.order = byVehicleThenTime(traces);
  p.travel = travelDirections(traces, p.order, cfg.nodes.travel_span_m, cfg.edges.max_gap_s);
  p.ds = downsample(raw, cfg.nodes.downsample_m, &p.travel);
  st.trace_points = traces.points.size();
  st.voxels = p.ds.points.size();
  logInfo("build-graph: " + std::to_string(raw.size()) + " trace points -> " +
          std::to_string(p.ds.points.size()) + " voxels");
  return p;
}

/// Step 1: nodes (hollow cylinder), and roundabouts, whose junctions replace the nodes there.
std::vector<Point3> junctionNodes(const Traces& traces, const PreparedTraces& p, const Config& cfg,
                                  GraphBuildResult& out, const std::string& where) {
  const double half_h = 0.5 * cfg.nodes.height_m;
  auto& st = out.stats;
  IntersectionResult ir = detectIntersections(p.ds.points, cfg.nodes, &p.ds.axes);
  st.intersection_points =
      static_cast<std::size_t>(std::count(ir.is_intersection.begin(), ir.is_intersection.end(), 1));
  out.roundabouts =
      detectRoundabouts(traces, p.order, p.travel, cfg.roundabouts, cfg.edges.max_gap_s, half_h);
  const std::vector<Roundabout>& rbs = out.roundabouts;
  st.roundabouts = rbs.size();
  if (!rbs.empty()) {
    const std::size_t replaced = mergeRoundaboutNodes(ir.nodes, rbs, cfg.roundabouts, half_h);
    std::size_t junctions = 0;
    for (const auto& rb : rbs) junctions += rb.junctions.size();
    logInfo("build-graph: " + std::to_string(rbs.size()) + " roundabout(s), " +
            std::to_string(junctions) + " ring junctions in place of " + std::to_string(replaced) +
            " node(s)");
  }
  if (ir.nodes.empty())
    throw std::runtime_error(where + ": no intersection found in the traces (no point sees >= " +
                             std::to_string(cfg.nodes.min_branches) +
                             " branches in the hollow cylinder); a road graph needs junctions");
  return std::move(ir.nodes);
}

/// Full polylines node u -> node v (intersections, and dead ends moved by a merge, are not on
/// the centreline yet), without spikes (dropSpikes, legs of two centreline steps or more).
std::vector<Polyline> streetPolylines(const std::vector<Street>& streets,
                                      const std::vector<Point3>& nodes, double step_m) {
  std::vector<Polyline> polys;
  for (const auto& s : streets) {
    Polyline pl;
    const Point3 &nu = nodes[static_cast<std::size_t>(s.u)],
                 &nv = nodes[static_cast<std::size_t>(s.v)];
    if ((nu - s.centre.front()).norm() > 0.5) pl.push_back(nu);
    pl.insert(pl.end(), s.centre.begin(), s.centre.end());
    if ((nv - s.centre.back()).norm() > 0.5) pl.push_back(nv);
    detail::dropSpikes(pl, 2.0 * step_m);
    if (pl.size() < 2) pl.push_back(pl.back());
    polys.push_back(std::move(pl));
  }
  return polys;
}

/// Per trace point, the street its voxel's street point belongs to (-1: cleared or dropped).
std::vector<int> streetOfTracePoints(const std::vector<Street>& streets,
                                     const detail::StreetPoints& spts, const Downsampled& ds) {
  std::vector<int> street_of_sp(spts.pts.size(), -1);
  for (std::size_t k = 0; k < streets.size(); ++k)
    for (int i : streets[k].members)
      street_of_sp[static_cast<std::size_t>(i)] = static_cast<int>(k);
  std::vector<int> street_of_point(ds.voxel_of.size(), -1);
  for (std::size_t i = 0; i < ds.voxel_of.size(); ++i) {
    const int k = spts.subset_of[static_cast<std::size_t>(ds.voxel_of[i])];
    if (k >= 0) street_of_point[i] = street_of_sp[static_cast<std::size_t>(k)];
  }
  return street_of_point;
}

void logGraph(const GraphBuildResult& out) {
  const auto& st = out.stats;
  if (st.unknown_direction_streets > 0)
    logWarn("build-graph: " + std::to_string(st.unknown_direction_streets) +
            " street(s) without a usable run of travel; assumed two-way");
  logInfo("build-graph: " + std::to_string(st.intersections) + " intersections, " +
          std::to_string(st.dead_ends) + " dead ends, " + std::to_string(st.streets) +
          " streets (" + std::to_string(st.one_way_streets) + " one-way), " +
          std::to_string(out.graph.edges.size()) + " directed edges");
}

}  // namespace

GraphBuildResult graphFromTraces(const Traces& traces, const Config& cfg) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string where = traces.source.empty() ? "traces" : traces.source;
  checkTraces(traces, where);
  const EdgeConfig& ec = cfg.edges;
  if (!(ec.clear_radius_m > 0 && ec.cluster_tolerance_m > 0 && ec.polyline_step_m > 0))
    throw std::invalid_argument("roadgraph.edges: radii, tolerance and step must be > 0");
  if (cfg.roundabouts.enabled) checkRoundaboutConfig(cfg.roundabouts);
  GraphBuildResult out;
  auto& st = out.stats;
  const PreparedTraces p = prepareTraces(traces, cfg, st);
  const double half_h = 0.5 * cfg.nodes.height_m;
  detail::GraphNodes gn;
  gn.pos = junctionNodes(traces, p, cfg, out, where);
  gn.n_inter = gn.pos.size();
  gn.is_end.assign(gn.pos.size(), 0);
  // Step 2: remove node neighbourhoods, cluster the rest into streets, attach them to nodes.
  const detail::StreetPoints spts =
      detail::clearNodeNeighbourhoods(p.ds.points, gn.pos, ec, half_h);
  std::vector<Street> streets =
      detail::attachStreets(spts, traces, p.order, p.ds.voxel_of, gn, ec, half_h, st);
  detail::mergeNearbyEnds(gn.pos, gn.is_end, ec.end_merge_m, half_h, streets, st);
  detail::joinStopLineEnds(gn, streets, spts, ec, half_h, st);
  detail::joinBendEnds(gn, streets, spts, ec, half_h, st);
  detail::splitAtTurningPlaces(gn, streets, spts, traces, p.order,
                               streetOfTracePoints(streets, spts, p.ds), ec, st);
  st.streets = streets.size();
  std::vector<Polyline> polys = streetPolylines(streets, gn.pos, ec.polyline_step_m);
  // Step 3: drives from junction to junction (ShortLinks.cpp): links between junctions whose
  // street the clearing removed, and directions of travel on streets too short for runs.
  const std::vector<int> street_of_point = streetOfTracePoints(streets, spts, p.ds);
  const detail::Passages passages =
      detail::junctionPassages(traces, p.order, street_of_point, gn.pos, gn.n_inter, ec, half_h);
  detail::addShortLinks(passages, gn.pos, ec, streets, polys, st);
  // Step 4: directions of travel, and the graph.
  const detail::TravelCounts runs =
      detail::countDirections(traces, p.order, street_of_point, streets, polys, passages, ec);
  assembleGraph(gn.pos, gn.is_end, streets, polys, runs, ec, out);
  // Divided roads: carriageway nodes of one place merged, the two carriageways one street.
  detail::mergeDividedRoads(out, cfg.divided, half_h);
  out.graph.validate(where);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  logGraph(out);
  return out;
}

}  // namespace slamroute::roadgraph
