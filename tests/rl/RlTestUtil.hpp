#pragma once
// Helpers shared by the rl tests: the shipped and the sumo-tools networks, small graphs.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "SumoToolsNets.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/rl/Planners.hpp"
#include "slamroute/rl/SyntheticGraph.hpp"

namespace slamroute::rl::test {

using slamroute::test::adlershofNet;
using slamroute::test::bolognaNet;
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
