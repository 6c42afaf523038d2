// validateRoute: reject a bad route before SUMO starts (nothing is written, no simulation runs).
#include <stdexcept>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::simulate {

void validateRoute(const SumoNet& net, const std::vector<std::string>& edges,
                   const std::string& where) {
  if (edges.empty()) throw std::invalid_argument(where + ": route is empty (no SUMO edges)");
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const SumoEdge* e = net.findEdge(edges[i]);
    if (!e)
      throw std::invalid_argument(where + ": edge '" + edges[i] + "' (route position " +
                                  std::to_string(i) + ") is not in net " + net.source.string());
    if (e->isInternal() || !e->allowsPassenger())
      throw std::invalid_argument(where + ": edge '" + edges[i] + "' (route position " +
                                  std::to_string(i) + ") is not drivable by passenger cars");
    if (i > 0 && !net.turnAllowed(edges[i - 1], edges[i]))
      throw std::invalid_argument(where + ": turn '" + edges[i - 1] + "' -> '" + edges[i] +
                                  "' (route position " + std::to_string(i) +
                                  ") is not allowed in net " + net.source.string());
  }
}

}  // namespace slamroute::simulate
