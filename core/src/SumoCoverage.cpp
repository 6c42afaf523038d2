// Directed coverage of SUMO edges and route length as driven in SUMO (SumoCoverage.hpp).
#include "slamroute/core/SumoCoverage.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "slamroute/core/DriveGraph.hpp"

namespace slamroute {

namespace {

/// Normal edges of `route` that the net has, consecutive repeats merged.
std::vector<const SumoEdge*> routeEdges(const SumoNet& net, const std::vector<std::string>& route) {
  std::vector<const SumoEdge*> out;
  for (const auto& id : route) {
    if (id.empty() || id[0] == ':') continue;
    const SumoEdge* e = net.findEdge(id);
    if (e && (out.empty() || out.back() != e)) out.push_back(e);
  }
  return out;
}

void countCovered(const SumoNet& net, const std::vector<const SumoEdge*>& driven, SumoCoverage& c) {
  const DriveGraph dg = DriveGraph::fromNet(net);
  std::unordered_set<const SumoEdge*> seen(driven.begin(), driven.end());
  for (std::size_t i = 0; i < dg.edges.size(); ++i) {
    const SumoEdge* e = net.findEdge(dg.edges[i].sumo_edge);
    if (dg.in_lscc_edge[i]) {
      ++c.junction_part_edges;
      c.junction_part_driven += seen.count(e) ? 1 : 0;
      c.edges_without_legal_route += dg.in_legal_edge[i] ? 0 : 1;
    }
    if (!dg.in_legal_edge[i]) continue;
    ++c.edges_total;
    c.length_total_m += e->length();
    if (!seen.count(e)) continue;
    ++c.edges_driven;
    c.length_driven_m += e->length();
  }
  c.edges_pct = c.edges_total > 0 ? 100.0 * c.edges_driven / c.edges_total : 0.0;
  c.length_pct = c.length_total_m > 0 ? 100.0 * c.length_driven_m / c.length_total_m : 0.0;
  c.junction_part_pct =
      c.junction_part_edges > 0 ? 100.0 * c.junction_part_driven / c.junction_part_edges : 0.0;
}

/// Internal-lane length of each passenger turn (the shortest of its lane connections) [m],
/// keyed "from to".
std::unordered_map<std::string, double> turnLengths(const SumoNet& net) {
  std::unordered_map<std::string, double> out;
  for (const auto& c : net.connections) {
    if (!net.turnAllowed(c.from, c.to)) continue;
    auto [it, fresh] = out.emplace(c.from + " " + c.to, c.via_length_m);
    if (!fresh) it->second = std::min(it->second, c.via_length_m);
  }
  return out;
}

}  // namespace

SumoCoverage sumoCoverage(const SumoNet& net, const std::vector<std::string>& route) {
  SumoCoverage c;
  const auto edges = routeEdges(net, route);
  countCovered(net, edges, c);
  const auto turns = turnLengths(net);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    c.route_on_edges_m += edges[k]->length();
    if (k == 0) continue;
    const auto it = turns.find(edges[k - 1]->id + " " + edges[k]->id);
    if (it == turns.end())
      ++c.turns_without_connection;
    else
      c.route_in_junctions_m += it->second;
  }
  return c;
}

void sumoCoverageToJson(const SumoCoverage& c, nlohmann::json& j) {
  j["directed_coverage"] = {
      {"definition",
       "directed SUMO edges driven, of the passenger edges in the net's largest part "
       "strongly connected under its turn permissions (internal junction edges excluded); "
       "junction_part: the same over the largest part strongly connected over junctions, "
       "turns ignored, whose edges_without_legal_route no legal drive enters and leaves"},
      {"edges_pct", c.edges_pct},
      {"length_pct", c.length_pct},
      {"edges_driven", c.edges_driven},
      {"edges_total", c.edges_total},
      {"length_driven_m", c.length_driven_m},
      {"length_total_m", c.length_total_m},
      {"junction_part",
       {{"edges_total", c.junction_part_edges},
        {"edges_driven", c.junction_part_driven},
        {"edges_pct", c.junction_part_pct},
        {"edges_without_legal_route", c.edges_without_legal_route}}}};
  j["sumo_length"] = {{"total_m", c.routeLengthM()},
                      {"on_edges_m", c.route_on_edges_m},
                      {"in_junctions_m", c.route_in_junctions_m},
                      {"turns_without_connection", c.turns_without_connection}};
}

std::optional<SumoCoverage> sumoCoverageFromJson(const nlohmann::json& j) {
  if (!j.contains("directed_coverage") || !j.contains("sumo_length")) return std::nullopt;
  const nlohmann::json& d = j.at("directed_coverage");
  const nlohmann::json& l = j.at("sumo_length");
  SumoCoverage c;
  c.edges_pct = d.at("edges_pct").get<double>();
  c.length_pct = d.at("length_pct").get<double>();
  c.edges_driven = d.at("edges_driven").get<int>();
  c.edges_total = d.at("edges_total").get<int>();
  c.length_driven_m = d.at("length_driven_m").get<double>();
  c.length_total_m = d.at("length_total_m").get<double>();
  if (d.contains("junction_part")) {
    const nlohmann::json& jp = d.at("junction_part");
    c.junction_part_edges = jp.at("edges_total").get<int>();
    c.junction_part_driven = jp.at("edges_driven").get<int>();
    c.junction_part_pct = jp.at("edges_pct").get<double>();
    c.edges_without_legal_route = jp.at("edges_without_legal_route").get<int>();
  }
  c.route_on_edges_m = l.at("on_edges_m").get<double>();
  c.route_in_junctions_m = l.at("in_junctions_m").get<double>();
  c.turns_without_connection = l.value("turns_without_connection", 0);
  return c;
}

}  // namespace slamroute
