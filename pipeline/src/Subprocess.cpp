#include "slamroute/pipeline/Subprocess.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"

extern char** environ;

namespace slamroute::pipeline {
namespace {

/// The child learns its parent's pid from here (stopWithParent).
constexpr const char* kParentEnv = "SLAMROUTE_STEP_PARENT";

/// This process's environment with kParentEnv set to its pid.
std::vector<std::string> childEnvironment() {
  std::vector<std::string> env;
  const std::string prefix = std::string(kParentEnv) + "=";
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind(prefix, 0) != 0) env.emplace_back(*e);
  env.push_back(prefix + std::to_string(::getpid()));
  return env;
}

}  // namespace

int startStep(const Step& s) {
  std::filesystem::create_directories(s.log.parent_path());
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, s.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  const std::string exe = selfExe();
  std::vector<std::string> argv_s{exe};
  argv_s.insert(argv_s.end(), s.args.begin(), s.args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_s = childEnvironment();
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = -1;
  // Exec this very image through /proc/self/exe: every step runs the same version as the parent,
  // even when the binary on disk is rebuilt (and replaced) during a long run.
  const int rc = posix_spawn(&pid, "/proc/self/exe", &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0)
    throw std::runtime_error("cannot start '" + s.label + "' (" + exe + "): " + std::strerror(rc));
  return pid;
}

std::optional<int> finishedStep(int pid) {
  int status = 0;
  const pid_t r = ::waitpid(pid, &status, WNOHANG);
  if (r == 0) return std::nullopt;
  if (r < 0)
    throw std::runtime_error("waiting for step process " + std::to_string(pid) + " failed");
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

void stopSteps(const std::vector<int>& pids, int sig) {
  for (int pid : pids) ::kill(pid, sig);
  for (int pid : pids) ::waitpid(pid, nullptr, 0);
}

namespace {

volatile sig_atomic_t g_stop_signal = 0;

void onStopSignal(int sig) { g_stop_signal = sig; }

constexpr std::array<int, 3> kStopSignals{SIGINT, SIGTERM, SIGHUP};

}  // namespace

StopSignals::StopSignals() {
  g_stop_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  for (std::size_t i = 0; i < kStopSignals.size(); ++i) ::sigaction(kStopSignals[i], &sa, &old_[i]);
}

StopSignals::~StopSignals() {
  for (std::size_t i = 0; i < kStopSignals.size(); ++i)
    ::sigaction(kStopSignals[i], &old_[i], nullptr);
}

int StopSignals::received() const { return g_stop_signal; }

void stopWithParent() {
  const char* parent = std::getenv(kParentEnv);
  if (!parent) return;
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  // The parent may have died before the prctl: then this process is someone else's child now.
  if (std::to_string(::getppid()) != parent) ::raise(SIGTERM);
}

std::string lastLogLine(const std::filesystem::path& log, std::size_t max_bytes) {
  std::ifstream in(log, std::ios::binary | std::ios::ate);
  if (!in) return {};
  const std::streamoff size = in.tellg();
  const std::streamoff from =
      std::max<std::streamoff>(0, size - static_cast<std::streamoff>(max_bytes));
  in.seekg(from);
  std::string line, last;
  bool first = from > 0;  // a line cut by the window is not quoted
  while (std::getline(in, line)) {
    if (first) {
      first = false;
      continue;
    }
    // Progress lines use '\r'; keep the text after the last one.
    const auto r = line.find_last_of('\r');
    if (r != std::string::npos) line = line.substr(r + 1);
    if (line.find_first_not_of(" \t") != std::string::npos) last = line;
  }
  return last;
}

std::filesystem::path stampPath(const Step& s) {
  std::filesystem::path p = s.log;
  return p.replace_extension(".done");
}

std::string selfExe() {
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n <= 0) throw std::runtime_error("cannot find the slamroute binary (/proc/self/exe)");
  buf[n] = '\0';
  return buf;
}

namespace {

using StepClock = std::chrono::steady_clock;
using RunningSteps =
    std::map<pid_t, std::pair<std::size_t, StepClock::time_point>>;  ///< pid -> step, start

/// Passes the stop signal on to the running steps, waits for them and throws Interrupted.
[[noreturn]] void stopOnSignal(int sig, const std::vector<Step>& steps,
                               const RunningSteps& running) {
  std::string stopped;
  std::vector<int> pids;
  for (const auto& [p, run] : running) {
    pids.push_back(p);
    stopped += (stopped.empty() ? "" : ", ") + steps[run.first].label;
  }
  stopSteps(pids, sig);
  throw Interrupted(sig, std::string("interrupted by ") + strsignal(sig) +
                             (stopped.empty() ? "" : "; stopped " + stopped) +
                             " (--resume continues from the steps that finished)");
}

/// One line per running step quoting the last line of its log.
void quoteProgress(const std::vector<Step>& steps, const RunningSteps& running,
                   StepClock::time_point now) {
  for (const auto& [p, run] : running) {
    const std::string line = lastLogLine(steps[run.first].log);
    char buf[64];
    std::snprintf(buf, sizeof buf, " [%.0f s]",
                  std::chrono::duration<double>(now - run.second).count());
    logInfo("  running  " + steps[run.first].label + buf + (line.empty() ? "" : ": " + line));
  }
}

/// A step that ended with wait status `status`: its result and, when it succeeded, its stamp.
/// Returns why it failed (empty: it succeeded).
std::string finishStep(const Step& step, int status, StepClock::time_point start, StepResult& r) {
  r.seconds = std::chrono::duration<double>(StepClock::now() - start).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (r.exit_code != 0)
    return step.label + " failed: " + lastLogLine(step.log) + " (log: " + step.log.string() + ")";
  if (!step.stamp.empty()) writeFileAtomic(stampPath(step), step.stamp);
  char buf[64];
  std::snprintf(buf, sizeof buf, " (%.1f s)", r.seconds);
  logInfo("  finished " + step.label + buf);
  return {};
}

}  // namespace

std::vector<StepResult> runSteps(const std::vector<Step>& steps, int jobs, double status_every_s) {
  auto last_status = StepClock::now();
  std::vector<StepResult> results(steps.size());
  RunningSteps running;
  std::size_t next = 0;
  std::string failure;
  const StopSignals stop_signals;
  while (next < steps.size() || !running.empty()) {
    if (const int sig = stop_signals.received()) stopOnSignal(sig, steps, running);
    while (failure.empty() && next < steps.size() &&
           static_cast<int>(running.size()) < std::max(1, jobs)) {
      logInfo("  started  " + steps[next].label);
      std::error_code ec;
      std::filesystem::remove(stampPath(steps[next]), ec);  // stale until the step succeeds again
      running[startStep(steps[next])] = {next, StepClock::now()};
      ++next;
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid < 0) throw std::runtime_error("waiting for pipeline steps failed");
    if (pid == 0) {  // none finished: quote the running steps' progress now and then
      const auto now = StepClock::now();
      if (status_every_s > 0.0 &&
          std::chrono::duration<double>(now - last_status).count() >= status_every_s) {
        last_status = now;
        quoteProgress(steps, running, now);
      }
      ::usleep(100000);
      continue;
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;
    const auto [idx, start] = it->second;
    running.erase(it);
    const std::string why = finishStep(steps[idx], status, start, results[idx]);
    if (failure.empty()) failure = why;
    if (!failure.empty()) next = steps.size();  // start nothing new; wait for the rest
  }
  if (!failure.empty()) throw std::runtime_error(failure);
  return results;
}

}  // namespace slamroute::pipeline
