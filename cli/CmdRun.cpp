// `slamroute run`: the whole pipeline on a net (default: the shipped city) and report.md.
// survey -> build-graph (validated against the net) -> plan with each planner -> make each route
// legal for SUMO -> drive each -> evaluate each -> report. SUMO steps run as child processes
// (libsumo: one simulation per process), two at a time on this 2-core target. Each step is
// stamped with what it was run from; --resume keeps the steps done before (Resume.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "Commands.hpp"
#include "CrewFiles.hpp"
#include "HtmlReport.hpp"
#include "Pipeline.hpp"
#include "Report.hpp"
#include "Resume.hpp"
#include "Subprocess.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/core/SumoNet.hpp"

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

}  // namespace

void registerRun(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string net, out, planners = "qlearning,random,postman", geo_origin;
    int jobs = 2;
    int slam_jobs = 0;
    bool save_scans = false, resume = false;
    double status_every = 60.0;
  };
  auto o = std::make_shared<Opts>();
  auto* sub = app.add_subcommand("run", "The whole pipeline on a net (default: the shipped city) + report.md");
  sub->add_option("--net", o->net, "SUMO network (default: networks/default_city/default_city.net.xml)");
  sub->add_option("--out", o->out, "output folder (default: out/<net name>)");
  sub->add_option("--planners", o->planners, "comma-separated planners to compare")->capture_default_str();
  sub->add_option("--jobs", o->jobs, "steps run at once (each SUMO step is its own process)")
      ->capture_default_str()->check(CLI::Range(1, 64));
  sub->add_option("--slam-jobs", o->slam_jobs,
                  "SLAM runs at once (0 = one per planner, sharing the cores: the stage ends when "
                  "the total work is done, not when the longest route's queue is; a run peaks at ~0.7 GB for "
                  "a 15 km drive, 2.8 GB for 75 km; fewer run at once when the memory is short)")
      ->capture_default_str()->check(CLI::Range(0, 64));
  sub->add_option("--geo-origin", o->geo_origin,
                  "LAT,LON: places a net without geo-reference (its centre there) for the routes' "
                  ".gpx / .kml")
      ->check(checkGeoOrigin);
  sub->add_flag("--save-scans", o->save_scans, "keep every LiDAR scan on disk (KITTI .bin; large)");
  sub->add_option("--status-every", o->status_every,
                  "seconds between progress lines of the running steps (0 = only start/finish)")
      ->capture_default_str()->check(CLI::Range(0.0, 86400.0));
  sub->add_flag("--resume", o->resume,
                "keep the steps already done in --out from the same seed, config, net and inputs "
                "(an interrupted run; or delete eval/ to redo only the SLAM); the rest runs again");
  sub->callback([&ctx, o] {
    ctx.load();
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const std::string net_path = o->net.empty() ? defaultNetPath() : o->net;
    const SumoNet net = SumoNet::read(net_path);  // fail early, one line, on a bad net
    std::string stem = fs::path(net_path).filename().string();
    stem = stem.substr(0, stem.find('.'));
    const fs::path out = fs::weakly_canonical(fs::absolute(o->out.empty() ? fs::path("out") / stem : fs::path(o->out)));
    const auto planners = splitList(o->planners);
    if (planners.empty()) throw std::invalid_argument("run: --planners is empty");
    fs::create_directories(out / "logs");
    const std::string net_abs = fs::weakly_canonical(fs::absolute(net_path)).string();  // one spelling per file, for --resume
    std::vector<std::pair<std::string, double>> times;  // NaN: kept from an earlier run
    // Runs a stage: every step is stamped; with --resume, those done before are kept.
    auto stage = [&](const std::vector<Step>& steps, int jobs) {
      const std::vector<Step> todo = stepsToRun(steps, o->resume);
      const std::vector<StepResult> res = runSteps(todo, jobs, o->status_every);
      for (const auto& st : steps) {
        double sec = std::nan("");
        for (std::size_t i = 0; i < todo.size(); ++i)
          if (todo[i].label == st.label) sec = res[i].seconds;
        times.emplace_back(st.label, sec);
      }
    };

    logInfo("[1/6] survey of " + net_abs);
    std::vector<Step> s1{childStep(ctx, "survey", {"survey", "--net", net_abs, "--out", (out / "survey").string()},
                              out / "logs" / "survey.log")};
    s1[0].output = out / "survey" / "survey.json";  // the folder appears complete
    stage(s1, 1);

    logInfo("[2/6] road graph from the survey");
    const fs::path graph = out / "graph" / "graph.json";
    std::vector<Step> s2{childStep(ctx, "build-graph",
                              {"build-graph", "--survey", (out / "survey").string(), "--net", net_abs,
                               "--out", graph.string()},
                              out / "logs" / "build-graph.log")};
    s2[0].output = fs::path(graph).replace_extension(".png");  // the last of graph.json's siblings
    stage(s2, 1);

    logInfo("[3/6] planning: " + o->planners);
    // The random route gets the Q-learning route's length as its budget (paper Table 1 compares
    // routes for the same crew time), so it is planned after the others.
    auto planStep = [&](const std::string& p, std::vector<std::string> extra) {
      std::vector<std::string> a{"plan", "--graph", graph.string(), "--planner", p, "--out",
                                 (out / "routes" / (p + ".json")).string()};
      a.insert(a.end(), extra.begin(), extra.end());
      Step st = childStep(ctx, "plan " + p, a, out / "logs" / ("plan-" + p + ".log"));
      st.output = out / "routes" / (p + ".json");
      return st;
    };
    const bool budgeted_random =
        std::count(planners.begin(), planners.end(), "random") && std::count(planners.begin(), planners.end(), "qlearning");
    std::vector<Step> s3;
    for (const auto& p : planners)
      if (!(budgeted_random && p == "random")) s3.push_back(planStep(p, {}));
    stage(s3, o->jobs);
    if (budgeted_random) {
      const double budget = routeLength(out / "routes" / "qlearning.json");
      stage({planStep("random", {"--max-length", std::to_string(budget)})}, 1);
    }
    std::string geo_note;
    for (const auto& p : planners) {
      makeRouteDrivable(net, out / "routes" / (p + ".json"));
      geo_note = writeCrewFiles(ctx, net, out / "routes" / (p + ".json"), o->geo_origin);
    }
    if (!geo_note.empty()) logInfo("  note: " + geo_note);

    logInfo("[4/6] driving each route in SUMO with traffic");
    std::vector<Step> s4;
    for (const auto& p : planners) {
      std::vector<std::string> a{"drive", "--net", net_abs, "--route", (out / "routes" / (p + ".json")).string(),
                                 "--out", (out / "drives" / p).string()};
      if (o->save_scans) a.push_back("--save-scans");
      s4.push_back(childStep(ctx, "drive " + p, a, out / "logs" / ("drive-" + p + ".log")));
      s4.back().output = out / "drives" / p / "drive.json";  // the folder appears complete
    }
    stage(s4, o->jobs);

    logInfo("[5/6] LiDAR SLAM on each drive");
    // Longest route first: with two evaluations at a time the last one to start is then the
    // shortest, and the run ends soonest.
    std::vector<std::pair<double, std::string>> by_length;
    for (const auto& p : planners)
      by_length.emplace_back(-Route::readJson(out / "routes" / (p + ".json")).length_m, p);
    std::stable_sort(by_length.begin(), by_length.end());
    std::vector<Step> s5;
    for (const auto& [neg_len, p] : by_length) {
      s5.push_back(childStep(ctx, "evaluate " + p,
                        {"evaluate", "--drive", (out / "drives" / p).string(), "--out", (out / "eval" / p).string()},
                        out / "logs" / ("evaluate-" + p + ".log")));
      s5.back().output = out / "eval" / p / "metrics.json";  // written last
    }
    // One SLAM run per planner by default, as many as the memory holds (a 75 km drive's SLAM
    // peaks at 2.8 GB): the longest routes may run together only if their estimates fit.
    std::vector<double> lengths;
    for (const auto& [neg_len, p] : by_length) lengths.push_back(-neg_len);
    std::string mem;
    const int fit = slamJobsThatFit(lengths, static_cast<int>(s5.size()), ctx.cfg.evaluate.output.keyframe_clouds_on_disk, &mem);
    if (o->slam_jobs > fit)
      logWarn("--slam-jobs " + std::to_string(o->slam_jobs) + " may exceed the memory (" + mem + ")");
    else if (o->slam_jobs == 0 && fit < static_cast<int>(s5.size()))
      logInfo("  " + std::to_string(fit) + " SLAM run(s) at once to fit the memory (" + mem + ")");
    stage(s5, o->slam_jobs > 0 ? o->slam_jobs : fit);

    logInfo("[6/6] report");
    ReportInputs in;
    in.net = net_abs;
    in.out = out;
    in.survey_dir = out / "survey";
    in.graph_json = graph;
    in.planners = planners;
    in.command = "slamroute run --net " + net_abs + " --out " + out.string() + " --planners " + o->planners +
                 " --seed " + std::to_string(ctx.cfg.seed) + (o->resume ? " --resume" : "");
    in.total_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    in.step_seconds = times;
    writeReport(in);
    logInfo("report: " + (out / "report.md").string());
    try {  // the interactive page is an extra: a run whose page cannot be written still succeeds
      const std::string why = writeHtmlReport(in, o->geo_origin);
      if (why.empty()) logInfo("report: " + (out / "report.html").string());
      else logWarn(why);
    } catch (const std::exception& e) {
      logWarn("report.html not written: " + std::string(e.what()));
    }
  });
}

}  // namespace slamroute::cli
