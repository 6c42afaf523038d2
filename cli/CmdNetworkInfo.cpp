// `slamroute network-info NET [--json]`: what a SUMO net holds for passenger cars.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "Commands.hpp"
#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute::cli {

void registerNetworkInfo(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string net, geojson, graphml, png;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* sub =
      app.add_subcommand("network-info", "Read a SUMO net and summarise its drivable graph");
  sub->add_option("net", o->net, "SUMO network (.net.xml or .net.xml.gz)")->required();
  sub->add_flag("--json", o->json, "print JSON instead of text");
  sub->add_option("--geojson", o->geojson, "also export the drivable graph as GeoJSON");
  sub->add_option("--graphml", o->graphml, "also export the drivable graph as GraphML");
  sub->add_option("--png", o->png, "also render the drivable graph to PNG (coloured by length)");
  sub->callback([&ctx, o] {
    ctx.load();
    const SumoNet net = SumoNet::read(o->net);
    const NetworkInfo info = networkInfo(net);
    if (o->json) {
      nlohmann::json j = {{"net", o->net},
                          {"junctions", info.junctions},
                          {"passenger_edges", info.passenger_edges},
                          {"lscc_junctions", info.lscc_junctions},
                          {"lscc_edges", info.lscc_edges},
                          {"total_length_m", info.total_length_m},
                          {"lscc_length_m", info.lscc_length_m}};
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << "net:                     " << o->net << "\n"
                << "junctions:               " << info.junctions << "\n"
                << "passenger edges:         " << info.passenger_edges << "\n"
                << "largest strongly connected part: " << info.lscc_junctions << " junctions / "
                << info.lscc_edges << " edges\n"
                << std::fixed << std::setprecision(1)
                << "total passenger length:  " << info.total_length_m / 1000.0 << " km ("
                << info.lscc_length_m / 1000.0 << " km in the largest part)\n";
    }
    if (!o->geojson.empty() || !o->graphml.empty() || !o->png.empty()) {
      const RoadGraph g = RoadGraph::fromSumoNet(net, /*lscc_only=*/false);
      if (!o->geojson.empty()) g.writeGeoJson(o->geojson);
      if (!o->graphml.empty()) g.writeGraphML(o->graphml);
      if (!o->png.empty()) g.renderPng(o->png, "length");
    }
  });
}

}  // namespace slamroute::cli
