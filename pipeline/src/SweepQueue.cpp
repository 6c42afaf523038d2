#include "slamroute/pipeline/SweepQueue.hpp"

#include <stdexcept>

namespace slamroute::pipeline {

SweepQueue::SweepQueue(std::vector<QueuedTask> tasks, int max_attempts)
    : tasks_(std::move(tasks)), status_(tasks_.size()), max_attempts_(max_attempts) {
  for (std::size_t i = 0; i < tasks_.size(); ++i) {
    for (std::size_t d : tasks_[i].deps)
      if (d >= i) throw std::invalid_argument("sweep: a task depends on a later one");
    if (tasks_[i].deps.empty()) status_[i].state = TaskState::Ready;
  }
}

std::optional<std::size_t> SweepQueue::next(double free_gb, bool idle) const {
  std::optional<std::size_t> best, best_fitting;
  for (std::size_t i = 0; i < tasks_.size(); ++i) {
    if (status_[i].state != TaskState::Ready) continue;
    if (!best || tasks_[i].cost > tasks_[*best].cost) best = i;
    if (tasks_[i].memory_gb <= free_gb &&
        (!best_fitting || tasks_[i].cost > tasks_[*best_fitting].cost))
      best_fitting = i;
  }
  return best_fitting ? best_fitting : (idle ? best : std::nullopt);
}

void SweepQueue::started(std::size_t i) {
  status_[i].state = TaskState::Running;
  ++status_[i].attempts;
}

void SweepQueue::succeeded(std::size_t i, double seconds, bool kept) {
  status_[i].state = TaskState::Done;
  status_[i].seconds = seconds;
  status_[i].kept = kept;
  status_[i].error.clear();
  release(i);
}

void SweepQueue::failed(std::size_t i, const std::string& why) {
  status_[i].error = why;
  if (status_[i].attempts < max_attempts_) {
    status_[i].state = TaskState::Ready;
    return;
  }
  status_[i].state = TaskState::Failed;
  skipDependents(i);
}

void SweepQueue::estimate(std::size_t i, double cost, double memory_gb) {
  tasks_[i].cost = cost;
  tasks_[i].memory_gb = memory_gb;
}

bool SweepQueue::finished() const {
  for (const auto& s : status_)
    if (s.state == TaskState::Ready || s.state == TaskState::Running) return false;
  return true;
}

void SweepQueue::release(std::size_t done) {
  for (std::size_t i = done + 1; i < tasks_.size(); ++i) {
    if (status_[i].state != TaskState::Waiting) continue;
    bool ready = true;
    for (std::size_t d : tasks_[i].deps) ready = ready && status_[d].state == TaskState::Done;
    if (ready) status_[i].state = TaskState::Ready;
  }
}

void SweepQueue::skipDependents(std::size_t failed) {
  for (std::size_t i = failed + 1; i < tasks_.size(); ++i) {
    if (status_[i].state != TaskState::Waiting) continue;
    for (std::size_t d : tasks_[i].deps)
      if (d == failed || status_[d].state == TaskState::Skipped) {
        status_[i].state = TaskState::Skipped;
        status_[i].error = "not run: a task it needs failed";
        break;
      }
  }
}

}  // namespace slamroute::pipeline
