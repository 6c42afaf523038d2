#pragma once
// Top level of `slamroute build-graph`: survey folder (or bare traces) -> graph.json + siblings.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/roadgraph/DepthScore.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {

struct BuildInputs {
  std::filesystem::path traces;       ///< traces.csv or SUMO FCD XML
  std::filesystem::path depth_index;  ///< depth/index.csv; empty = no depth weights
  std::filesystem::path net;          ///< SUMO net for validation + SUMO edge mapping; optional
};
/// DIR/traces.csv (or DIR/fcd.xml) and DIR/depth/index.csv when present. Throws naming DIR.
BuildInputs surveyInputs(const std::filesystem::path& dir);

struct BuildOutput {
  GraphBuildResult built;  ///< built.graph carries weights, sumo_edges and metadata_json
  WeightStats weights;
  std::optional<ValidationResult> validation;
  std::optional<ValidationResult> place_validation;  ///< divided roads as one street
};
/// Reads the inputs, builds the road graph from the traces (graphFromTraces), weights its edges
/// from the depth frames, validates it against the net and maps it onto the net's edges (when
/// given), and records all of it in the graph's metadata.
BuildOutput buildGraphFromInputs(const BuildInputs& in, const Config& cfg);

/// GRAPH.json, GRAPH.geojson, GRAPH.graphml and GRAPH.png: the files writeGraphOutputs replaces.
std::vector<std::filesystem::path> graphOutputPaths(const std::filesystem::path& json_path);
/// Throws std::invalid_argument naming the file when an output path is one of the inputs.
void checkOutputsAreNotInputs(const BuildInputs& in, const std::filesystem::path& json_path);

/// GRAPH.json plus GRAPH.geojson, GRAPH.graphml and GRAPH.png (coloured by weight), replaced
/// together (AtomicFileSet): a failure while writing keeps the previous four whole.
void writeGraphOutputs(const RoadGraph& graph, const std::filesystem::path& json_path);

}  // namespace slamroute::roadgraph
