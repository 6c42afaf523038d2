#pragma once
// Runs slamroute's own subcommands as child processes. libsumo allows one simulation per
// process, so the pipeline runs every SUMO step (survey, each drive) in its own process; this
// also lets independent steps use both cores.
#include <filesystem>
#include <string>
#include <vector>

namespace slamroute::cli {

struct Step {
  std::string label;               ///< shown in progress lines
  std::vector<std::string> args;   ///< arguments after the program name
  std::filesystem::path log;       ///< child's stdout+stderr go here
  /// The file the step writes last (atomically); `experiment --resume` skips a step whose output
  /// exists. Empty: always run.
  std::filesystem::path output{};
};

struct StepResult {
  int exit_code = -1;
  double seconds = 0.0;
};

/// Path of the running slamroute binary (/proc/self/exe).
std::string selfExe();

/// Runs `steps` with at most `jobs` at once, prints one line per start/finish. Throws
/// std::runtime_error naming the first failed step and quoting the last line of its log.
std::vector<StepResult> runSteps(const std::vector<Step>& steps, int jobs);

}  // namespace slamroute::cli
