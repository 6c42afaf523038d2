// `slamroute config --dump`: the full default configuration as YAML.
#include <iostream>

#include "Commands.hpp"
#include "slamroute/core/ConfigIO.hpp"

namespace slamroute::cli {

void registerConfig(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("config", "Show the configuration (defaults are the paper's)");
  auto dump = std::make_shared<bool>(false);
  sub->add_flag("--dump", *dump, "print the full configuration as YAML (with --config applied)");
  sub->callback([&ctx, dump] {
    ctx.load();
    if (!*dump) throw std::invalid_argument("config: nothing to do (try --dump)");
    std::cout << "# slamroute configuration; pass an edited copy with --config FILE.yaml\n"
              << config::dumpYaml(ctx.cfg);
  });
}

}  // namespace slamroute::cli
