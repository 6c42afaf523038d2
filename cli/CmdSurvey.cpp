// `slamroute survey --net NET --out DIR`: SUMO vehicles cover the net; traces + depth frames
// (simulate/Survey.hpp).
#include <cstdio>
#include <iostream>

#include "Commands.hpp"
#include "slamroute/simulate/Survey.hpp"

namespace slamroute::cli {

void registerSurvey(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string net, out;
    double noise = -1.0, spacing = -1.0;
  };
  auto o = std::make_shared<Opts>();
  auto* sub = app.add_subcommand(
      "survey", "Drive vehicles over a net in SUMO, record traces and depth frames");
  sub->add_option("--net", o->net, "SUMO network (.net.xml); default: the shipped default city");
  sub->add_option("--out", o->out, "survey folder to write")->required();
  sub->add_option("--noise", o->noise,
                  "GPS-like trace noise sigma [m] (overrides simulate.survey.noise_sigma_m)");
  sub->add_option("--depth-spacing", o->spacing,
                  "metres between depth frames per vehicle, 0 = none "
                  "(overrides simulate.survey.depth_spacing_m)");
  sub->callback([&ctx, o] {
    ctx.load();
    simulate::Config cfg = ctx.cfg.simulate;
    if (o->noise >= 0.0) cfg.survey.noise_sigma_m = o->noise;
    if (o->spacing >= 0.0) cfg.survey.depth_spacing_m = o->spacing;
    simulate::SurveyOptions s;
    s.net = o->net.empty() ? defaultNetPath() : o->net;
    s.out_dir = o->out;
    s.seed = ctx.cfg.seed;
    const simulate::SurveyResult r = simulate::runSurvey(s, cfg);
    char line[320];
    std::snprintf(line, sizeof line,
                  "survey: %zu survey + %zu background vehicles, %zu trace rows, %zu depth "
                  "frames, %.1f MB, %.0f s simulated, %.1f s wall\n"
                  "coverage: %zu of %zu drivable edges visited (%.1f%%)",
                  r.survey_vehicles, r.background_vehicles, r.trace_rows, r.depth_frames,
                  static_cast<double>(r.bytes_written) / 1e6, r.sim_seconds, r.wall_seconds,
                  r.visited_edges, r.drivable_edges, r.coverage_pct);
    std::cout << line << "\n"
              << "wrote " << r.out_dir.string() << "\n";
  });
}

}  // namespace slamroute::cli
