// `slamroute build-graph --survey DIR --out GRAPH.json [--net NET]` (paper §3.1): road graph from
// location traces, edge weights from depth images; with --net also scores the graph against the
// net's true intersections and maps every graph edge to the SUMO edges it covers.
#include <iomanip>
#include <iostream>

#include "Commands.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/roadgraph/BuildGraph.hpp"

namespace slamroute::cli {

void registerBuildGraph(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string survey, traces, depth, out, net;
    bool no_depth = false;
  };
  auto o = std::make_shared<Opts>();
  auto* sub = app.add_subcommand("build-graph", "Build the road graph from a survey (paper 3.1)");
  auto* s =
      sub->add_option("--survey", o->survey,
                      "survey folder (traces.csv + depth/index.csv, from `slamroute survey`)");
  auto* t = sub->add_option("--traces", o->traces, "bare traces.csv or SUMO FCD XML instead");
  s->excludes(t);
  sub->add_option("--depth", o->depth, "depth/index.csv (overrides the survey's)");
  sub->add_flag("--no-depth", o->no_depth, "skip depth weights (every edge gets the fallback)");
  sub->add_option("--out", o->out, "output GRAPH.json (+ .geojson, .graphml, .png)")->required();
  sub->add_option("--net", o->net, "SUMO net: validate nodes/edges and map edges to SUMO edges");
  sub->callback([&ctx, o] {
    ctx.load();
    if (o->survey.empty() && o->traces.empty())
      throw std::invalid_argument("build-graph: give --survey DIR or --traces FILE");
    roadgraph::BuildInputs in;
    if (!o->survey.empty()) {
      in = roadgraph::surveyInputs(o->survey);
    } else {
      in.traces = o->traces;
    }
    if (!o->depth.empty()) in.depth_index = o->depth;
    if (o->no_depth) in.depth_index.clear();
    in.net = o->net;
    roadgraph::checkOutputsAreNotInputs(in, o->out);
    const auto res = roadgraph::buildGraphFromInputs(in, ctx.cfg.roadgraph);
    roadgraph::writeGraphOutputs(res.built.graph, o->out);
    const auto& st = res.built.stats;
    std::cout << "graph:          " << o->out << "\n"
              << "nodes:          " << res.built.graph.nodes.size() << " (" << st.intersections
              << " intersections, " << st.dead_ends << " dead ends, " << st.turning_places
              << " turning places)\n"
              << "streets:        " << st.streets << " (" << st.one_way_streets << " one-way), "
              << res.built.graph.edges.size() << " directed edges\n"
              << "depth frames:   " << res.weights.scored << " scored, " << res.weights.failed
              << " skipped, mean score " << std::fixed << std::setprecision(3)
              << res.weights.mean_score << "\n";
    if (res.validation) {
      const auto& v = *res.validation;
      std::cout << std::setprecision(3) << "node precision: " << v.node_precision << " ("
                << v.matched_nodes << "/" << v.detected_nodes << ")\n"
                << "node recall:    " << v.node_recall << " (" << v.matched_nodes << "/"
                << v.true_intersections << ")\n"
                << "node F1:        " << v.node_f1 << "\n"
                << "edge precision: " << v.edge_precision << " (" << v.matched_streets << "/"
                << v.detected_streets << ")\n"
                << "edge recall:    " << v.edge_recall << " (" << v.found_chains << "/"
                << v.true_chains << ")\n";
    }
    if (res.place_validation) {
      const auto& v = *res.place_validation;
      std::cout << "places (divided roads as one street): node F1 " << v.node_f1 << " ("
                << v.matched_nodes << " of " << v.detected_nodes << " nodes, "
                << v.true_intersections << " places), edge precision " << v.edge_precision
                << ", recall " << v.edge_recall << "\n";
    }
  });
}

}  // namespace slamroute::cli
