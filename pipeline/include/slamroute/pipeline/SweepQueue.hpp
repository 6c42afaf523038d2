#pragma once
// The scheduling state of a sweep's tasks: which are ready (their dependencies succeeded), which
// to start next (longest first, within the memory a rank has free), retries and failures.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace slamroute::pipeline {

enum class TaskState { Waiting, Ready, Running, Done, Failed, Skipped };

struct TaskStatus {
  TaskState state = TaskState::Waiting;
  int attempts = 0;      ///< starts so far
  bool kept = false;     ///< done in an earlier sweep (--resume)
  double seconds = 0.0;  ///< run time of the successful attempt
  std::string error;     ///< why the last attempt failed / why the task was skipped
};

/// What the queue knows of a task: its dependencies and its estimates.
struct QueuedTask {
  std::vector<std::size_t> deps;
  double cost = 0.0;       ///< for longest first
  double memory_gb = 0.0;  ///< peak memory while it runs
};

class SweepQueue {
 public:
  /// A failed task runs again until it has had `max_attempts` starts.
  explicit SweepQueue(std::vector<QueuedTask> tasks, int max_attempts = 2);

  /// The ready task of highest cost whose memory fits in `free_gb`; on an `idle` rank the
  /// largest ready task even when it does not fit (it would never run otherwise).
  std::optional<std::size_t> next(double free_gb, bool idle) const;

  void started(std::size_t i);
  void succeeded(std::size_t i, double seconds, bool kept = false);
  /// A failed attempt: ready again while attempts are left, else failed, and every task that
  /// depends on it skipped.
  void failed(std::size_t i, const std::string& why);
  /// Its rank died: ready again (counts as an attempt, so a task that kills its rank stops).
  void requeue(std::size_t i, const std::string& why) { failed(i, why); }
  /// Updates a ready or waiting task's estimates (route lengths become known as plans finish).
  void estimate(std::size_t i, double cost, double memory_gb);

  const TaskStatus& status(std::size_t i) const { return status_[i]; }
  const QueuedTask& task(std::size_t i) const { return tasks_[i]; }
  std::size_t size() const { return tasks_.size(); }
  /// No task ready or running.
  bool finished() const;

 private:
  void release(std::size_t done);
  void skipDependents(std::size_t failed);

  std::vector<QueuedTask> tasks_;
  std::vector<TaskStatus> status_;
  int max_attempts_;
};

}  // namespace slamroute::pipeline
