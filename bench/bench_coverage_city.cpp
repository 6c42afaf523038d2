// The coverage planners on a whole city against the postman route: directed coverage of the net's
// SUMO edges (core/SumoCoverage.hpp), length as SUMO drives it / the postman's, predicted C_k
// against the bound, planning time; mean +- sd over seeds (bench/RESULTS.md).
//   bench_coverage_city [--net NET] [--seeds N] [--threshold M2] [--planners a,b,..]
// Default: the shipped city, 5 seeds, rl.coverage's default bound, postman and aco-ga.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "slamroute/core/Log.hpp"
#include "slamroute/core/SumoCoverage.hpp"
#include "slamroute/pipeline/Statistics.hpp"
#include "slamroute/rl/Planners.hpp"

using namespace slamroute;

namespace {

struct Options {
  std::string net =
      std::string(SLAMROUTE_SOURCE_DIR) + "/networks/default_city/default_city.net.xml";
  int seeds = 5;
  double threshold_m2 = rl::CoverageConfig{}.c_threshold_m2;
  std::vector<std::string> planners = {"postman", "aco-ga"};
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--net")
      o.net = v;
    else if (k == "--seeds")
      o.seeds = std::stoi(v);
    else if (k == "--threshold")
      o.threshold_m2 = std::stod(v);
    else if (k == "--planners") {
      o.planners.clear();
      std::stringstream ss(v);
      for (std::string p; std::getline(ss, p, ',');) o.planners.push_back(p);
    }
  }
  return o;
}

struct Row {
  std::vector<double> directed, sumo_km, ratio, c_max, c_avg, revisits, seconds;
  int kept = 0;
};

std::string ms(const std::vector<double>& v, int decimals) {
  return pipeline::formatMeanSd(pipeline::meanSd(v), decimals);
}

}  // namespace

int main(int argc, char** argv) {
  setLogLevel(LogLevel::Warn);
  const Options o = parse(argc, argv);
  const SumoNet net = SumoNet::read(o.net);
  const RoadGraph g = RoadGraph::fromSumoNet(net, /*lscc_only=*/false);
  std::printf("net %s, bound C_threshold = %.1f m^2, %d seeds\n\n", o.net.c_str(), o.threshold_m2,
              o.seeds);
  std::printf(
      "| planner | directed SUMO edges [%%] | length in SUMO [km] | / postman | C_max [m^2] | "
      "C_average [m^2] | bound kept | revisits | planning [s] "
      "|\n|---|---|---|---|---|---|---|---|---|\n");
  rl::Config ref;
  ref.planner = "postman";
  const double postman_km =
      sumoCoverage(net, rl::plan(g, ref, 1, o.net).sumo_edges).routeLengthM() / 1000.0;
  for (const auto& p : o.planners) {
    Row row;
    for (int seed = 1; seed <= o.seeds; ++seed) {
      rl::Config cfg;
      cfg.planner = p;
      cfg.coverage.c_threshold_m2 = o.threshold_m2;
      const Route r = rl::plan(g, cfg, static_cast<std::uint64_t>(seed), o.net);
      const SumoCoverage c = sumoCoverage(net, r.sumo_edges);
      const auto u = nlohmann::json::parse(r.extra_json)["uncertainty"];
      const double km = c.routeLengthM() / 1000.0;
      row.directed.push_back(c.edges_pct);
      row.sumo_km.push_back(km);
      row.ratio.push_back(km / postman_km);
      row.c_max.push_back(u["c_max_m2"].get<double>());
      row.c_avg.push_back(u["c_average_m2"].get<double>());
      row.revisits.push_back(nlohmann::json::parse(r.extra_json).value("loop_closure_revisits", 0));
      row.seconds.push_back(r.planning_seconds);
      row.kept += u["bound_satisfied"].get<bool>() ? 1 : 0;
    }
    std::printf("| %s | %s | %s | %s | %s | %s | %d / %d | %s | %s |\n", p.c_str(),
                ms(row.directed, 1).c_str(), ms(row.sumo_km, 2).c_str(), ms(row.ratio, 3).c_str(),
                ms(row.c_max, 1).c_str(), ms(row.c_avg, 1).c_str(), row.kept, o.seeds,
                ms(row.revisits, 1).c_str(), ms(row.seconds, 2).c_str());
  }
  return 0;
}
