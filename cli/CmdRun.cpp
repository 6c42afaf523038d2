// `slamroute run`: the whole pipeline on a net (default: the shipped city) and report.md.
// survey -> build-graph (validated against the net) -> plan with each planner -> make each route
// legal for SUMO -> drive each -> evaluate each -> report. SUMO steps run as child processes
// (libsumo: one simulation per process), two at a time on this 2-core target. Each step is
// stamped with what it was run from; --resume keeps the steps done before (pipeline/Resume.hpp).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>

#include "Commands.hpp"
#include "CrewFiles.hpp"
#include "HtmlReport.hpp"
#include "Pipeline.hpp"
#include "Report.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/pipeline/FleetSteps.hpp"
#include "slamroute/pipeline/Stages.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

namespace {

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

struct RunOpts {
  std::string net, out, planners = "qlearning,random,postman,aco-ga", geo_origin;
  int vehicles = 1;  ///< > 1: a fleet too (kFleetId)
  std::string fleet_planner = "partition";
  int jobs = 2;
  int slam_jobs = 0;
  bool save_scans = false, resume = false;
  bool plans_only = false;  ///< stop once the routes are planned and made drivable
  double status_every = 60.0;
};

/// The plan requests of `run`: every planner once; the random walk, when Q-learning is planned
/// too, gets the Q-learning route's length as its budget (paper Table 1 compares routes for the
/// same crew time).
std::vector<pipeline::PlanRequest> planRequests(const std::vector<std::string>& planners) {
  const bool budgeted_random = std::count(planners.begin(), planners.end(), "random") &&
                               std::count(planners.begin(), planners.end(), "qlearning");
  std::vector<pipeline::PlanRequest> out;
  for (const auto& p : planners) {
    pipeline::PlanRequest r;
    r.id = r.planner = p;
    if (budgeted_random && p == "random") r.budget_from = "qlearning";
    out.push_back(r);
  }
  return out;
}

/// The fleet's route, drive and evaluation are named by this id in the run folder.
constexpr const char* kFleetId = "fleet";

/// The single routes' plan requests and, with a fleet, the fleet's.
std::vector<pipeline::PlanRequest> allPlanRequests(const std::vector<std::string>& planners,
                                                   const RunOpts& o) {
  std::vector<pipeline::PlanRequest> out = planRequests(planners);
  if (o.vehicles > 1) {
    pipeline::PlanRequest r;
    r.id = kFleetId;
    r.planner = o.fleet_planner;
    r.vehicles = o.vehicles;
    out.push_back(r);
  }
  return out;
}

/// Legal repair of every route and its crew files (.gpx, .kml, ...); the fleet's routes too, with
/// one set of crew files per vehicle (fleet.vehicle_0.gpx, ...).
void repairRoutes(const Context& ctx, const SumoNet& net, const pipeline::RunLayout& run,
                  const std::vector<std::string>& planners, const RunOpts& o) {
  std::string geo_note;
  for (const auto& p : planners) {
    pipeline::makeRouteDrivable(net, run.route(p));
    geo_note = writeCrewFiles(ctx, net, run.route(p), o.geo_origin);
  }
  if (o.vehicles > 1) {
    pipeline::makeFleetRouteDrivable(net, run.route(kFleetId));
    geo_note = writeFleetCrewFiles(ctx, net, run.route(kFleetId), o.geo_origin);
  }
  if (!geo_note.empty()) logInfo("  note: " + geo_note);
}

/// Every route's drive, the fleet's (one SUMO session) among them, `jobs` at once.
void driveAll(pipeline::StageRunner& stages, const pipeline::ChildOptions& child,
              const pipeline::RunLayout& run, const std::string& net,
              const std::vector<std::string>& planners, const RunOpts& o) {
  std::vector<Step> steps;
  for (const auto& p : planners)
    steps.push_back(pipeline::driveStep(child, run, net, p, o.save_scans));
  if (o.vehicles > 1)
    steps.push_back(pipeline::fleetDriveStep(child, run, net, kFleetId, o.save_scans));
  stages.run(steps, o.jobs);
}

/// Every single drive's SLAM, then the fleet's: its vehicles one after another and the merge.
void evaluateAll(const Context& ctx, pipeline::StageRunner& stages,
                 const pipeline::ChildOptions& child, const pipeline::RunLayout& run,
                 const std::vector<std::string>& planners, const RunOpts& o) {
  if (!planners.empty())
    pipeline::evaluateDrives(stages, child, run, planners, {}, o.slam_jobs,
                             static_cast<int>(planners.size()),
                             ctx.cfg.evaluate.output.keyframe_clouds_on_disk);
  if (o.vehicles > 1) stages.run({pipeline::fleetEvaluateStep(child, run, kFleetId)}, 1);
}

std::string fleetNote(const RunOpts& o) {
  if (o.vehicles < 2) return "";
  return " and a fleet of " + std::to_string(o.vehicles) + " (" + o.fleet_planner + ")";
}

std::string fleetArgs(const RunOpts& o) {
  if (o.vehicles < 2) return "";
  return " --vehicles " + std::to_string(o.vehicles) + " --fleet-planner " + o.fleet_planner;
}

void writeReports(const ReportInputs& in, const std::string& geo_origin) {
  writeReport(in);
  logInfo("report: " + (in.out / "report.md").string());
  try {  // the interactive page is an extra: a run whose page cannot be written still succeeds
    const std::string why = writeHtmlReport(in, geo_origin);
    if (why.empty())
      logInfo("report: " + (in.out / "report.html").string());
    else
      logWarn(why);
  } catch (const std::exception& e) {
    logWarn("report.html not written: " + std::string(e.what()));
  }
}

void runPipeline(Context& ctx, const RunOpts& o) {
  ctx.load();
  const auto t0 = std::chrono::steady_clock::now();
  const std::string net_path = o.net.empty() ? defaultNetPath() : o.net;
  const SumoNet net = SumoNet::read(net_path);  // fail early, one line, on a bad net
  std::string stem = fs::path(net_path).filename().string();
  stem = stem.substr(0, stem.find('.'));
  const pipeline::RunLayout run{
      fs::weakly_canonical(fs::absolute(o.out.empty() ? fs::path("out") / stem : fs::path(o.out)))};
  const auto planners = splitList(o.planners);
  if (planners.empty() && o.vehicles < 2)
    throw std::invalid_argument("run: --planners is empty (and no fleet: --vehicles 1)");
  fs::create_directories(run.logs());
  const std::string net_abs =
      fs::weakly_canonical(fs::absolute(net_path)).string();  // one spelling per file, for --resume
  const pipeline::ChildOptions child = childOptions(ctx);
  pipeline::StageRunner stages(o.resume, o.status_every);

  logInfo("[1/6] survey of " + net_abs);
  stages.run({pipeline::surveyStep(child, run, net_abs)}, 1);
  logInfo("[2/6] road graph from the survey");
  stages.run({pipeline::buildGraphStep(child, run, net_abs)}, 1);
  logInfo("[3/6] planning: " + o.planners + fleetNote(o));
  pipeline::planRoutes(stages, child, run, allPlanRequests(planners, o), o.jobs);
  repairRoutes(ctx, net, run, planners, o);
  if (o.plans_only) {
    logInfo("--plans-only: routes in " + (run.out / "routes").string() +
            "; no drive, SLAM or report");
    return;
  }
  logInfo("[4/6] driving each route in SUMO with traffic");
  driveAll(stages, child, run, net_abs, planners, o);
  logInfo("[5/6] LiDAR SLAM on each drive");
  evaluateAll(ctx, stages, child, run, planners, o);

  logInfo("[6/6] report");
  ReportInputs in;
  in.net = net_abs;
  in.out = run.out;
  in.survey_dir = run.survey();
  in.graph_json = run.graph();
  in.planners = planners;
  if (o.vehicles > 1) in.fleet = kFleetId;
  in.command = "slamroute run --net " + net_abs + " --out " + run.out.string() + " --planners '" +
               o.planners + "'" + fleetArgs(o) + " --seed " + std::to_string(ctx.cfg.seed) +
               (o.resume ? " --resume" : "");
  in.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  in.step_seconds = stages.times();
  writeReports(in, o.geo_origin);
}

}  // namespace

void registerRun(CLI::App& app, Context& ctx) {
  auto o = std::make_shared<RunOpts>();
  auto* sub = app.add_subcommand(
      "run", "The whole pipeline on a net (default: the shipped city) + report.md");
  sub->add_option("--net", o->net,
                  "SUMO network (default: networks/default_city/default_city.net.xml)");
  sub->add_option("--out", o->out, "output folder (default: out/<net name>)");
  sub->add_option("--planners", o->planners, "comma-separated planners to compare")
      ->capture_default_str();
  sub->add_option("--vehicles", o->vehicles,
                  "K > 1: also a fleet of K vehicles sharing the streets, driven in one SUMO "
                  "session, evaluated with its merged map (routes/fleet.json, drives/fleet/, "
                  "eval/fleet/); --planners '' runs the fleet alone")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  sub->add_option("--fleet-planner", o->fleet_planner, "the fleet's planner: partition | postman")
      ->capture_default_str()
      ->check(CLI::IsMember({"partition", "postman"}));
  sub->add_option("--jobs", o->jobs, "steps run at once (each SUMO step is its own process)")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  sub->add_option("--slam-jobs", o->slam_jobs,
                  "SLAM runs at once (0 = one per planner, sharing the cores: the stage ends when "
                  "the total work is done, not when the longest route's queue is; a run peaks at "
                  "~0.7 GB for "
                  "a 15 km drive, 2.8 GB for 75 km; fewer run at once when the memory is short)")
      ->capture_default_str()
      ->check(CLI::Range(0, 64));
  sub->add_option("--geo-origin", o->geo_origin,
                  "LAT,LON: places a net without geo-reference (its centre there) for the routes' "
                  ".gpx / .kml")
      ->check(checkGeoOrigin);
  sub->add_flag("--save-scans", o->save_scans, "keep every LiDAR scan on disk (KITTI .bin; large)");
  sub->add_option("--status-every", o->status_every,
                  "seconds between progress lines of the running steps (0 = only start/finish)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 86400.0));
  sub->add_flag("--plans-only", o->plans_only,
                "stop once the routes are planned and made drivable (survey, graph and routes with "
                "their directed coverage; no drive, SLAM or report)");
  sub->add_flag("--resume", o->resume,
                "keep the steps already done in --out from the same seed, config, net and inputs "
                "(an interrupted run; or delete eval/ to redo only the SLAM); the rest runs again");
  sub->callback([&ctx, o] { runPipeline(ctx, *o); });
}

}  // namespace slamroute::cli
