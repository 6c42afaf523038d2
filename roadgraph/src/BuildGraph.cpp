// `slamroute build-graph` pipeline: traces -> graph (§3.1 steps 1-3) -> depth weights (step 4)
// -> optional SUMO validation and SUMO edge mapping -> graph.json and siblings.
#include "slamroute/roadgraph/BuildGraph.hpp"

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "StreetsThroughBends.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute::roadgraph {

BuildInputs surveyInputs(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw std::runtime_error(dir.string() + ": survey folder not found");
  BuildInputs in;
  for (const char* name : {"traces.csv", "fcd.xml", "fcd.xml.gz"})
    if (fs::exists(dir / name)) {
      in.traces = dir / name;
      break;
    }
  if (in.traces.empty())
    throw std::runtime_error(dir.string() + ": survey folder has no traces.csv (or fcd.xml)");
  if (fs::exists(dir / "depth" / "index.csv")) in.depth_index = dir / "depth" / "index.csv";
  return in;
}

namespace {

/// Paper §3.1 step 4: edge weights from the depth frames, or the fallback weight without them.
WeightStats weighEdges(RoadGraph& g, const std::filesystem::path& depth_index,
                       const DepthConfig& cfg) {
  if (depth_index.empty()) {
    logWarn("depth: no depth/index.csv; every edge gets the fallback weight " +
            std::to_string(cfg.fallback_weight));
    for (auto& e : g.edges) e.weight = cfg.fallback_weight;
    WeightStats w;
    w.fallback_weight = cfg.fallback_weight;
    return w;
  }
  std::vector<DepthFrame> frames;
  try {
    frames = readDepthIndex(depth_index);
  } catch (const std::exception& e) {
    logWarn(std::string("depth: ") + e.what() + "; every edge gets the fallback weight");
  }
  return assignDepthWeights(g, frames, cfg);
}

/// What matching the graph onto a SUMO net found (BuildOutput::validation holds the rest).
struct NetMatch {
  std::size_t unmapped = 0;
  std::optional<TurnStats> turns;
};

/// Validation against the net (streets joined through turning places, as the net's chains run),
/// SUMO junction per node, SUMO edges per graph edge, turns.
NetMatch matchToNet(BuildOutput& out, const std::filesystem::path& net_path,
                    const SumoMatchConfig& cfg) {
  RoadGraph& g = out.built.graph;
  const SumoNet net = SumoNet::read(net_path);
  const RoadGraph scored = detail::streetsThroughBends(g, out.built.node_is_end);
  out.validation = validateAgainstNet(scored, out.built.node_is_end, net, cfg);
  out.place_validation = validateAgainstPlaces(scored, out.built.node_is_end, net, cfg);
  for (std::size_t n = 0; n < g.nodes.size(); ++n)
    g.nodes[n].sumo_junction = out.validation->node_junction[n];
  NetMatch m;
  m.unmapped = mapSumoEdges(g, net, cfg);
  if (m.unmapped > 0)
    logWarn("build-graph: " + std::to_string(m.unmapped) + " edge(s) not mapped to SUMO edges");
  if (cfg.turns_from_net) {
    m.turns = turnsFromNet(g, net, cfg);
    logInfo("build-graph: turns from the net: " + std::to_string(m.turns->forbidden_turns) +
            " of " + std::to_string(m.turns->candidate_turns) +
            " turns at the graph's nodes are not allowed in SUMO");
  }
  return m;
}

nlohmann::json statsJson(const GraphBuildStats& st) {
  return {{"trace_points", st.trace_points},
          {"voxels", st.voxels},
          {"intersection_points", st.intersection_points},
          {"intersections", st.intersections},
          {"dead_ends", st.dead_ends},
          {"streets", st.streets},
          {"one_way_streets", st.one_way_streets},
          {"unknown_direction_streets", st.unknown_direction_streets},
          {"merged_end_pairs", st.merged_end_pairs},
          {"short_links", st.short_links},
          {"stop_line_junctions", st.stop_line_junctions},
          {"bend_end_junctions", st.bend_end_junctions},
          {"passed_nodes", st.passed_nodes},
          {"u_turn_streets", st.u_turn_streets},
          {"roundabouts", st.roundabouts},
          {"divided_node_pairs", st.divided_node_pairs},
          {"divided_streets", st.divided_streets},
          {"staggered_node_pairs", st.staggered_node_pairs},
          {"turning_places", st.turning_places},
          {"dropped_fragments", st.dropped_fragments},
          {"seconds", st.seconds}};
}

nlohmann::json weightsJson(const WeightStats& w, const std::filesystem::path& depth_index) {
  return {{"depth_index", depth_index.string()},
          {"frames", w.frames},
          {"scored", w.scored},
          {"failed", w.failed},
          {"unassigned", w.unassigned},
          {"streets_with_frames", w.streets_with_frames},
          {"mean_score", w.mean_score},
          {"score", "normalised entropy of the eigenvalues of the normals' scatter matrix"}};
}

nlohmann::json roundaboutsJson(const std::vector<Roundabout>& roundabouts) {
  nlohmann::json rbs = nlohmann::json::array();
  for (const auto& rb : roundabouts) {
    nlohmann::json junctions = nlohmann::json::array();
    for (const auto& j : rb.junctions) junctions.push_back({j.x(), j.y(), j.z()});
    rbs.push_back({{"centre", {rb.centre.x(), rb.centre.y(), rb.centre.z()}},
                   {"radius_m", rb.radius_m},
                   {"sense", rb.sense > 0 ? "counter-clockwise" : "clockwise"},
                   {"vehicles", rb.vehicles},
                   {"junctions", junctions}});
  }
  return rbs;
}

std::string graphMetadata(const BuildInputs& in, const BuildOutput& out,
                          const std::optional<NetMatch>& net) {
  nlohmann::json meta = {{"generator", "slamroute build-graph (paper 3.1)"},
                         {"traces", in.traces.string()},
                         {"stats", statsJson(out.built.stats)},
                         {"weights", weightsJson(out.weights, in.depth_index)}};
  std::vector<int> ends, turning;
  for (std::size_t n = 0; n < out.built.node_is_end.size(); ++n) {
    if (out.built.node_is_end[n] != kIntersection) ends.push_back(static_cast<int>(n));
    if (out.built.node_is_end[n] == kTurningPlace) turning.push_back(static_cast<int>(n));
  }
  meta["end_nodes"] = ends;  // every node that is not an intersection
  meta["turning_places"] = turning;
  meta["roundabouts"] = roundaboutsJson(out.built.roundabouts);
  if (out.validation && net) {
    const auto& turns = net->turns;
    meta["net"] = in.net.string();
    meta["validation"] = nlohmann::json::parse(out.validation->toJson());
    meta["place_validation"] = nlohmann::json::parse(out.place_validation->toJson());
    meta["sumo_mapping"] = {{"unmapped_edges", net->unmapped},
                            {"turns_from_net", turns.has_value()},
                            {"candidate_turns", turns ? turns->candidate_turns : 0},
                            {"forbidden_turns", turns ? turns->forbidden_turns : 0}};
  }
  return meta.dump();
}

}  // namespace

BuildOutput buildGraphFromInputs(const BuildInputs& in, const Config& cfg) {
  BuildOutput out;
  out.built = graphFromTraces(readTraces(in.traces), cfg);
  out.weights = weighEdges(out.built.graph, in.depth_index, cfg.depth);
  std::optional<NetMatch> net;
  if (!in.net.empty()) net = matchToNet(out, in.net, cfg.sumo);
  out.built.graph.metadata_json = graphMetadata(in, out, net);
  return out;
}

std::vector<std::filesystem::path> graphOutputPaths(const std::filesystem::path& json_path) {
  std::vector<std::filesystem::path> out = {json_path};
  for (const char* ext : {".geojson", ".graphml", ".png"}) {
    auto p = json_path;
    out.push_back(p.replace_extension(ext));
  }
  return out;
}

void checkOutputsAreNotInputs(const BuildInputs& in, const std::filesystem::path& json_path) {
  namespace fs = std::filesystem;
  for (const fs::path& input : {in.traces, in.depth_index, in.net}) {
    if (input.empty()) continue;
    std::error_code ec;
    const fs::path a = fs::weakly_canonical(input, ec);
    for (const fs::path& output : graphOutputPaths(json_path))
      if (a == fs::weakly_canonical(output, ec))
        throw std::invalid_argument(output.string() + ": is an input of build-graph (" +
                                    input.string() + "); choose another --out");
  }
}

void writeGraphOutputs(const RoadGraph& graph, const std::filesystem::path& json_path) {
  const auto paths = graphOutputPaths(json_path);
  AtomicFileSet files;
  graph.writeJson(files.staged(paths[0]));
  graph.writeGeoJson(files.staged(paths[1]));
  graph.writeGraphML(files.staged(paths[2]));
  graph.renderPng(files.staged(paths[3]), "weight");
  files.commit();
}

}  // namespace slamroute::roadgraph
