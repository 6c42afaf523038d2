#include "Pipeline.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

#include "slamroute/core/Log.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/SumoRoute.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

Step childStep(const Context& ctx, const std::string& label, std::vector<std::string> args,
               const fs::path& log, long long seed) {
  std::vector<std::string> full{"--seed", std::to_string(seed >= 0 ? static_cast<std::uint64_t>(seed) : ctx.cfg.seed),
                                "--log-level", ctx.log_level == "debug" ? "debug" : "info"};
  if (!ctx.config_file.empty()) {
    full.push_back("--config");
    full.push_back(fs::weakly_canonical(fs::absolute(ctx.config_file)).string());
  }
  full.insert(full.end(), args.begin(), args.end());
  return {label, full, log};
}

double routeLength(const fs::path& route_json) { return Route::readJson(route_json).length_m; }

double slamMemoryGb(double route_km, bool clouds_on_disk) {
  return 0.3 + (clouds_on_disk ? 0.008 : 0.04) * std::max(0.0, route_km);
}

double availableMemoryGb() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kb = 0.0;
  while (in >> key >> kb) {
    std::getline(in, unit);
    if (key == "MemAvailable:") return kb * 1024.0 / 1e9;  // the kernel's kB are KiB
  }
  return 0.0;
}

int slamJobsForMemory(std::vector<double> need_gb, double budget_gb, int max_jobs) {
  const int cap = std::max(1, std::min(max_jobs, static_cast<int>(need_gb.size())));
  if (!(budget_gb > 0.0)) return cap;
  std::sort(need_gb.begin(), need_gb.end(), std::greater<>());
  double sum = 0.0;
  int k = 0;
  while (k < cap && sum + need_gb[static_cast<std::size_t>(k)] <= budget_gb) sum += need_gb[static_cast<std::size_t>(k++)];
  return std::max(1, k);
}

int slamJobsThatFit(const std::vector<double>& route_m, int max_jobs, bool clouds_on_disk, std::string* why) {
  std::vector<double> need;
  for (double m : route_m) need.push_back(slamMemoryGb(m / 1000.0, clouds_on_disk));
  const double avail = availableMemoryGb();
  if (why && !need.empty()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "largest SLAM estimated at %.1f GB, %.1f GB available",
                  *std::max_element(need.begin(), need.end()), avail);
    *why = buf;
  }
  return slamJobsForMemory(std::move(need), 0.9 * avail, max_jobs);
}

void makeRouteDrivable(const SumoNet& net, const fs::path& route_json) {
  Route r = Route::readJson(route_json);
  if (r.sumo_edges.empty())
    throw std::runtime_error(route_json.string() + ": route has no SUMO edges (graph not matched to the net?)");
  const LegalRoute legal = legalizeSumoRoute(net, r.sumo_edges);
  if (legal.repaired_transitions > 0 || legal.dropped_edges > 0) {
    std::ostringstream note;
    note << (r.notes.empty() ? "" : r.notes + "; ") << "SUMO route: " << legal.repaired_transitions
         << " transitions joined by legal detours (+" << static_cast<int>(legal.added_length_m) << " m)";
    if (legal.dropped_edges > 0) note << ", " << legal.dropped_edges << " edges no legal path passes dropped";
    r.notes = note.str();
    r.sumo_edges = legal.edges;
    r.writeJson(route_json);
  }
  fs::path rou = route_json;
  rou.replace_extension(".rou.xml");
  r.writeRouXml(rou);
}

}  // namespace slamroute::cli
