// validateRoute: reject a bad route before SUMO starts (nothing is written, no simulation runs).
#include <sstream>
#include <stdexcept>

#include "slamroute/core/Log.hpp"
#include "slamroute/core/SumoRoute.hpp"

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::simulate {

void validateRoute(const SumoNet& net, const std::vector<std::string>& edges,
                   const std::string& where, bool check_turns) {
  if (edges.empty()) throw std::invalid_argument(where + ": route is empty (no SUMO edges)");
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const SumoEdge* e = net.findEdge(edges[i]);
    if (!e)
      throw std::invalid_argument(where + ": edge '" + edges[i] + "' (route position " +
                                  std::to_string(i) + ") is not in net " + net.source.string());
    if (e->isInternal() || !e->allowsPassenger())
      throw std::invalid_argument(where + ": edge '" + edges[i] + "' (route position " +
                                  std::to_string(i) + ") is not drivable by passenger cars");
    if (check_turns && i > 0 && !net.turnAllowed(edges[i - 1], edges[i]))
      throw std::invalid_argument(where + ": turn '" + edges[i - 1] + "' -> '" + edges[i] +
                                  "' (route position " + std::to_string(i) +
                                  ") is not allowed in net " + net.source.string());
  }
}

std::vector<std::string> drivableRoute(const SumoNet& net, const std::vector<std::string>& edges,
                                       const std::string& where, bool join_forbidden_turns) {
  if (!join_forbidden_turns) {
    validateRoute(net, edges, where);
    return edges;
  }
  validateRoute(net, edges, where, /*check_turns=*/false);
  LegalRoute legal;
  try {
    legal = legalizeSumoRoute(net, edges);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where + ": " + e.what());
  }
  if (legal.repaired_transitions > 0 || legal.dropped_edges > 0) {
    std::ostringstream msg;
    msg << where << ": " << legal.repaired_transitions
        << " turn(s) SUMO does not allow joined by the shortest legal detour (+"
        << static_cast<long>(legal.added_length_m + 0.5) << " m)";
    if (legal.dropped_edges > 0)
      msg << ", " << legal.dropped_edges << " edge(s) dropped that no legal path passes";
    logWarn(msg.str());
  }
  return legal.edges;  // every consecutive pair is a SUMO connection by construction
}

}  // namespace slamroute::simulate
