#pragma once
// Elapsed time of the sweep's scheduler and workers (steady clock: wall-clock changes do not
// move it).
#include <chrono>

namespace slamroute::pipeline {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace slamroute::pipeline
