#pragma once
// Parameters of the roadgraph module, with the paper's defaults and units. YAML section
// "roadgraph:". Paper §3.1 fixes only the hollow cylinder (10 m / 25 m / 10 m) and the 14 normal
// neighbours; every other value is our choice, documented where it is used.
#include <string>

namespace slamroute::roadgraph {

/// Intersection (node) detection with the hollow cylinder (paper §3.1, Fig. 2b).
struct NodeConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  double downsample_m = 2.0;     ///< voxel size trace points are thinned to first [m]
  double inner_radius_m = 10.0;  ///< hollow cylinder inner radius [m] (paper)
  double outer_radius_m = 25.0;  ///< hollow cylinder outer radius [m] (paper)
  double height_m = 10.0;        ///< hollow cylinder height, centred on the point [m] (paper)
  /// Euclidean clustering distance inside the cylinder [m]. 4 m: a two-way street's lane
  /// centres are 3.2 m apart and must form one cluster; streets further apart stay separate.
  double cluster_tolerance_m = 4.0;
  int min_cluster_points = 3;      ///< smaller clusters in the cylinder are noise [points]
  double min_branch_span_m = 4.0;  ///< a cluster must span this much radially to be a branch [m]
  double min_branch_angle_deg = 30.0;  ///< clusters seen closer in bearing are one branch [deg]
  /// Parallel clusters (axes within parallel_angle_deg) on the same side of the point whose centre
  /// lines are closer than carriageway_gap_m are the two carriageways of one divided road.
  double parallel_angle_deg = 15.0;  ///< [deg]
  double carriageway_gap_m = 15.0;   ///< [m]
  /// Radii factor of a second, larger ring tried where the paper's ring sees too few branches
  /// (big junctions whose turning traffic links the arms inside the ring); <= 1 disables it.
  double wide_scale = 1.5;
  /// ... tried only where the paper's ring has points over at least this range of bearings [deg]
  double wide_min_coverage_deg = 100.0;
  int min_branches = 3;           ///< clusters needed to call a point an intersection point
  bool require_connected = true;  ///< count only branches linked to the point inside the disk
  /// With travel directions: an arm's axis is its vehicles' mean axis when the doubled-angle
  /// mean has at least this length relative to the sum of lengths (1 = all parallel).
  double min_axis_coherence = 0.5;
  double travel_span_m = 5.0;   ///< travel direction from the trace this far behind/ahead [m]
  int vote_iterations = 2;      ///< crossing re-evaluations per intersection point's vote
  double vote_max_m = 25.0;     ///< crossings farther from the point are not accepted [m]
  double vote_radius_m = 3.0;   ///< vote density radius (seed order) [m]
  double node_radius_m = 10.0;  ///< votes within this of a seed vote form its node [m]
  /// Weaker nodes this close to a stronger one are absorbed [m]. 18 m: the carriageway crossings
  /// of two divided roads (or the corners of a big junction box) collect votes of their own
  /// 10-16 m apart; separate junctions that close become one node (bench/RESULTS.md).
  double merge_distance_m = 18.0;
  /// Candidates with fewer votes than this fraction of the median candidate's are dropped.
  double min_vote_fraction = 0.25;
  int min_node_points = 3;  ///< groups with fewer votes are discarded as noise
  /// A group with at least this many times the median group's votes is a node even when its
  /// centre sees < min_branches (big junctions whose turning traffic links the arms in both
  /// rings around the centre, while the points voting for it see them apart) [ratio]; 0 = off.
  double strong_vote_factor = 1.5;
  /// Move the node to the least-squares crossing of its arms seen from the vote median. Off: at big
  /// junctions the arms seen from one spot include links of the junction box and pull the node
  /// metres off, while the median of hundreds of votes is stable (Bologna F1 +0.017).
  bool refine_centre = false;
};
template <class V>
void visitFields(V& v, NodeConfig& c) {
  v.field("downsample_m", c.downsample_m, "voxel size trace points are thinned to [m]");
  v.field("inner_radius_m", c.inner_radius_m, "hollow cylinder inner radius [m] (paper 10)");
  v.field("outer_radius_m", c.outer_radius_m, "hollow cylinder outer radius [m] (paper 25)");
  v.field("height_m", c.height_m, "hollow cylinder height, centred on the point [m] (paper 10)");
  v.field("cluster_tolerance_m", c.cluster_tolerance_m, "clustering distance in the cylinder [m]");
  v.field("min_cluster_points", c.min_cluster_points, "smaller clusters are noise [points]");
  v.field("min_branch_span_m", c.min_branch_span_m,
          "radial extent a cluster needs to count as a branch (noise stubs do not) [m]");
  v.field("min_branch_angle_deg", c.min_branch_angle_deg,
          "clusters closer in bearing from the point are one branch (divided roads) [deg]");
  v.field("parallel_angle_deg", c.parallel_angle_deg,
          "parallel clusters (axes within this) on the same side may be one divided road [deg]");
  v.field("carriageway_gap_m", c.carriageway_gap_m,
          "parallel clusters whose centre lines are closer are one divided road [m]");
  v.field("wide_scale", c.wide_scale,
          "radii factor of a second ring tried where the paper's sees too few branches (<=1 off)");
  v.field("wide_min_coverage_deg", c.wide_min_coverage_deg,
          "second ring only where the first has points over this range of bearings [deg]");
  v.field("min_branches", c.min_branches, "clusters that make an intersection point (paper 3)");
  v.field("require_connected", c.require_connected,
          "count only branches connected to the point inside the outer disk");
  v.field("min_axis_coherence", c.min_axis_coherence,
          "arm axis from travel directions when their doubled-angle mean is this coherent (0-1)");
  v.field("travel_span_m", c.travel_span_m,
          "travel direction of a trace point from its trace this far behind/ahead [m]");
  v.field("vote_iterations", c.vote_iterations,
          "crossing re-evaluations per intersection point's centre vote");
  v.field("vote_max_m", c.vote_max_m,
          "crossings farther from the voting point are not accepted (it votes for itself) [m]");
  v.field("vote_radius_m", c.vote_radius_m, "vote density radius for the seed order [m]");
  v.field("node_radius_m", c.node_radius_m,
          "centre votes within this of a seed vote form one node (junction resolution) [m]");
  v.field("merge_distance_m", c.merge_distance_m,
          "a node this close to one with more votes is absorbed by it [m]");
  v.field("min_vote_fraction", c.min_vote_fraction,
          "nodes need this fraction of the median node's centre votes (0 = off)");
  v.field("min_node_points", c.min_node_points, "centre votes needed for a node");
  v.field("strong_vote_factor", c.strong_vote_factor,
          "groups with this many times the median group's votes are nodes even when their centre "
          "sees too few branches (0 = off) [ratio]");
  v.field("refine_centre", c.refine_centre, "node at least-squares crossing of its arms");
}

/// Street (edge) clustering and attachment (paper §3.1, eqs. 1-2, Fig. 2c-d).
struct EdgeConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  double clear_radius_m = 12.0;      ///< trace points this close to a node are removed [m]
  double cluster_tolerance_m = 4.0;  ///< Euclidean clustering distance of street points [m]
  int min_street_points = 5;         ///< smaller leftover clusters are dropped [points]
  double attach_max_m = 22.0;        ///< a street end farther than this from a node dead-ends [m]
  double end_merge_m = 20.0;         ///< dead ends this close are one node (an undriven corner) [m]
  double polyline_step_m = 5.0;      ///< centreline vertex spacing [m]
  /// Street points whose way from one end of the street to the other through them is longer
  /// than the street by more than this lie on a side branch and are left out of its centreline
  /// (StreetClusters.cpp, membersAlongStreet) [m].
  double centreline_branch_max_m = 20.0;
  double min_run_m = 8.0;             ///< travel along a street counted as a direction [m]
  double max_gap_s = 3.0;             ///< a vehicle's trace breaks at larger time gaps [s]
  int min_direction_runs = 1;         ///< runs needed to accept a direction of travel
  bool split_at_passed_nodes = true;  ///< split a street cluster at a junction it runs through
  /// A dead end whose street, continued this far, crosses another street is a T junction there
  /// (its vehicles' routes ended at the stop line, 5-8 m short of the street) [m]; 0 = off.
  double stop_line_reach_m = 15.0;
  /// A dead end this close to a bend of another street, lined up with one of its legs, is a
  /// junction there (a survey route set off on the street: BendEnds.cpp) [m]; 0 = off.
  double bend_end_reach_m = 15.0;
  /// Links between junctions too close for a street to survive the clearing (ShortLinks.cpp):
  /// A vehicle this close to a node passes its junction [m]. 12 m = clear_radius_m: the node of a
  /// big junction lies up to 10-15 m from the lanes through it, so 8 m misses links there.
  double link_visit_m = 12.0;
  double link_max_m = 30.0;   ///< nodes farther apart are never linked this way [m]
  int min_link_vehicles = 2;  ///< vehicles needed to accept a direction of a link
};
template <class V>
void visitFields(V& v, EdgeConfig& c) {
  v.field("clear_radius_m", c.clear_radius_m, "points this close to a node are removed [m]");
  v.field("cluster_tolerance_m", c.cluster_tolerance_m, "street clustering distance [m]");
  v.field("min_street_points", c.min_street_points, "smaller clusters are dropped [points]");
  v.field("attach_max_m", c.attach_max_m, "street end farther from any node is a dead end [m]");
  v.field("end_merge_m", c.end_merge_m,
          "dead ends this close together are one node: streets whose ends meet at a corner no "
          "survey vehicle drove round stay connected (0 = off) [m]");
  v.field("polyline_step_m", c.polyline_step_m, "centreline vertex spacing [m]");
  v.field("centreline_branch_max_m", c.centreline_branch_max_m,
          "street points whose way from one end to the other through them is longer than the "
          "street by more than this (a side branch) are left out of the centreline [m]");
  v.field("min_run_m", c.min_run_m, "travel along a street counted as a direction [m]");
  v.field("max_gap_s", c.max_gap_s, "a vehicle's trace breaks at larger time gaps [s]");
  v.field("min_direction_runs", c.min_direction_runs, "runs needed to accept a direction");
  v.field("split_at_passed_nodes", c.split_at_passed_nodes,
          "a street cluster reaching >= 3 nodes that runs past one of them (branch point within "
          "clear_radius_m of it) is split into one street per branch ending there");
  v.field("stop_line_reach_m", c.stop_line_reach_m,
          "a dead end whose street, continued this far, crosses another street's middle is a T "
          "junction on it (routes that end at the stop line) (0 = off) [m]");
  v.field("bend_end_reach_m", c.bend_end_reach_m,
          "a dead end this close to another street's bend, its street lined up with one leg of "
          "the bend, is a junction at the bend (routes that set off there) (0 = off) [m]");
  v.field("link_visit_m", c.link_visit_m,
          "a vehicle this close to a node passes its junction (short links) [m]");
  v.field("link_max_m", c.link_max_m,
          "junctions at most this far apart are linked when vehicles drive from one straight to "
          "the other without a street point in between (0 = off) [m]");
  v.field("min_link_vehicles", c.min_link_vehicles, "vehicles needed per direction of a link");
}

/// Divided roads (DividedRoads.cpp): the nodes on the two carriageways of a divided road where a
/// street crosses it are one node, and the two carriageways one street with two directions.
struct DividedRoadConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  bool enabled = true;
  /// Carriageway nodes at most this far apart can be one place [m]. 32 m: carriageways are
  /// 10-25 m apart and their nodes stand up to ~3 m outside them (the votes of the crossing
  /// street pull them out).
  double max_node_gap_m = 32.0;
  double min_offset_m = 4.0;         ///< the partner lies at least this far beside the arm [m]
  double max_along_m = 15.0;         ///< ... and at most this far ahead of / behind the node [m]
  double arm_length_m = 25.0;        ///< an arm's direction from the node to this far along [m]
  double parallel_angle_deg = 20.0;  ///< the two carriageways' arms are parallel within [deg]
  /// Staggered junctions (StaggeredJunctions.cpp): two T junctions joined by a street of at most
  /// this length whose side streets leave on opposite sides of it are one place (0 = off) [m].
  /// Off by default: each such merge is one SUMO junction less at junction level (Braunschweig's
  /// node F1 0.905 -> 0.878, below the held-out test's 0.9), while at place level it is one
  /// true place (bench/RESULTS.md "Divided roads"). 40 m: the pairs on Berlin-Adlershof stand
  /// 31-36 m apart.
  double stagger_max_gap_m = 0.0;
  double stagger_straight_deg = 30.0;  ///< the through street bends less than this [deg]
  /// Also a T and the T whose side arm it stands on (the street jogs across a crossing street).
  bool stagger_jogs = false;
};
template <class V>
void visitFields(V& v, DividedRoadConfig& c) {
  v.field("enabled", c.enabled, "merge the carriageway nodes of divided roads into one place");
  v.field("max_node_gap_m", c.max_node_gap_m,
          "carriageway nodes at most this far apart can be one place [m]");
  v.field("min_offset_m", c.min_offset_m, "the partner lies at least this far beside the arm [m]");
  v.field("max_along_m", c.max_along_m, "... and at most this far along the arm [m]");
  v.field("arm_length_m", c.arm_length_m, "arm direction from the node to this far along [m]");
  v.field("parallel_angle_deg", c.parallel_angle_deg,
          "the two carriageways' arms are parallel within this [deg]");
  v.field("stagger_max_gap_m", c.stagger_max_gap_m,
          "two T junctions at most this far apart with side streets on opposite sides of the "
          "street joining them are one place (0 = off) [m]");
  v.field("stagger_straight_deg", c.stagger_straight_deg,
          "... the street through them bends less than this at each [deg]");
  v.field("stagger_jogs", c.stagger_jogs,
          "also merge a T with the T whose side arm it stands on (a street jogging across "
          "another)");
}

/// Edge weights from depth images (paper §3.1, eqs. 3-4).
struct DepthConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  int pixel_stride = 4;   ///< use every n-th pixel in x and y [px]
  int normal_neighbours = 14;      ///< nearest neighbours per normal (paper 14)
  int search_window_px = 2;        ///< neighbour candidates within this many strided pixels
  double depth_px_per_m = 40.0;    ///< eq. 3 scale: Y = D * this, so depth and pixels compare
  double max_depth_m = 100.0;      ///< farther returns are ignored [m]
  int min_normals = 50;            ///< fewer normals -> score 0 (nothing to match against)
  double frame_max_dist_m = 20.0;  ///< frames farther from every street are ignored [m]
  double fallback_weight = 1.0;    ///< weight when no depth frame is usable at all
};
template <class V>
void visitFields(V& v, DepthConfig& c) {
  v.field("pixel_stride", c.pixel_stride, "use every n-th pixel in x and y [px]");
  v.field("normal_neighbours", c.normal_neighbours, "neighbours per normal (paper 14)");
  v.field("search_window_px", c.search_window_px, "neighbour candidate window [strided px]");
  v.field("depth_px_per_m", c.depth_px_per_m, "eq. 3 depth scale: Y = D[m] * this [px/m]");
  v.field("max_depth_m", c.max_depth_m, "farther returns are ignored [m]");
  v.field("min_normals", c.min_normals, "fewer normals give score 0");
  v.field("frame_max_dist_m", c.frame_max_dist_m, "frames farther from every street ignored [m]");
  v.field("fallback_weight", c.fallback_weight, "edge weight when no depth frame is usable");
}

/// Comparison with a SUMO net and mapping of graph edges to SUMO edges.
struct SumoMatchConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  double match_radius_m = 15.0;      ///< detected node matches a true intersection this close [m]
  double sample_step_m = 4.0;        ///< polyline sampling for the SUMO edge mapping [m]
  double max_lane_dist_m = 12.0;     ///< samples farther from every lane are not mapped [m]
  double end_skip_m = 8.0;           ///< samples this close to an end node are skipped [m]
  double stray_radius_m = 25.0;      ///< end edge arriving at u / leaving v this close: stray [m]
  double stray_min_length_m = 20.0;  ///< shorter end edges (junction complexes) are kept [m]
  /// End edges shorter than this are connectors between two junctions a fraction of a metre
  /// apart (OSM nets: Bologna's 203[1]b, 0.2 m) and are dropped from chain ends [m].
  double connector_max_m = 1.0;
  /// Chain end edges matched by at most this many samples that SUMO joins to the chain only
  /// through other edges are lanes of another arm beside the node, and are dropped.
  int bridged_end_max_samples = 2;
  bool turns_from_net = true;       ///< turn permissions of the graph from the net's connections
  double turn_max_detour_m = 60.0;  ///< SUMO edges allowed between two graph edges at a turn [m]
  /// Place-level validation: intersections joined by a street whose ends lie this close are one
  /// place, the net's junctions and the graph's nodes alike [m]. 38 m: the junctions that SUMO
  /// joins by an edge of at most 25 m between their shapes lie 10-37 m apart (centre to centre)
  /// on Berlin-Adlershof and Braunschweig.
  double place_link_max_m = 38.0;
};
template <class V>
void visitFields(V& v, SumoMatchConfig& c) {
  v.field("match_radius_m", c.match_radius_m, "node matches a true intersection this close [m]");
  v.field("sample_step_m", c.sample_step_m, "polyline sampling for SUMO edge mapping [m]");
  v.field("max_lane_dist_m", c.max_lane_dist_m, "samples farther from every lane unmapped [m]");
  v.field("end_skip_m", c.end_skip_m, "samples this close to end nodes are skipped [m]");
  v.field("stray_radius_m", c.stray_radius_m,
          "chain end edge arriving at the start / leaving the end node this close is dropped [m]");
  v.field("stray_min_length_m", c.stray_min_length_m, "shorter chain end edges are kept [m]");
  v.field("connector_max_m", c.connector_max_m,
          "chain end edges shorter than this (connectors between junctions) are dropped [m]");
  v.field("bridged_end_max_samples", c.bridged_end_max_samples,
          "chain end edges with at most this many samples, joined to the chain only through "
          "other edges, are dropped");
  v.field("turns_from_net", c.turns_from_net,
          "turn permissions of the graph from the net (no U-turn where SUMO has none)");
  v.field("turn_max_detour_m", c.turn_max_detour_m,
          "SUMO edges allowed between two graph edges at a turn [m]");
  v.field("place_link_max_m", c.place_link_max_m,
          "place-level validation: intersections (net and graph alike) joined by a street whose "
          "ends lie this close are one place (divided roads, junction boxes) [m]");
}

/// Roundabouts (Roundabouts.cpp): rings that vehicles circle round an empty middle.
struct RoundaboutConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  bool enabled = true;
  double min_radius_m = 6.0;   ///< smallest ring radius (centre to circulating lane) [m]
  double max_radius_m = 30.0;  ///< largest ring radius [m]
  double resample_m = 2.0;     ///< each path is averaged over this much travel before fitting [m]
  /// A vehicle circles the ring when a stretch of its path fits a circle (rms below
  /// max_fit_rms_m) and turns monotonically about it by at least min_sweep_deg. 120 deg: a turn
  /// at a crossing sweeps about 90 deg; a roundabout's through movement 150-200 deg.
  double min_sweep_deg = 120.0;     ///< [deg]
  double max_fit_rms_m = 0.8;       ///< [m]
  double centre_tolerance_m = 6.0;  ///< circle fits with centres this close are one ring [m]
  int min_vehicles = 3;             ///< distinct vehicles that must circle a ring
  /// Trace points this close to the radius are on the ring [m]. 3.5 m: a two-lane ring (Bologna)
  /// puts its lanes 1.6 m either side of the fitted radius, plus GPS noise; with 2.5 m vehicles
  /// changing lanes left the band and seemed to leave the ring.
  double ring_width_m = 3.5;
  /// Share of the ring's 36 sectors holding >= 3 points that move along the ring (a bend or two
  /// junctions' turning arcs cover part of a circle only).
  double min_occupied = 0.9;
  double min_sense_share = 0.9;   ///< share of the points along the ring circling in its sense
  double max_inner_share = 0.02;  ///< points within half the radius / points on the ring
  /// A vehicle joins (leaves) the ring where it first (last) comes this close to the radius [m].
  /// 1 m: Ingolstadt's split arms then join and leave 7.8 m apart along the ring (5 m with 2.5 m).
  double join_width_m = 1.0;
  double min_run_sweep_deg = 20.0;  ///< a stay on the ring counts when it turns this far [deg]
  double arm_gap_m = 4.0;         ///< joins (or leaves) farther apart along the ring: separate [m]
  int min_arm_vehicles = 2;       ///< stays that must join (leave) where a junction is
  double junction_merge_m = 5.0;  ///< a join and a leave this close along the ring: one [m]
  /// Hollow-cylinder nodes within radius + this of the centre are replaced [m]. 14 m: the
  /// carriageways of a divided arm part 25-30 m from the centre of a 36 m ring; their fork is no
  /// junction of the net.
  double absorb_margin_m = 14.0;
};
template <class V>
void visitFields(V& v, RoundaboutConfig& c) {
  v.field("enabled", c.enabled, "detect roundabouts (rings vehicles circle) as their junctions");
  v.field("min_radius_m", c.min_radius_m, "smallest ring radius [m]");
  v.field("max_radius_m", c.max_radius_m, "largest ring radius [m]");
  v.field("resample_m", c.resample_m, "paths averaged over this much travel before fitting [m]");
  v.field("min_sweep_deg", c.min_sweep_deg,
          "a vehicle circles a ring when its path turns this far on one fitted circle [deg]");
  v.field("max_fit_rms_m", c.max_fit_rms_m, "circle fit residual limit [m]");
  v.field("centre_tolerance_m", c.centre_tolerance_m, "circle centres this close: one ring [m]");
  v.field("min_vehicles", c.min_vehicles, "distinct vehicles that must circle a ring");
  v.field("ring_width_m", c.ring_width_m, "points this close to the radius are on the ring [m]");
  v.field("min_occupied", c.min_occupied,
          "share of the ring's 36 sectors with points moving along it (0-1)");
  v.field("min_sense_share", c.min_sense_share,
          "share of points along the ring circling in its sense (0-1)");
  v.field("max_inner_share", c.max_inner_share,
          "points inside half the radius relative to points on the ring (an empty middle)");
  v.field(
      "join_width_m", c.join_width_m,
      "a vehicle joins (leaves) the ring where it first (last) comes this close to the radius [m]");
  v.field("min_run_sweep_deg", c.min_run_sweep_deg, "a stay on the ring turns this far [deg]");
  v.field("arm_gap_m", c.arm_gap_m, "joins (leaves) farther apart along the ring: separate [m]");
  v.field("min_arm_vehicles", c.min_arm_vehicles, "stays that must join (leave) at a junction");
  v.field("junction_merge_m", c.junction_merge_m,
          "a join and a leave this close along the ring are one junction [m]");
  v.field("absorb_margin_m", c.absorb_margin_m,
          "hollow-cylinder nodes within radius + this of the centre are replaced [m]");
}

struct Config {
  NodeConfig nodes;
  RoundaboutConfig roundabouts;
  EdgeConfig edges;
  DividedRoadConfig divided;
  DepthConfig depth;
  SumoMatchConfig sumo;
};

template <class V>
void visitFields(V& v, Config& c) {
  v.section("nodes", c.nodes);
  v.section("roundabouts", c.roundabouts);
  v.section("edges", c.edges);
  v.section("divided", c.divided);
  v.section("depth", c.depth);
  v.section("sumo", c.sumo);
}

}  // namespace slamroute::roadgraph
