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

using LineGraph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property,
                          boost::property<boost::edge_weight_t, double>>;

/// The passenger edges of a net as the vertices of a line graph (arc = allowed turn, cost = the
/// length of the edge driven next) and its largest strongly connected part.
class PassengerLineGraph {
 public:
  explicit PassengerLineGraph(const SumoNet& net)
      : pax_(passengerEdges(net, index_)), lg_(pax_.size()) {
    for (std::size_t i = 0; i < pax_.size(); ++i)
      for (const auto& c : net.connections)
        if (c.from == pax_[i]->id) {
          auto it = index_.find(c.to);
          if (it != index_.end() && net.turnAllowed(c.from, c.to))
            boost::add_edge(i, it->second, pax_[it->second]->length(), lg_);
        }
    findLargestPart();
  }

  bool has(const std::string& id) const { return index_.count(id) > 0; }
  bool inLargest(const std::string& id) const { return comp_[index_.at(id)] == largest_; }

  /// The edges strictly between a and b on the shortest legal path; false when there is none.
  bool pathBetween(const std::string& a, const std::string& b,
                   std::vector<const SumoEdge*>& between) {
    const std::size_t s = index_.at(a), t = index_.at(b);
    dist_.resize(pax_.size());
    pred_.resize(pax_.size());
    const auto vertex = boost::get(boost::vertex_index, lg_);
    boost::dijkstra_shortest_paths(
        lg_, s,
        boost::predecessor_map(boost::make_iterator_property_map(pred_.begin(), vertex))
            .distance_map(boost::make_iterator_property_map(dist_.begin(), vertex)));
    if (pred_[t] == t) return false;
    between.clear();
    for (std::size_t v = pred_[t]; v != s; v = pred_[v]) between.push_back(pax_[v]);
    std::reverse(between.begin(), between.end());
    return true;
  }

 private:
  void findLargestPart() {
    comp_.resize(pax_.size());
    const std::size_t ncomp =
        pax_.empty() ? 0
                     : boost::strong_components(
                           lg_, boost::make_iterator_property_map(
                                    comp_.begin(), boost::get(boost::vertex_index, lg_)));
    std::vector<std::size_t> comp_size(ncomp, 0);
    for (std::size_t c : comp_) ++comp_size[c];
    largest_ = static_cast<std::size_t>(std::max_element(comp_size.begin(), comp_size.end()) -
                                        comp_size.begin());
  }

  /// The edges open to passenger cars, numbered in `index`.
  static std::vector<const SumoEdge*> passengerEdges(
      const SumoNet& net, std::unordered_map<std::string, std::size_t>& index) {
    std::vector<const SumoEdge*> pax;
    for (const auto& e : net.edges)
      if (e.allowsPassenger() && !e.from.empty()) {
        index.emplace(e.id, pax.size());
        pax.push_back(&e);
      }
    return pax;
  }

  std::unordered_map<std::string, std::size_t> index_;
  std::vector<const SumoEdge*> pax_;
  LineGraph lg_;
  std::vector<std::size_t> comp_;
  std::size_t largest_ = 0;
  std::vector<double> dist_;
  std::vector<std::size_t> pred_;
};

/// Continues out.edges legally to edge b: directly, by the shortest legal path, or, where there
/// is no legal way, by dropping b (interior edges only) or the last edge when it lies outside
/// the drivable core.
void continueTo(const SumoNet& net, PassengerLineGraph& lg, const std::string& b, bool b_interior,
                LegalRoute& out) {
  std::vector<const SumoEdge*> between;
  for (;;) {
    const std::string a = out.edges.back();
    if (a == b) return;
    if (net.turnAllowed(a, b)) {
      out.edges.push_back(b);
      return;
    }
    if (lg.pathBetween(a, b, between)) {
      for (const SumoEdge* e : between) {
        out.edges.push_back(e->id);
        out.added_length_m += e->length();
      }
      out.edges.push_back(b);
      ++out.repaired_transitions;
      return;
    }
    if (b_interior && !lg.inLargest(b)) {
      ++out.dropped_edges;
      return;
    }
    if (out.edges.size() > 1 && !lg.inLargest(a)) {
      out.edges.pop_back();
      ++out.dropped_edges;
      continue;
    }
    throw std::invalid_argument(net.source.string() + ": no legal way from edge '" + a +
                                "' to edge '" + b + "'");
  }
}

}  // namespace

int firstIllegalTurn(const SumoNet& net, const std::vector<std::string>& edges) {
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    if (!net.turnAllowed(edges[i], edges[i + 1])) return static_cast<int>(i);
  return -1;
}

LegalRoute legalizeSumoRoute(const SumoNet& net, const std::vector<std::string>& edges) {
  const std::string where = net.source.string();
  PassengerLineGraph lg(net);
  for (const auto& id : edges) {
    if (!net.findEdge(id))
      throw std::invalid_argument(where + ": route edge '" + id + "' is not in the net");
    if (!lg.has(id))
      throw std::invalid_argument(where + ": route edge '" + id +
                                  "' is not open to passenger cars");
  }
  LegalRoute out;
  if (edges.empty()) return out;
  out.edges.push_back(edges.front());
  for (std::size_t k = 1; k < edges.size(); ++k)
    continueTo(net, lg, edges[k], k + 1 < edges.size(), out);
  return out;
}

}  // namespace slamroute
