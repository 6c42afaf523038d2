// Q-learning on real nets: how many training episodes reach the goal (every node visited), the
// share of the route the learned policy chose (the rest are shortest-path completions), route
// length and planning time, under the paper's setting, without the guide, and the defaults.
//   bench_qlearning_nets [--seed S] [--nets NET,NET,..]
// Default nets: Bologna Acosta, Ingolstadt (../shared/networks), Berlin-Adlershof (sumo-tools),
// the shipped city.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "slamroute/core/Log.hpp"
#include "slamroute/rl/Planners.hpp"

using namespace slamroute;

namespace {

struct Options {
  std::uint64_t seed = 42;
  std::vector<std::string> nets = {
      std::string(SLAMROUTE_SHARED_DIR) + "/networks/bologna_acosta/acosta_buslanes.net.xml",
      std::string(SLAMROUTE_SHARED_DIR) + "/networks/ingolstadt21/ingolstadt21.net.xml",
      "/usr/share/sumo/tools/game/DRT/osm.net.xml",
      std::string(SLAMROUTE_SOURCE_DIR) + "/networks/default_city/default_city.net.xml"};
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--seed")
      o.seed = std::stoull(v);
    else if (k == "--nets") {
      o.nets.clear();
      std::stringstream ss(v);
      for (std::string p; std::getline(ss, p, ',');) o.nets.push_back(p);
    }
  }
  return o;
}

/// The three settings compared: the paper's, the defaults without the guide (the planner's
/// defaults before the guide), the defaults.
std::vector<std::pair<std::string, rl::Config>> settings() {
  rl::Config defaults;
  defaults.planner = "qlearning";
  rl::Config no_guide = defaults;
  no_guide.qlearning.guide_to_uncovered = false;
  no_guide.qlearning.guide_reward = 0.0;
  no_guide.qlearning.stall_steps = 2;  // without the guide, a greedy detour is cut after 2 steps
  rl::Config paper = no_guide;
  paper.qlearning.explore_new_first = false;
  paper.qlearning.spread_starts = false;
  paper.qlearning.cap_scales_with_log_edges = false;
  return {{"paper", paper}, {"no guide", no_guide}, {"defaults", defaults}};
}

}  // namespace

int main(int argc, char** argv) {
  setLogLevel(LogLevel::Warn);
  const Options o = parse(argc, argv);
  std::printf("seed %llu, %d episodes\n\n", static_cast<unsigned long long>(o.seed),
              rl::QLearningConfig{}.episodes);
  std::printf(
      "| net | setting | episodes reaching goal | learned share [%%] | route km | "
      "node cov [%%] | planning [s] |\n|---|---|---|---|---|---|---|\n");
  for (const auto& net : o.nets) {
    if (!std::filesystem::exists(net)) {
      std::printf("| %s | missing |||||\n", net.c_str());
      continue;
    }
    const RoadGraph g = RoadGraph::fromSumoNet(SumoNet::read(net), /*lscc_only=*/false);
    for (const auto& [name, cfg] : settings()) {
      const auto t0 = std::chrono::steady_clock::now();
      const Route r = rl::plan(g, cfg, o.seed, net);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const auto x = nlohmann::json::parse(r.extra_json);
      std::printf("| %s | %s | %d / %d | %.1f | %.2f | %.1f | %.2f |\n",
                  std::filesystem::path(net).filename().c_str(), name.c_str(),
                  x["episodes_reaching_goal"].get<int>(), x["episodes"].get<int>(),
                  100.0 * x["learned_policy_share"].get<double>(), r.length_m / 1000.0,
                  r.node_coverage_pct, s);
      std::fflush(stdout);
    }
  }
}
