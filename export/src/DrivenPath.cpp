#include "slamroute/export/DrivenPath.hpp"

#include <stdexcept>

namespace slamroute::exports {

DrivenPath drivenPath(const SumoNet& net, const std::vector<std::string>& sumo_edges) {
  DrivenPath d;
  for (const auto& id : sumo_edges) {
    const SumoEdge* e = net.findEdge(id);
    if (!e)
      throw std::invalid_argument(net.source.string() + ": the route's SUMO edge '" + id +
                                  "' is not in this net");
    d.edge_first.push_back(d.points.size());
    d.edge_start_m.push_back(d.length_m);
    const double len = polylineLength(e->shape);
    d.edge_length_m.push_back(len);
    d.length_m += len;
    for (const auto& p : e->shape)
      if (d.points.empty() || (d.points.back() - p).norm() > 1e-6) d.points.push_back(p);
  }
  return d;
}

}  // namespace slamroute::exports
