// runExplore: the online loop, then the measures and DIR (driven.rou.xml, explore.json,
// coverage.png, timing.json), staged and moved in at the end.
#include "slamroute/explore/Explore.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>
#include <sstream>

#include "ExploreRun.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/StagingDir.hpp"
#include "slamroute/evaluate/Output.hpp"
#include "slamroute/explore/Measures.hpp"

namespace slamroute::explore {
namespace {

constexpr const char* kSummary = "explore.json";

std::string routesXml(const ExploreResult& r) {
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<routes>\n";
  for (const VehicleResult& v : r.vehicles) {
    os << "  <vehicle id=\"" << v.id << "\" depart=\"" << v.depart_s << "\">\n    <route edges=\"";
    for (std::size_t i = 0; i < v.edges.size(); ++i) os << (i ? " " : "") << v.edges[i];
    os << "\"/>\n  </vehicle>\n";
  }
  os << "</routes>\n";
  return os.str();
}

nlohmann::json milestoneJson(const Milestone& m, double bound_m) {
  nlohmann::json j = {{"share", m.share}, {"reached", m.reached}};
  if (!m.reached) return j;
  j["time_s"] = m.time_s;
  j["fleet_distance_m"] = m.fleet_distance_m;
  j["vehicle_distance_m"] = m.vehicle_distance_m;
  j["fleet_distance_over_bound"] = bound_m > 0 ? m.fleet_distance_m / bound_m : 0.0;
  return j;
}

nlohmann::json summaryJson(const ExploreOptions& o, const ExploreResult& r,
                           const std::string& map_poses) {
  nlohmann::json j = {{"net", o.net.string()},
                      {"strategy", r.strategy},
                      {"vehicles", o.vehicles},
                      {"seed", o.seed},
                      {"map_poses", map_poses},
                      {"directed_streets", r.total_edges},
                      {"streets_driven", r.edges_driven},
                      {"end_time_s", r.end_time_s},
                      {"time_limit_hit", r.time_limit_hit},
                      {"decisions", r.decisions},
                      {"offline_bound_m", r.offline_bound_m},
                      {"offline_makespan_m", r.offline_makespan_m},
                      {"streets_known", r.streets_known},
                      {"grid_cells_known", r.grid_cells_known}};
  for (const Milestone& m : r.milestones)
    j["milestones"].push_back(milestoneJson(m, r.offline_bound_m));
  for (const VehicleResult& v : r.vehicles)
    j["per_vehicle"].push_back({{"id", v.id},
                                {"depart_s", v.depart_s},
                                {"distance_m", v.distance_m},
                                {"streets", v.edges.size()},
                                {"decisions", v.decisions}});
  for (const CoverageSample& c : r.curve)
    j["curve"].push_back({c.time_s, c.fleet_distance_m, c.edges_driven});
  return j;
}

nlohmann::json timingJson(const ExploreResult& r) {
  std::vector<double> ms = r.decision_ms;
  std::sort(ms.begin(), ms.end());
  const double sum = std::accumulate(ms.begin(), ms.end(), 0.0);
  return {{"decisions", ms.size()},
          {"mean_ms", ms.empty() ? 0.0 : sum / static_cast<double>(ms.size())},
          {"median_ms", ms.empty() ? 0.0 : ms[ms.size() / 2]},
          {"max_ms", ms.empty() ? 0.0 : ms.back()}};
}

void writeCoveragePlot(const std::filesystem::path& path, const ExploreResult& r) {
  std::vector<double> t = {0.0}, share = {0.0};
  for (const CoverageSample& c : r.curve) {
    t.push_back(c.time_s);
    share.push_back(100.0 * c.edges_driven / std::max(1, r.total_edges));
  }
  evaluate::plotCurve(path, t, share,
                      "directed streets driven [%] vs simulated time [s] (" + r.strategy + ", " +
                          std::to_string(r.vehicles.size()) + " vehicles)",
                      900, 100.0);
}

}  // namespace

ExploreResult runExplore(const ExploreOptions& opts, const Config& cfg,
                         const simulate::WorldConfig& world, const simulate::DriveConfig& drive) {
  cfg.validate();
  StagingDir staging(opts.out_dir, kSummary);
  ExploreRun run(opts, cfg, world, drive);
  ExploreResult r = run.run();
  for (double share : {0.90, 0.95, 1.0})
    r.milestones.push_back(milestoneAt(r.curve, r.total_edges, share));
  const OfflineBound bound = run.offlineBound();
  r.offline_bound_m = bound.total_m;
  r.offline_makespan_m = bound.makespan_m;
  const auto& dir = staging.path();
  writeFileAtomic(dir / "driven.rou.xml", routesXml(r));
  writeFileAtomic(dir / kSummary, summaryJson(opts, r, cfg.map_poses).dump(2) + "\n");
  writeFileAtomic(dir / "timing.json", timingJson(r).dump(2) + "\n");
  writeCoveragePlot(dir / "coverage.png", r);
  staging.commit();
  logInfo("explore: " + std::to_string(r.edges_driven) + "/" + std::to_string(r.total_edges) +
          " directed streets driven in " + std::to_string(static_cast<int>(r.end_time_s)) + " s");
  return r;
}

}  // namespace slamroute::explore
