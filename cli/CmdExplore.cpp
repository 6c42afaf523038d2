// `slamroute explore --net NET --vehicles K --strategy S --out DIR [--start E1,E2,...]`:
// K vehicles explore a net they do not know, online in SUMO (explore/Explore.hpp).
#include <cstdio>
#include <iostream>

#include "Commands.hpp"
#include "slamroute/explore/Explore.hpp"
#include "slamroute/explore/Strategies.hpp"

namespace slamroute::cli {

void registerExplore(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string net, strategy = "nearest", out;
    int vehicles = 1;
    std::vector<std::string> start;
  };
  auto o = std::make_shared<Opts>();
  auto* sub = app.add_subcommand(
      "explore", "Explore an unknown net online with K vehicles (frontiers, GP, fleet, SIBA)");
  sub->add_option("--net", o->net, "SUMO network (.net.xml); default: the shipped default city");
  sub->add_option("--vehicles", o->vehicles, "number of vehicles K")->check(CLI::Range(1, 64));
  sub->add_option("--strategy", o->strategy, "nearest | gp-frontier | fleet | central | siba")
      ->check(CLI::IsMember(explore::strategyNames()));
  sub->add_option("--start", o->start, "start edge per vehicle (SUMO ids, comma separated)")
      ->delimiter(',');
  sub->add_option("--out", o->out, "output folder")->required();
  sub->callback([&ctx, o] {
    ctx.load();
    explore::ExploreOptions e;
    e.net = o->net.empty() ? defaultNetPath() : o->net;
    e.vehicles = o->vehicles;
    e.strategy = o->strategy;
    e.out_dir = o->out;
    e.start_edges = o->start;
    e.seed = ctx.cfg.seed;
    const explore::ExploreResult r =
        explore::runExplore(e, ctx.cfg.explore, ctx.cfg.simulate.world, ctx.cfg.simulate.drive);
    for (const explore::Milestone& m : r.milestones) {
      char line[200];
      if (m.reached)
        std::snprintf(line, sizeof line,
                      "%3.0f %%: %.0f s, %.0f m (%.2f x the offline fleet bound)", 100 * m.share,
                      m.time_s, m.fleet_distance_m, m.fleet_distance_m / r.offline_bound_m);
      else
        std::snprintf(line, sizeof line, "%3.0f %%: not reached", 100 * m.share);
      std::cout << line << "\n";
    }
    std::cout << "wrote " << e.out_dir.string() << "\n";
  });
}

}  // namespace slamroute::cli
