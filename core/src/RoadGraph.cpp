// RoadGraph model: construction from a SUMO net, queries, and graph.json I/O.
#include "slamroute/core/RoadGraph.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "JsonFile.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Coordinates.hpp"
#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute {
using nlohmann::json;

std::vector<std::vector<int>> RoadGraph::outEdges() const {
  std::vector<std::vector<int>> out(nodes.size());
  for (const auto& e : edges) out[static_cast<std::size_t>(e.u)].push_back(e.id);
  return out;
}

std::vector<int> RoadGraph::nextEdges(int edge) const {
  if (restricted_turns) return allowed_next.at(static_cast<std::size_t>(edge));
  std::vector<int> out;
  const int v = edges.at(static_cast<std::size_t>(edge)).v;
  for (const auto& e : edges)
    if (e.u == v) out.push_back(e.id);
  return out;
}

double RoadGraph::totalLength() const {
  double s = 0.0;
  for (const auto& e : edges) s += e.length_m;
  return s;
}

void RoadGraph::validate(const std::string& where) const {
  const int n = static_cast<int>(nodes.size()), m = static_cast<int>(edges.size());
  for (int i = 0; i < n; ++i) {
    const RoadNode& node = nodes[static_cast<std::size_t>(i)];
    if (node.id != i)
      throw std::invalid_argument(where + ": node ids must be 0..N-1 in order (node " +
                                  std::to_string(i) + ")");
    if (!plausibleCoordinate(node.pos.x()) || !plausibleCoordinate(node.pos.y()) ||
        !plausibleCoordinate(node.pos.z()))
      throw std::invalid_argument(where + ": node " + std::to_string(i) + ": " + kCoordinateRule);
  }
  for (int i = 0; i < m; ++i) {
    const RoadEdge& e = edges[static_cast<std::size_t>(i)];
    if (e.id != i)
      throw std::invalid_argument(where + ": edge ids must be 0..M-1 in order (edge " +
                                  std::to_string(i) + ")");
    if (e.u < 0 || e.u >= n || e.v < 0 || e.v >= n)
      throw std::invalid_argument(where + ": edge " + std::to_string(i) + " names a missing node");
    if (!(e.length_m >= 0.0) || !(e.length_m <= kMaxCoordinateM) || !std::isfinite(e.weight))
      throw std::invalid_argument(where + ": edge " + std::to_string(i) +
                                  " has a bad length or weight");
    for (const Point3& p : e.polyline)
      if (!plausibleCoordinate(p.x()) || !plausibleCoordinate(p.y()) || !plausibleCoordinate(p.z()))
        throw std::invalid_argument(where + ": edge " + std::to_string(i) +
                                    " polyline: " + kCoordinateRule);
  }
  if (restricted_turns) {
    if (allowed_next.size() != edges.size())
      throw std::invalid_argument(where + ": turn table size differs from the edge count");
    for (int i = 0; i < m; ++i)
      for (int nx : allowed_next[static_cast<std::size_t>(i)])
        if (nx < 0 || nx >= m ||
            edges[static_cast<std::size_t>(nx)].u != edges[static_cast<std::size_t>(i)].v)
          throw std::invalid_argument(where + ": turn from edge " + std::to_string(i) +
                                      " to edge " + std::to_string(nx) + " is not a turn");
  }
}

RoadGraph RoadGraph::fromSumoNet(const SumoNet& net, bool lscc_only) {
  const DriveGraph dg = DriveGraph::fromNet(net);
  RoadGraph g;
  g.restricted_turns = true;
  std::vector<int> node_of(dg.numVertices(), -1), edge_of(dg.numEdges(), -1);
  for (std::size_t v = 0; v < dg.numVertices(); ++v) {
    if (lscc_only && !dg.in_lscc_vertex[v]) continue;
    node_of[v] = static_cast<int>(g.nodes.size());
    g.nodes.push_back({node_of[v], dg.g[v].pos, dg.g[v].junction_id});
  }
  std::size_t dropped = 0;
  for (std::size_t i = 0; i < dg.numEdges(); ++i) {
    if (lscc_only && !dg.in_lscc_edge[i]) {
      ++dropped;
      continue;
    }
    const SumoEdge& se = *net.findEdge(dg.edges[i].sumo_edge);
    RoadEdge e;
    e.id = static_cast<int>(g.edges.size());
    e.u = node_of[dg.edges[i].u];
    e.v = node_of[dg.edges[i].v];
    e.length_m = dg.edges[i].length_m;
    e.polyline = se.shape;
    e.sumo_edges = {se.id};
    edge_of[i] = e.id;
    g.edges.push_back(std::move(e));
  }
  // Streets: pair each edge with an unpaired reverse edge between the same two nodes.
  std::map<std::pair<int, int>, std::vector<int>> by_ends;
  for (const auto& e : g.edges) by_ends[{e.u, e.v}].push_back(e.id);
  int street = 0;
  for (auto& e : g.edges) {
    if (e.street >= 0) continue;
    e.street = street;
    auto it = by_ends.find({e.v, e.u});
    if (it != by_ends.end() && e.u != e.v) {
      for (int r : it->second)
        if (g.edges[static_cast<std::size_t>(r)].street < 0) {
          g.edges[static_cast<std::size_t>(r)].street = street;
          break;
        }
    }
    ++street;
  }
  g.allowed_next.assign(g.edges.size(), {});
  for (std::size_t i = 0; i < dg.numEdges(); ++i) {
    if (edge_of[i] < 0) continue;
    for (std::size_t nx : dg.allowed_next[i])
      if (edge_of[nx] >= 0)
        g.allowed_next[static_cast<std::size_t>(edge_of[i])].push_back(edge_of[nx]);
  }
  g.metadata_json = json{
      {"source", "sumo-net"},
      {"net", net.source.string()},
      {"largest_scc_only", lscc_only},
      {"dropped_edges",
       dropped}}.dump();
  return g;
}

RoadGraph RoadGraph::readJson(const std::filesystem::path& path) {
  const std::string name = path.string();
  const json j = detail::readJsonFile(path);
  RoadGraph g;
  try {
    if (!j.is_object() || !j.contains("nodes") || !j.contains("edges"))
      throw std::invalid_argument(name + ": not a road graph (needs \"nodes\" and \"edges\")");
    for (const auto& n : j.at("nodes")) {
      RoadNode node;
      node.id = n.at("id").get<int>();
      node.pos = Point3(n.at("x").get<double>(), n.at("y").get<double>(), n.value("z", 0.0));
      node.sumo_junction = n.value("sumo_junction", "");
      g.nodes.push_back(std::move(node));
    }
    for (const auto& e : j.at("edges")) {
      RoadEdge edge;
      edge.id = e.at("id").get<int>();
      edge.u = e.at("u").get<int>();
      edge.v = e.at("v").get<int>();
      edge.length_m = e.at("length").get<double>();
      edge.weight = e.value("weight", 1.0);
      edge.street = e.value("street", -1);
      if (e.contains("polyline"))
        for (const auto& p : e.at("polyline"))
          edge.polyline.emplace_back(p.at(0).get<double>(), p.at(1).get<double>(),
                                     p.size() > 2 ? p.at(2).get<double>() : 0.0);
      if (e.contains("sumo_edges"))
        edge.sumo_edges = e.at("sumo_edges").get<std::vector<std::string>>();
      g.edges.push_back(std::move(edge));
    }
    if (j.contains("turns") && !j.at("turns").is_null()) {
      g.restricted_turns = true;
      g.allowed_next = j.at("turns").get<std::vector<std::vector<int>>>();
    }
    if (j.contains("metadata")) g.metadata_json = j.at("metadata").dump();
  } catch (const json::exception& e) {
    throw std::invalid_argument(name + ": malformed road graph (" + detail::jsonErrorText(e) + ")");
  }
  // Streets default to one per edge when the file does not pair directions.
  for (auto& e : g.edges)
    if (e.street < 0) e.street = e.id;
  g.validate(name);
  return g;
}

void RoadGraph::writeJson(const std::filesystem::path& path) const {
  json j;
  j["nodes"] = json::array();
  for (const auto& n : nodes) {
    json jn = {{"id", n.id}, {"x", n.pos.x()}, {"y", n.pos.y()}, {"z", n.pos.z()}};
    if (!n.sumo_junction.empty()) jn["sumo_junction"] = n.sumo_junction;
    j["nodes"].push_back(std::move(jn));
  }
  j["edges"] = json::array();
  for (const auto& e : edges) {
    json pl = json::array();
    for (const auto& p : e.polyline) pl.push_back({p.x(), p.y(), p.z()});
    j["edges"].push_back({{"id", e.id},
                          {"u", e.u},
                          {"v", e.v},
                          {"length", e.length_m},
                          {"weight", e.weight},
                          {"street", e.street},
                          {"polyline", std::move(pl)},
                          {"sumo_edges", e.sumo_edges}});
  }
  j["turns"] = restricted_turns ? json(allowed_next) : json(nullptr);
  j["metadata"] = json::parse(metadata_json.empty() ? "{}" : metadata_json);
  detail::requireFiniteNumbers(j, path.string());
  writeFileAtomic(path, j.dump(1) + "\n");
}

}  // namespace slamroute
