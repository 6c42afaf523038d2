// Paper §3.1: traces -> road graph. The steps, each in its own file:
// 1. Nodes: hollow-cylinder intersection points merged into junctions (Intersections.cpp); at
//    roundabouts, which the cylinder cannot see, the ring's junctions instead (Roundabouts.cpp).
// 2. Streets: the trace points left after removing the nodes' neighbourhoods, clustered, each
//    cluster attached to its two nearest nodes, eqs. 1-2 (StreetClusters.cpp), with its centreline
//    (Centreline.cpp); dead ends that nearly touch are one node (EndNodes.cpp).
// 3. Links between junctions too close for a street to survive the clearing, from vehicles that
//    drive from one straight into the other (ShortLinks.cpp).
// 4. Direction(s) of travel from each vehicle's runs along a street (StreetDirections.cpp): a
//    street with runs in one direction only is one-way (one directed edge); with both, or with no
//    usable run (then logged), it is two-way (two RoadEdges sharing `street`).
#include "slamroute/roadgraph/GraphBuilder.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

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

}  // namespace

GraphBuildResult buildRoadGraph(const Traces& traces, const Config& cfg) {
  const auto t0 = std::chrono::steady_clock::now();
  checkTraces(traces, traces.source.empty() ? "traces" : traces.source);
  const std::string where = traces.source.empty() ? "traces" : traces.source;
  const EdgeConfig& ec = cfg.edges;
  if (!(ec.clear_radius_m > 0 && ec.cluster_tolerance_m > 0 && ec.polyline_step_m > 0))
    throw std::invalid_argument("roadgraph.edges: radii, tolerance and step must be > 0");
  if (cfg.roundabouts.enabled) checkRoundaboutConfig(cfg.roundabouts);
  GraphBuildResult out;
  auto& st = out.stats;
  st.trace_points = traces.points.size();

  std::vector<Point3> raw;
  raw.reserve(traces.points.size());
  for (const auto& p : traces.points) raw.push_back(p.pos);
  const std::vector<std::size_t> order = byVehicleThenTime(traces);
  const std::vector<Vec3> travel =
      travelDirections(traces, order, cfg.nodes.travel_span_m, cfg.edges.max_gap_s);
  const Downsampled ds = downsample(raw, cfg.nodes.downsample_m, &travel);
  st.voxels = ds.points.size();
  logInfo("build-graph: " + std::to_string(raw.size()) + " trace points -> " +
          std::to_string(ds.points.size()) + " voxels");

  const double half_h = 0.5 * cfg.nodes.height_m;

  // Step 1: nodes (hollow cylinder), and roundabouts, whose junctions replace the nodes there.
  IntersectionResult ir = detectIntersections(ds.points, cfg.nodes, &ds.axes);
  st.intersection_points =
      static_cast<std::size_t>(std::count(ir.is_intersection.begin(), ir.is_intersection.end(), 1));
  out.roundabouts = detectRoundabouts(traces, order, travel, cfg.roundabouts, ec.max_gap_s, half_h);
  const std::vector<Roundabout>& rbs = out.roundabouts;
  st.roundabouts = rbs.size();
  if (!rbs.empty()) {
    const std::size_t replaced = mergeRoundaboutNodes(ir.nodes, rbs, cfg.roundabouts, half_h);
    std::size_t junctions = 0;
    for (const auto& rb : rbs) junctions += rb.junctions.size();
    logInfo("build-graph: " + std::to_string(rbs.size()) + " roundabout(s), " +
            std::to_string(junctions) + " ring junctions in place of " +
            std::to_string(replaced) + " node(s)");
  }
  if (ir.nodes.empty())
    throw std::runtime_error(where + ": no intersection found in the traces (no point sees >= " +
                             std::to_string(cfg.nodes.min_branches) +
                             " branches in the hollow cylinder); a road graph needs junctions");
  detail::GraphNodes gn;
  gn.pos = ir.nodes;
  gn.n_inter = gn.pos.size();
  gn.is_end.assign(gn.pos.size(), 0);
  const std::size_t n_inter = gn.n_inter;

  // Step 2: remove node neighbourhoods, cluster the rest into streets, attach them to nodes.
  const detail::StreetPoints spts = detail::clearNodeNeighbourhoods(ds.points, gn.pos, ec, half_h);
  std::vector<Street> streets =
      detail::attachStreets(spts, traces, order, ds.voxel_of, gn, ec, half_h, st);
  std::vector<Point3>& nodes = gn.pos;
  const std::vector<char>& is_end = gn.is_end;
  detail::mergeNearbyEnds(nodes, is_end, ec.end_merge_m, half_h, streets, st);
  st.streets = streets.size();
  const std::vector<int>& subset_of = spts.subset_of;
  std::vector<int> street_of_sp(spts.pts.size(), -1);
  for (std::size_t k = 0; k < streets.size(); ++k)
    for (int i : streets[k].members)
      street_of_sp[static_cast<std::size_t>(i)] = static_cast<int>(k);

  // Full polylines node u -> node v.
  std::vector<Polyline> polys;
  for (const auto& s : streets) {
    Polyline pl;
    // Intersections, and dead ends moved by a merge, are not on the centreline yet.
    const Point3 &nu = nodes[static_cast<std::size_t>(s.u)],
                 &nv = nodes[static_cast<std::size_t>(s.v)];
    if ((nu - s.centre.front()).norm() > 0.5) pl.push_back(nu);
    pl.insert(pl.end(), s.centre.begin(), s.centre.end());
    if ((nv - s.centre.back()).norm() > 0.5) pl.push_back(nv);
    if (pl.size() < 2) pl.push_back(pl.back());
    polys.push_back(std::move(pl));
  }

  // Step 3: links between close junctions; the trace points on each street.
  std::vector<int> street_of_point(traces.points.size(), -1);
  for (std::size_t i = 0; i < traces.points.size(); ++i) {
    const int k = subset_of[static_cast<std::size_t>(ds.voxel_of[i])];
    if (k >= 0) street_of_point[i] = street_of_sp[static_cast<std::size_t>(k)];
  }
  // Drives from junction to junction (ShortLinks.cpp): links between junctions whose street the
  // clearing removed, and directions of travel on streets too short for runs to show them.
  const detail::Passages passages =
      detail::junctionPassages(traces, order, street_of_point, nodes, n_inter, ec, half_h);
  detail::addShortLinks(passages, nodes, ec, streets, polys, st);
  // Step 4: directions of travel, and the graph.
  const detail::TravelCounts runs =
      detail::countDirections(traces, order, street_of_point, streets, polys, passages, ec);
  assembleGraph(nodes, is_end, streets, polys, runs, ec, out);
  if (st.unknown_direction_streets > 0)
    logWarn("build-graph: " + std::to_string(st.unknown_direction_streets) +
            " street(s) without a usable run of travel; assumed two-way");
  RoadGraph& g = out.graph;
  g.validate(where);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  logInfo("build-graph: " + std::to_string(st.intersections) + " intersections, " +
          std::to_string(st.dead_ends) + " dead ends, " + std::to_string(st.streets) +
          " streets (" + std::to_string(st.one_way_streets) + " one-way), " +
          std::to_string(g.edges.size()) + " directed edges");
  return out;
}

}  // namespace slamroute::roadgraph
