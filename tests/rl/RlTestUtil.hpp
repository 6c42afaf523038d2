#pragma once
// Helpers shared by the rl tests: shared/shipped networks, small graphs.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/rl/Planners.hpp"
#include "slamroute/rl/SyntheticGraph.hpp"

namespace slamroute::rl::test {

inline std::filesystem::path sharedNet(const std::string& rel) {
  return std::filesystem::path(SLAMROUTE_SHARED_DIR) / "networks" / rel;
}
inline std::filesystem::path bolognaNet() { return sharedNet("bologna_acosta/acosta_buslanes.net.xml"); }
inline std::filesystem::path ingolstadtNet() { return sharedNet("ingolstadt21/ingolstadt21.net.xml"); }
inline std::filesystem::path defaultCityNet() {
  return std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
}

inline RoadGraph netGraph(const std::filesystem::path& p) {
  return RoadGraph::fromSumoNet(SumoNet::read(p), /*lscc_only=*/false);
}

inline nlohmann::json extra(const Route& r) { return nlohmann::json::parse(r.extra_json); }

/// Two-way rows x cols grid, 100 m blocks, every turn allowed (U-turns too).
inline RoadGraph grid(int rows, int cols) {
  GridCitySpec s;
  s.rows = rows;
  s.cols = cols;
  return gridCity(s);
}

}  // namespace slamroute::rl::test
