// Ranks > 0 of a sweep: run the tasks rank 0 sends (Sweep.hpp).
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <map>

#include <nlohmann/json.hpp>

#include "Elapsed.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/pipeline/Memory.hpp"
#include "slamroute/pipeline/Sweep.hpp"

namespace slamroute::pipeline {
namespace {

using nlohmann::json;

struct Running {
  std::size_t task;
  Clock::time_point start;
};

/// Starts the task of a Task message.
void startTask(const std::string& text, std::map<int, Running>& running) {
  const json j = json::parse(text);
  Step s{j.at("label").get<std::string>(), j.at("args").get<std::vector<std::string>>(),
         j.at("log").get<std::string>()};
  running[startStep(s)] = {j.at("task").get<std::size_t>(), Clock::now()};
}

/// Reports the tasks that ended to rank 0.
void reportFinished(Cluster& c, std::map<int, Running>& running) {
  for (auto it = running.begin(); it != running.end();) {
    const auto code = finishedStep(it->first);
    if (!code) {
      ++it;
      continue;
    }
    c.send(
        0, Tag::Done,
        json{
            {"task", it->second.task}, {"exit", *code}, {"seconds", secondsSince(it->second.start)}}
            .dump());
    it = running.erase(it);
  }
}

void stopAll(std::map<int, Running>& running) {
  std::vector<int> pids;
  for (const auto& [pid, r] : running) pids.push_back(pid);
  stopSteps(pids, SIGTERM);
  running.clear();
}

}  // namespace

void serveSweep(Cluster& c, const std::filesystem::path& out, const SweepOptions& opts) {
  const auto pid_file = out / "workers" / ("rank" + std::to_string(c.rank()) + ".pid");
  std::filesystem::create_directories(pid_file.parent_path());
  writeFileAtomic(pid_file, std::to_string(::getpid()) + "\n");
  c.send(0, Tag::Hello, json{{"memory_gb", availableMemoryGb()}}.dump());
  std::map<int, Running> running;
  auto heard = Clock::now(), beat = Clock::now();
  for (;;) {
    while (auto m = c.poll()) {
      heard = Clock::now();
      if (m->tag == Tag::Stop) return stopAll(running);
      if (m->tag == Tag::Task) startTask(m->text, running);
    }
    reportFinished(c, running);
    if (secondsSince(beat) >= 1.0) {
      beat = Clock::now();
      c.send(0, Tag::Heartbeat, "");
    }
    if (secondsSince(heard) > opts.worker_timeout_s) {
      logWarn("rank " + std::to_string(c.rank()) + ": rank 0 silent, stopping");
      return stopAll(running);
    }
    ::usleep(20000);
  }
}

}  // namespace slamroute::pipeline
