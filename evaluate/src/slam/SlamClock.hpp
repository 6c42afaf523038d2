#pragma once
// Stage timing of the SLAM uses the thread's CPU time, so figures are per core and not distorted
// by other processes competing for the machine.
#include <ctime>

namespace slamroute::evaluate::slam {

inline double cpuNow() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
inline double cpuSince(double t0) { return cpuNow() - t0; }

}  // namespace slamroute::evaluate::slam
