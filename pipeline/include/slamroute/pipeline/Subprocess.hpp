#pragma once
// Runs slamroute's own subcommands as child processes. libsumo allows one simulation per
// process, so the pipeline runs every SUMO step (survey, each drive) in its own process; this
// also lets independent steps use both cores.
#include <signal.h>

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace slamroute::pipeline {

struct Step {
  std::string label;              ///< shown in progress lines
  std::vector<std::string> args;  ///< arguments after the program name
  std::filesystem::path log;      ///< child's stdout+stderr go here
  /// The file the step writes last (atomically); `--resume` may keep a step whose output exists.
  /// Empty: always run.
  std::filesystem::path output{};
  /// What the step is run from (Resume.hpp's stepStamp); runSteps writes it to stampPath() when
  /// the step succeeds and removes an older one when it starts. Empty: no stamp.
  std::string stamp{};
};

/// Where a step's stamp lives: beside its log, LOG with the extension .done.
std::filesystem::path stampPath(const Step& s);

struct StepResult {
  int exit_code = -1;
  double seconds = 0.0;
};

/// runSteps was stopped by SIGINT, SIGTERM or SIGHUP: the running steps were stopped too.
struct Interrupted : std::runtime_error {
  Interrupted(int sig, const std::string& what) : std::runtime_error(what), signal(sig) {}
  int signal;  ///< the signal that stopped the run; the program exits with 128 + it
};

/// While one lives, SIGINT, SIGTERM and SIGHUP (a job scheduler stopping the run, a closed
/// terminal, Ctrl-C) are caught instead of ending the process, so that the steps it runs can be
/// stopped with it instead of going on as orphans; the previous handlers come back when it goes.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  /// The last stop signal caught since construction; 0: none.
  int received() const;

 private:
  std::array<struct sigaction, 3> old_{};
};

/// In a step started by runSteps: asks the kernel to send SIGTERM when the parent dies (SIGKILL
/// of `run` included), so no step goes on as an orphan writing results nobody stamps; SIGTERM
/// removes the step's staging folder. Does nothing in a process not started by runSteps.
void stopWithParent();

/// Path of the running slamroute binary (/proc/self/exe).
std::string selfExe();

/// Starts one step as a child process (its output to its log) and returns its pid; throws when
/// it cannot be started. For schedulers that run steps one by one (sweep); runSteps runs a batch.
int startStep(const Step& s);

/// The exit code of a child started by startStep once it has ended (128 + signal when killed);
/// nullopt while it runs. Reaps only that child.
std::optional<int> finishedStep(int pid);

/// Sends `sig` to each child started by startStep and waits until each has ended (a step cleans
/// up on SIGINT / SIGTERM: its staging folder goes).
void stopSteps(const std::vector<int>& pids, int sig);

/// Runs `steps` with at most `jobs` at once, prints one line per start/finish and, every
/// `status_every_s` seconds (0 = never), one line per running step quoting the last line of its
/// log (its progress: a SLAM run on a city takes an hour). A step that succeeds gets its stamp
/// written (Step::stamp). SIGINT, SIGTERM or SIGHUP while steps run (a job scheduler stopping
/// the run, a closed terminal) are passed on to the running steps, which are waited for; then
/// Interrupted is thrown. Throws std::runtime_error naming the
/// first failed step and quoting the last line of its log.
std::vector<StepResult> runSteps(const std::vector<Step>& steps, int jobs,
                                 double status_every_s = 60.0);

/// The last non-blank line of a log (text after the last '\r' of a progress line), reading at
/// most its last `max_bytes`; empty when the file is missing or blank.
std::string lastLogLine(const std::filesystem::path& log, std::size_t max_bytes = 4096);

}  // namespace slamroute::pipeline
