// Drivable passenger graph of a SUMO net (Boost.Graph) and its largest strongly connected part.
#include "slamroute/core/DriveGraph.hpp"

#include <boost/graph/strong_components.hpp>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace slamroute {
namespace {

/// Marks the largest set of edges strongly connected under allowed_next (edges as vertices).
void markLegalPart(DriveGraph& dg) {
  using EdgeGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;
  EdgeGraph eg(dg.edges.size());
  for (std::size_t i = 0; i < dg.edges.size(); ++i)
    for (std::size_t next : dg.allowed_next[i]) boost::add_edge(i, next, eg);
  std::vector<int> comp(dg.edges.size());
  const int ncomp = boost::strong_components(
      eg, boost::make_iterator_property_map(comp.begin(), boost::get(boost::vertex_index, eg)));
  std::vector<std::size_t> size(static_cast<std::size_t>(ncomp), 0);
  for (int c : comp) ++size[static_cast<std::size_t>(c)];
  const auto best = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
  dg.in_legal_edge.assign(dg.edges.size(), false);
  for (std::size_t i = 0; i < comp.size(); ++i)
    if (comp[i] == best) {
      dg.in_legal_edge[i] = true;
      ++dg.legal_edges;
    }
}

}  // namespace

DriveGraph DriveGraph::fromNet(const SumoNet& net) {
  DriveGraph dg;
  std::unordered_map<std::string, std::size_t> vertex_of;
  auto vertex = [&](const std::string& jid) {
    auto it = vertex_of.find(jid);
    if (it != vertex_of.end()) return it->second;
    DriveVertex v;
    v.junction_id = jid;
    if (const SumoJunction* j = net.findJunction(jid)) v.pos = j->pos;
    const std::size_t idx = boost::add_vertex(v, dg.g);
    vertex_of.emplace(jid, idx);
    return idx;
  };
  for (const SumoEdge& e : net.edges) {
    if (!e.allowsPassenger() || e.from.empty() || e.to.empty()) continue;
    const std::size_t u = vertex(e.from), v = vertex(e.to);
    DriveEdge de;
    de.index = dg.edges.size();
    de.sumo_edge = e.id;
    de.length_m = e.length();
    de.speed_mps = e.speed();
    de.shape = e.shape;
    boost::add_edge(u, v, de, dg.g);
    dg.edge_of.emplace(e.id, dg.edges.size());
    dg.edges.push_back({u, v, e.id, de.length_m});
  }
  if (dg.edges.empty())
    throw std::invalid_argument(net.source.string() +
                                ": the net has no edge open to passenger cars");

  dg.allowed_next.assign(dg.edges.size(), {});
  for (std::size_t i = 0; i < dg.edges.size(); ++i) {
    for (auto [ei, ee] = boost::out_edges(dg.edges[i].v, dg.g); ei != ee; ++ei) {
      const DriveEdge& next = dg.g[*ei];
      if (net.turnAllowed(dg.edges[i].sumo_edge, next.sumo_edge))
        dg.allowed_next[i].push_back(next.index);
    }
  }

  std::vector<int> comp(dg.numVertices());
  const int ncomp = boost::strong_components(
      dg.g, boost::make_iterator_property_map(comp.begin(), boost::get(boost::vertex_index, dg.g)));
  std::vector<std::size_t> size(static_cast<std::size_t>(ncomp), 0);
  for (int c : comp) ++size[static_cast<std::size_t>(c)];
  std::size_t best = 0;
  for (std::size_t c = 1; c < size.size(); ++c)
    if (size[c] > size[best]) best = c;
  dg.in_lscc_vertex.assign(dg.numVertices(), false);
  for (std::size_t v = 0; v < comp.size(); ++v)
    if (static_cast<std::size_t>(comp[v]) == best) {
      dg.in_lscc_vertex[v] = true;
      ++dg.lscc_vertices;
    }
  dg.in_lscc_edge.assign(dg.edges.size(), false);
  for (std::size_t i = 0; i < dg.edges.size(); ++i)
    if (dg.in_lscc_vertex[dg.edges[i].u] && dg.in_lscc_vertex[dg.edges[i].v]) {
      dg.in_lscc_edge[i] = true;
      ++dg.lscc_edges;
    }
  markLegalPart(dg);
  return dg;
}

NetworkInfo networkInfo(const SumoNet& net) {
  const DriveGraph dg = DriveGraph::fromNet(net);
  NetworkInfo info;
  info.junctions = net.junctions.size();
  info.passenger_edges = dg.numEdges();
  info.lscc_junctions = dg.lscc_vertices;
  info.lscc_edges = dg.lscc_edges;
  for (std::size_t i = 0; i < dg.edges.size(); ++i) {
    info.total_length_m += dg.edges[i].length_m;
    if (dg.in_lscc_edge[i]) info.lscc_length_m += dg.edges[i].length_m;
  }
  return info;
}

}  // namespace slamroute
