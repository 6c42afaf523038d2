// slamroute: plans the drives of mapping vehicles through cities. See README.md.
#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <string>

#include "Commands.hpp"
#include "Subprocess.hpp"
#include "slamroute/core/Log.hpp"

namespace {

/// --seed: a whole number that fits 64 bits; CLI11 alone turns "-1" and 2^64 into 2^64-1.
std::string checkSeed(std::string& text) {
  std::uint64_t v = 0;
  const char* end = text.data() + text.size();
  const auto [p, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || p != end)
    return "'" + text + "' is not a whole number from 0 to 18446744073709551615";
  return "";
}

/// The first word that is not an option or a global option's value: the command. CLI11 reports
/// an unknown one as "A subcommand is required", which names nothing.
void checkCommandName(const CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--config" || a == "--seed" || a == "--log-level") {
      ++i;
      continue;
    }
    if (a.empty() || a[0] == '-') continue;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == a) return;
    throw std::invalid_argument("unknown command '" + a + "' (slamroute --help lists them)");
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace slamroute;
  cli::stopWithParent();
  CLI::App app{"slamroute: plan, drive and evaluate LiDAR mapping routes through cities"};
  app.set_version_flag("--version", std::string("slamroute ") + SLAMROUTE_VERSION);
  app.require_subcommand(1);
  app.fallthrough();
  cli::Context ctx;
  app.add_option("--config", ctx.config_file, "YAML config file (see `slamroute config --dump`)");
  app.add_option("--seed", ctx.seed, "random seed (same seed, same output)")
      ->check(CLI::Validator(checkSeed, "UINT64"));
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
  cli::registerSweep(app, ctx);
  cli::registerExplore(app, ctx);

  // One line per error, like every other error of slamroute (CLI11 adds a second).
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "slamroute: error: " + std::string(e.what()) + " (see --help)\n";
  });

  try {
    checkCommandName(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const cli::Interrupted& e) {
    std::cerr << "slamroute: " << e.what() << "\n";
    return 128 + e.signal;
  } catch (const std::filesystem::filesystem_error& e) {
    // The library's text ("filesystem error: cannot create directories: Not a directory [...]")
    // as "PATH: what went wrong".
    std::cerr << "slamroute: error: " << (e.path1().empty() ? "" : e.path1().string() + ": ")
              << e.code().message() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "slamroute: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
