#pragma once
// Subcommand registration. Each subcommand lives in its own Cmd*.cpp and registers itself on
// the root CLI11 app; the shared Context carries the global options and the loaded config.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "AppConfig.hpp"

namespace slamroute::cli {

struct Context {
  std::string config_file;            ///< --config FILE.yaml
  std::optional<std::uint64_t> seed;  ///< --seed N (overrides the config's seed)
  std::string log_level = "info";     ///< --log-level
  AppConfig cfg;
  /// Loads the config file (if any), applies --seed and --log-level. Call first in callbacks.
  void load();
};

/// Overrides `cfg` with a YAML config file's keys; each section is validated as it is loaded.
/// Throws std::runtime_error / std::invalid_argument with one line naming the file.
void loadConfigFile(const std::string& file, AppConfig& cfg);

void registerNetworkInfo(CLI::App& app, Context& ctx);
void registerConfig(CLI::App& app, Context& ctx);
void registerSurvey(CLI::App& app, Context& ctx);
void registerBuildGraph(CLI::App& app, Context& ctx);
void registerPlan(CLI::App& app, Context& ctx);
void registerDrive(CLI::App& app, Context& ctx);
void registerEvaluate(CLI::App& app, Context& ctx);
void registerCompare(CLI::App& app, Context& ctx);
void registerRun(CLI::App& app, Context& ctx);
void registerExperiment(CLI::App& app, Context& ctx);
void registerSweep(CLI::App& app, Context& ctx);
void registerExplore(CLI::App& app, Context& ctx);

/// The shipped default city (networks/default_city/default_city.net.xml).
std::string defaultNetPath();

}  // namespace slamroute::cli
