// Legal SUMO routes: Dijkstra on the line graph of passenger edges (vertex = SUMO edge, arc =
// allowed turn, arc cost = length of the edge driven next).
#include "slamroute/core/SumoRoute.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/strong_components.hpp>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace slamroute {
namespace {

using LineGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property,
                                        boost::property<boost::edge_weight_t, double>>;

}  // namespace

int firstIllegalTurn(const SumoNet& net, const std::vector<std::string>& edges) {
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    if (!net.turnAllowed(edges[i], edges[i + 1])) return static_cast<int>(i);
  return -1;
}

LegalRoute legalizeSumoRoute(const SumoNet& net, const std::vector<std::string>& edges) {
  const std::string where = net.source.string();
  std::vector<const SumoEdge*> pax;
  std::unordered_map<std::string, std::size_t> index;
  for (const auto& e : net.edges)
    if (e.allowsPassenger() && !e.from.empty()) {
      index.emplace(e.id, pax.size());
      pax.push_back(&e);
    }
  for (const auto& id : edges) {
    if (!net.findEdge(id)) throw std::invalid_argument(where + ": route edge '" + id + "' is not in the net");
    if (!index.count(id))
      throw std::invalid_argument(where + ": route edge '" + id + "' is not open to passenger cars");
  }
  LegalRoute out;
  if (edges.empty()) return out;
  LineGraph lg(pax.size());
  for (std::size_t i = 0; i < pax.size(); ++i)
    for (const auto& c : net.connections)
      if (c.from == pax[i]->id) {
        auto it = index.find(c.to);
        if (it != index.end() && net.turnAllowed(c.from, c.to))
          boost::add_edge(i, it->second, pax[it->second]->length(), lg);
      }
  std::vector<std::size_t> comp(pax.size());
  const std::size_t ncomp = pax.empty() ? 0 : boost::strong_components(
      lg, boost::make_iterator_property_map(comp.begin(), boost::get(boost::vertex_index, lg)));
  std::vector<std::size_t> comp_size(ncomp, 0);
  for (std::size_t c : comp) ++comp_size[c];
  const std::size_t largest =
      static_cast<std::size_t>(std::max_element(comp_size.begin(), comp_size.end()) - comp_size.begin());
  auto inLargest = [&](const std::string& id) { return comp[index.at(id)] == largest; };

  std::vector<double> dist(pax.size());
  std::vector<std::size_t> pred(pax.size());
  out.edges.push_back(edges.front());
  for (std::size_t k = 1; k < edges.size(); ++k) {
    const std::string& b = edges[k];
    const bool b_interior = k + 1 < edges.size();
    for (;;) {
      const std::string a = out.edges.back();
      if (a == b) break;
      if (net.turnAllowed(a, b)) {
        out.edges.push_back(b);
        break;
      }
      const std::size_t s = index.at(a), t = index.at(b);
      boost::dijkstra_shortest_paths(
          lg, s,
          boost::predecessor_map(boost::make_iterator_property_map(pred.begin(), boost::get(boost::vertex_index, lg)))
              .distance_map(boost::make_iterator_property_map(dist.begin(), boost::get(boost::vertex_index, lg))));
      if (pred[t] != t) {
        std::vector<std::size_t> path;
        for (std::size_t v = pred[t]; v != s; v = pred[v]) path.push_back(v);
        std::reverse(path.begin(), path.end());
        for (std::size_t v : path) {
          out.edges.push_back(pax[v]->id);
          out.added_length_m += pax[v]->length();
        }
        out.edges.push_back(b);
        ++out.repaired_transitions;
        break;
      }
      // No legal way: drop whichever of the two lies outside the drivable core (b first).
      if (b_interior && !inLargest(b)) {
        ++out.dropped_edges;
        break;
      }
      if (out.edges.size() > 1 && !inLargest(a)) {
        out.edges.pop_back();
        ++out.dropped_edges;
        continue;
      }
      throw std::invalid_argument(where + ": no legal way from edge '" + a + "' to edge '" + b + "'");
    }
  }
  return out;
}

}  // namespace slamroute
