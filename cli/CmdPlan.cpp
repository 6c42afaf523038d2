// `slamroute plan (--graph GRAPH.json | --net NET) --planner P --out ROUTE.json`: paper §3.2 and
// the baseline planners. With --net (or when the graph's edges carry SUMO edges) it also writes
// ROUTE.rou.xml next to ROUTE.json.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "Commands.hpp"
#include "CrewFiles.hpp"
#include "PlanFleet.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoCoverage.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/export/ExportFleet.hpp"
#include "slamroute/export/ExportRoute.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::cli {

namespace {

/// --start-junction: the node of a SUMO junction id.
int nodeOfJunction(const RoadGraph& g, const std::string& junction) {
  for (const auto& n : g.nodes)
    if (n.sumo_junction == junction) return n.id;
  throw std::invalid_argument("--start-junction: no node for SUMO junction '" + junction + "'");
}

/// OUT and, when the route has SUMO edges, OUT.rou.xml, replaced together: an older OUT.rou.xml
/// (or crew files, or a former fleet's vehicle files) never stays beside a route it does not
/// belong to. Returns the .rou.xml written
/// (or empty).
std::filesystem::path writeRouteFiles(const Route& r, const std::filesystem::path& out) {
  std::filesystem::path rou = out;
  rou.replace_extension(".rou.xml");
  AtomicFileSet files;
  r.writeJson(files.staged(out));
  for (const auto& old : exports::existingVehicleFiles(out)) files.dropAtCommit(old);
  if (r.sumo_edges.empty()) {
    files.dropAtCommit(rou);
    for (const auto& crew : exports::crewFilePaths(out)) files.dropAtCommit(crew);
    rou.clear();
  } else {
    r.writeRouXml(files.staged(rou));
  }
  files.commit();
  return rou;
}

struct PlanOpts {
  std::string graph, net, planner, out, start_junction, reward, goal, geo_origin;
  int start = -1;
  double max_length_m = -1.0;
  FleetPlanOptions fleet;
};

void addPlanOptions(CLI::App* sub, PlanOpts& o) {
  auto* g_opt = sub->add_option("--graph", o.graph, "road graph (graph.json)");
  auto* n_opt =
      sub->add_option("--net", o.net, "SUMO network (.net.xml[.gz]); also writes .rou.xml");
  g_opt->excludes(n_opt);
  sub->add_option("--planner", o.planner,
                  "qlearning | random | tsp | postman | aco-ga | open-loop | exhaustive-revisit | "
                  "switching | partition (fleet only) (default: rl.planner)");
  sub->add_option("--vehicles", o.fleet.vehicles,
                  "K vehicles share the streets (postman or partition; default: rl.fleet.vehicles)")
      ->check(CLI::Range(1, 1000));
  auto* d_opt = sub->add_option("--depot", o.fleet.depot,
                                "fleet: SUMO edge every vehicle leaves from and returns to");
  sub->add_option("--depots", o.fleet.depots, "fleet: one depot SUMO edge per vehicle, E1,E2,..")
      ->excludes(d_opt);
  sub->add_option("--out", o.out, "output route (route.json)")->required();
  auto* s_opt = sub->add_option("--start", o.start, "start node id (default: rl.start_node)");
  sub->add_option("--start-junction", o.start_junction, "start at the node of this SUMO junction")
      ->excludes(s_opt);
  sub->add_option("--reward", o.reward, "qlearning reward: full | accuracy (default: rl.reward)");
  sub->add_option("--goal", o.goal, "coverage goal: nodes | edges (default: rl.goal)");
  sub->add_option("--geo-origin", o.geo_origin,
                  "LAT,LON: with --net, places a net without geo-reference (its centre there) for "
                  "ROUTE.gpx / ROUTE.kml")
      ->check(checkGeoOrigin);
  sub->add_option("--max-length", o.max_length_m,
                  "random: stop at this driven length [m] (default: rl.random.budget_m)")
      ->check(CLI::NonNegativeNumber);
}

/// rl config with the command line's overrides (the start node comes with the graph).
rl::Config planConfig(const Context& ctx, const PlanOpts& o) {
  rl::Config cfg = ctx.cfg.rl;
  if (!o.planner.empty()) cfg.planner = o.planner;
  if (!o.reward.empty()) cfg.reward = o.reward;
  if (!o.goal.empty()) cfg.goal = o.goal;
  if (o.max_length_m >= 0.0) cfg.random.budget_m = o.max_length_m;
  return cfg;
}

/// The graph to plan on: read from --graph, or the whole --net (kept in `net`); `where` names it.
RoadGraph planGraph(const PlanOpts& o, std::optional<SumoNet>& net, std::string& where) {
  if (o.net.empty()) {
    where = o.graph;
    return RoadGraph::readJson(o.graph);
  }
  net = SumoNet::read(o.net);
  where = o.net;
  return RoadGraph::fromSumoNet(*net, /*lscc_only=*/false);
}

/// Directed SUMO coverage first (when the net is known), then the two-way graph figure.
std::string coverageText(const Route& r) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(1);
  if (r.sumo_coverage)
    os << "directed SUMO edges " << r.sumo_coverage->edges_pct << " % (length "
       << r.sumo_coverage->length_pct << " %), " << r.sumo_coverage->routeLengthM() / 1000.0
       << " km in SUMO, ";
  os << "two-way graph coverage " << r.edge_coverage_pct << " %";
  return os.str();
}

void printPlanSummary(const Route& r, const std::filesystem::path& out,
                      const std::filesystem::path& rou) {
  const auto extra = nlohmann::json::parse(r.extra_json);
  std::cout << std::fixed << std::setprecision(1) << r.planner << ": " << r.edges.size()
            << " edges, " << r.length_m / 1000.0 << " km, node coverage " << r.node_coverage_pct
            << " %, " << coverageText(r) << ", " << r.loop_closures
            << " loop closures, illegal turns " << extra.value("illegal_turns", 0) << ", "
            << std::setprecision(2) << r.planning_seconds << " s"
            << (r.completed_by_shortest_paths ? " (completed by shortest paths)" : "") << "\n"
            << "wrote " << out.string() << (rou.empty() ? "" : " and " + rou.string()) << "\n";
  if (const int n = extra.value("edges_without_sumo", 0); n > 0 && !rou.empty())
    std::cout << n << " route edge(s) have no SUMO edges (links SUMO models inside junctions); "
              << "`drive` joins their neighbours by legal SUMO paths\n";
}

void runPlan(Context& ctx, const PlanOpts& o) {
  ctx.load();
  if (o.graph.empty() && o.net.empty())
    throw std::invalid_argument("plan: give --graph GRAPH.json or --net NET");
  rl::Config cfg = planConfig(ctx, o);
  std::string where;
  std::optional<SumoNet> net;
  const RoadGraph g = planGraph(o, net, where);
  if (o.start >= 0) cfg.start_node = o.start;
  if (!o.start_junction.empty()) cfg.start_node = nodeOfJunction(g, o.start_junction);
  const std::filesystem::path out(o.out);
  if (isFleetRequest(cfg, o.fleet)) {
    FleetPlanOptions fleet = o.fleet;
    fleet.geo_origin = o.geo_origin;
    return planFleetCommand(ctx, g, cfg, fleet, where, out, net ? &*net : nullptr);
  }
  Route r = rl::plan(g, cfg, ctx.cfg.seed, where);
  if (r.sumo_edges.empty() && !o.net.empty())
    throw std::runtime_error("plan: the route has no SUMO edges; cannot write the .rou.xml");
  if (net) r.sumo_coverage = sumoCoverage(*net, r.sumo_edges);
  const std::filesystem::path rou = writeRouteFiles(r, out);
  printPlanSummary(r, out, rou);
  if (net)
    if (const std::string note = writeCrewFiles(ctx, *net, out, o.geo_origin); !note.empty())
      logInfo("note: " + note);
}

}  // namespace

void registerPlan(CLI::App& app, Context& ctx) {
  auto o = std::make_shared<PlanOpts>();
  auto* sub = app.add_subcommand("plan", "Plan a mapping route on a graph or net (paper 3.2)");
  addPlanOptions(sub, *o);
  sub->callback([&ctx, o] { runPlan(ctx, *o); });
}

}  // namespace slamroute::cli
