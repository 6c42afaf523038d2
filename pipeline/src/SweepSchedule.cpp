// Rank 0 of a sweep: the scheduler (Sweep.hpp).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "Elapsed.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/pipeline/Memory.hpp"
#include "slamroute/pipeline/Resume.hpp"
#include "slamroute/pipeline/Sweep.hpp"

namespace slamroute::pipeline {
namespace {

using nlohmann::json;

struct RankState {
  bool alive = true;
  double memory_gb = 0.0;  ///< what the rank reported free when it started
  std::set<std::size_t> running;
  Clock::time_point heard = Clock::now();
};

std::vector<QueuedTask> queued(const std::vector<SweepTask>& tasks) {
  std::vector<QueuedTask> q;
  for (const auto& t : tasks) q.push_back({t.deps, taskCost(t), taskMemoryGb(t)});
  return q;
}

class Scheduler {
 public:
  Scheduler(Cluster& c, std::vector<SweepTask> tasks, const SweepOptions& o)
      : c_(c),
        tasks_(std::move(tasks)),
        q_(queued(tasks_), o.max_attempts),
        o_(o),
        steps_(tasks_.size()),
        ranks_(static_cast<std::size_t>(c.size())) {
    ranks_[0].memory_gb = availableMemoryGb();
  }

  SweepOutcome run() {
    const auto t0 = Clock::now();
    auto last_beat = Clock::now();
    const StopSignals stop_signals;
    int interrupted_by = 0;
    while (!q_.finished()) {
      if ((interrupted_by = stop_signals.received()) != 0) {
        stopLocalTasks(interrupted_by);
        break;
      }
      receive();
      reapLocal();
      dropSilentRanks();
      assign();
      if (secondsSince(last_beat) >= 1.0) {
        last_beat = Clock::now();
        for (int r = 1; r < c_.size(); ++r)
          if (ranks_[static_cast<std::size_t>(r)].alive) c_.send(r, Tag::Heartbeat, "");
      }
      ::usleep(20000);
    }
    for (int r = 1; r < c_.size(); ++r)
      if (ranks_[static_cast<std::size_t>(r)].alive) c_.send(r, Tag::Stop, "");
    SweepOutcome out{tasks_, {}, secondsSince(t0), c_.size(), interrupted_by};
    for (std::size_t i = 0; i < tasks_.size(); ++i) out.status.push_back(q_.status(i));
    return out;
  }

 private:
  RankState& rank(int r) { return ranks_[static_cast<std::size_t>(r)]; }

  void receive() {
    while (auto m = c_.poll()) {
      if (m->from <= 0 || m->from >= c_.size() || !rank(m->from).alive)
        continue;  // a rank taken for dead
      rank(m->from).heard = Clock::now();
      if (m->tag == Tag::Hello)
        rank(m->from).memory_gb = json::parse(m->text).value("memory_gb", 0.0);
      if (m->tag == Tag::Done) {
        const json j = json::parse(m->text);
        finish(j.at("task").get<std::size_t>(), j.at("exit").get<int>(),
               j.at("seconds").get<double>(), m->from);
      }
    }
  }

  /// Passes the stop signal on to the tasks running here and waits for them (the other ranks
  /// stop theirs when told to stop). The stopped tasks stay unfinished: no stamp, so --resume
  /// runs them again.
  void stopLocalTasks(int sig) {
    std::vector<int> pids;
    std::string names;
    for (const auto& [pid, run] : local_) {
      pids.push_back(pid);
      names += (names.empty() ? "" : ", ") + tasks_[run.first].name;
    }
    logWarn(std::string("sweep: ") + strsignal(sig) + (names.empty() ? "" : ", stopping " + names));
    stopSteps(pids, sig);
    local_.clear();
  }

  void reapLocal() {
    for (auto it = local_.begin(); it != local_.end();) {
      const auto code = finishedStep(it->first);
      if (!code) {
        ++it;
        continue;
      }
      const auto [task, start] = it->second;
      it = local_.erase(it);
      finish(task, *code, secondsSince(start), 0);
    }
  }

  void dropSilentRanks() {
    for (int r = 1; r < c_.size(); ++r) {
      RankState& s = rank(r);
      if (!s.alive || secondsSince(s.heard) < o_.worker_timeout_s) continue;
      s.alive = false;
      c_.peerDied(r);
      logWarn("rank " + std::to_string(r) + " silent for " +
              std::to_string(static_cast<int>(o_.worker_timeout_s)) + " s: taken for dead, its " +
              std::to_string(s.running.size()) + " task(s) re-queued");
      for (std::size_t i : s.running) {
        q_.requeue(i, "rank " + std::to_string(r) + " died while running it");
        logInfo("  re-queued " + tasks_[i].name);
      }
      s.running.clear();
    }
  }

  void assign() {
    for (int r = 0; r < c_.size(); ++r) {
      RankState& s = rank(r);
      while (s.alive && static_cast<int>(s.running.size()) < o_.jobs_per_rank) {
        double used = 0.0;
        for (std::size_t i : s.running) used += q_.task(i).memory_gb;
        const auto next = q_.next(0.9 * s.memory_gb - used, s.running.empty());
        if (!next) break;
        start(*next, r);
      }
    }
  }

  void start(std::size_t i, int r) {
    std::vector<Step> todo;
    try {
      todo = stepsToRun({taskStep(tasks_[i])}, o_.resume);
    } catch (const std::exception& e) {  // an input of the step cannot be read
      q_.started(i);
      q_.failed(i, e.what());
      return;
    }
    if (todo.empty()) return kept(i);
    steps_[i] = todo[0];
    std::error_code ec;
    std::filesystem::remove(stampPath(steps_[i]), ec);  // stale until the task succeeds again
    q_.started(i);
    rank(r).running.insert(i);
    logInfo("  started  " + tasks_[i].name + " on rank " + std::to_string(r));
    if (r == 0) {
      local_[startStep(steps_[i])] = {i, Clock::now()};
      return;
    }
    c_.send(r, Tag::Task,
            json{{"task", i},
                 {"label", steps_[i].label},
                 {"args", steps_[i].args},
                 {"log", steps_[i].log.string()}}
                .dump());
  }

  void kept(std::size_t i) {
    q_.started(i);
    std::string why;
    if (!afterSuccess(i, &why)) return q_.failed(i, why);
    q_.succeeded(i, 0.0, true);
    logInfo("  kept     " + tasks_[i].name + " (done before from the same inputs)");
  }

  void finish(std::size_t i, int exit_code, double seconds, int r) {
    if (!rank(r).running.erase(i)) return;  // not running there (any more)
    std::string why = "exit code " + std::to_string(exit_code) + ": " + lastLogLine(steps_[i].log) +
                      " (log: " + steps_[i].log.string() + ")";
    if (exit_code == 0) writeFileAtomic(stampPath(steps_[i]), steps_[i].stamp);
    if (exit_code == 0 && afterSuccess(i, &why)) {
      q_.succeeded(i, seconds);
      char buf[64];
      std::snprintf(buf, sizeof buf, " (%.1f s, rank %d)", seconds, r);
      logInfo("  finished " + tasks_[i].name + buf);
      return;
    }
    q_.failed(i, why);
    const bool again = q_.status(i).state == TaskState::Ready;
    logWarn(tasks_[i].name + " failed" + (again ? " (runs once more)" : "") + ": " + why);
  }

  /// A plan's route made legal for SUMO, and its dependents' estimates updated with its length.
  bool afterSuccess(std::size_t i, std::string* why) {
    if (tasks_[i].kind != TaskKind::Plan) return true;
    try {
      auto it = nets_.find(tasks_[i].net);
      if (it == nets_.end()) it = nets_.emplace(tasks_[i].net, SumoNet::read(tasks_[i].net)).first;
      makeRouteDrivable(it->second, tasks_[i].run.route(tasks_[i].plan.id));
    } catch (const std::exception& e) {
      *why = std::string("legal repair of the route: ") + e.what();
      return false;
    }
    for (std::size_t j = i + 1; j < tasks_.size(); ++j)
      if (tasks_[j].run.out == tasks_[i].run.out && tasks_[j].plan.id == tasks_[i].plan.id)
        q_.estimate(j, taskCost(tasks_[j]), taskMemoryGb(tasks_[j]));
    return true;
  }

  Cluster& c_;
  std::vector<SweepTask> tasks_;
  SweepQueue q_;
  SweepOptions o_;
  std::vector<Step> steps_;  ///< the stamped step of each task started
  std::vector<RankState> ranks_;
  std::map<int, std::pair<std::size_t, Clock::time_point>> local_;  ///< pid -> task, start
  std::map<std::string, SumoNet> nets_;
};

}  // namespace

SweepOutcome scheduleSweep(Cluster& cluster, std::vector<SweepTask> tasks,
                           const SweepOptions& opts) {
  return Scheduler(cluster, std::move(tasks), opts).run();
}

}  // namespace slamroute::pipeline
