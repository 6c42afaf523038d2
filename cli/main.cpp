// slamroute: plans the drives of mapping vehicles through cities. See README.md.
#include <CLI/CLI.hpp>

#include <iostream>

#include "Commands.hpp"
#include "Subprocess.hpp"
#include "slamroute/core/Log.hpp"

int main(int argc, char** argv) {
  using namespace slamroute;
  CLI::App app{"slamroute: plan, drive and evaluate LiDAR mapping routes through cities"};
  app.set_version_flag("--version", std::string("slamroute ") + SLAMROUTE_VERSION);
  app.require_subcommand(1);
  app.fallthrough();
  cli::Context ctx;
  app.add_option("--config", ctx.config_file, "YAML config file (see `slamroute config --dump`)");
  app.add_option("--seed", ctx.seed, "random seed (same seed, same output)");
  app.add_option("--log-level", ctx.log_level, "debug|info|warn|error|quiet")
      ->check(CLI::IsMember({"debug", "info", "warn", "error", "quiet"}));

  cli::registerNetworkInfo(app, ctx);
  cli::registerConfig(app, ctx);
  cli::registerSurvey(app, ctx);
  cli::registerBuildGraph(app, ctx);
  cli::registerPlan(app, ctx);
  cli::registerDrive(app, ctx);
  cli::registerEvaluate(app, ctx);
  cli::registerCompare(app, ctx);
  cli::registerRun(app, ctx);
  cli::registerExperiment(app, ctx);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const cli::Interrupted& e) {
    std::cerr << "slamroute: " << e.what() << "\n";
    return 128 + e.signal;
  } catch (const cli::NotImplemented& e) {
    std::cerr << "slamroute: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "slamroute: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
