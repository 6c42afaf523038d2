// Fleet planning on real nets: makespan against the simple lower bound max(L1 / K, longest
// depot-edge-depot round trip) and against the proven depot-trips bound (FleetRoute
// depot_bound_m), total length against the single postman route L1, balance and planning time,
// for K = 2, 4, 8 and both strategies. Depot: the first node of the planning
// graph (rl.start_node = -1). Usage:
//   bench_fleet [--strategies partition,postman] [--k 2,4,8] [--candidates N] [--moves N]
//               [--kicks N] [--merge-budget N] [--budget W] [--seed S]
//               [--nets NAME,NAME] (names as in the table)
// Bologna and Ingolstadt are read from ../shared/networks beside the clone (not shipped: see
// networks/README.md); Berlin-Adlershof from Debian's sumo-tools.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/rl/Fleet.hpp"

namespace {

struct Net {
  std::string name;
  std::filesystem::path path;
};

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace slamroute;
  std::vector<std::string> strategies{"partition", "postman"};
  std::vector<std::string> ks{"2", "4", "8"};
  rl::FleetConfig defaults;
  std::vector<std::string> only;  // net names to run; empty: all
  std::uint64_t seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--strategies")
      strategies = splitList(argv[i + 1]);
    else if (a == "--k")
      ks = splitList(argv[i + 1]);
    else if (a == "--candidates")
      defaults.candidates_per_move = std::stoi(argv[i + 1]);
    else if (a == "--moves")
      defaults.balance_moves = std::stoi(argv[i + 1]);
    else if (a == "--kicks")
      defaults.kick_rounds = std::stoi(argv[i + 1]);
    else if (a == "--merge-budget")
      defaults.merge_budget = std::stoi(argv[i + 1]);
    else if (a == "--budget")
      defaults.kick_budget = std::stoi(argv[i + 1]);
    else if (a == "--seed")
      seed = std::stoull(argv[i + 1]);
    else if (a == "--nets")
      only = splitList(argv[i + 1]);
  }
  const std::string src = SLAMROUTE_SOURCE_DIR, shared = SLAMROUTE_SHARED_DIR;
  const std::vector<Net> nets{
      {"default city", src + "/networks/default_city/default_city.net.xml"},
      {"Bologna (Acosta)", shared + "/networks/bologna_acosta/acosta_buslanes.net.xml"},
      {"Ingolstadt", shared + "/networks/ingolstadt21/ingolstadt21.net.xml"},
      {"Berlin-Adlershof", "/usr/share/sumo/tools/game/DRT/osm.net.xml"}};
  std::printf(
      "| net | strategy | K | makespan [km] | bound [km] | makespan / bound | "
      "depot bound [km] | makespan / depot bound | total / L1 | balance | coverage [%%] | "
      "planning [s] |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Net& net : nets) {
    if (!only.empty() && std::find(only.begin(), only.end(), net.name) == only.end()) continue;
    const RoadGraph g = RoadGraph::fromSumoNet(SumoNet::read(net.path), /*lscc_only=*/false);
    for (const std::string& strategy : strategies)
      for (const std::string& k : ks) {
        rl::Config cfg;
        cfg.fleet = defaults;
        cfg.fleet.vehicles = std::stoi(k);
        cfg.fleet.strategy = strategy;
        const FleetRoute f = rl::planFleet(g, cfg, {}, seed, net.name);
        std::printf(
            "| %s | %s | %s | %.2f | %.2f | %.3f | %.2f | %.3f | %.3f | %.3f | %.1f | %.2f |\n",
            net.name.c_str(), strategy.c_str(), k.c_str(), f.makespan_m / 1000.0,
            f.lower_bound_m / 1000.0, f.makespan_m / f.lower_bound_m, f.depot_bound_m / 1000.0,
            f.makespan_m / f.depot_bound_m, f.total_length_m / f.single_route_m, f.balance,
            f.edge_coverage_pct, f.planning_seconds);
        std::fflush(stdout);
      }
  }
  return 0;
}
