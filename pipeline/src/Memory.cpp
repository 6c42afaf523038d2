#include "slamroute/pipeline/Memory.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>

#include "slamroute/core/Log.hpp"

namespace slamroute::pipeline {

double slamMemoryGb(double route_km, bool clouds_on_disk) {
  return 0.3 + (clouds_on_disk ? 0.008 : 0.04) * std::max(0.0, route_km);
}

double availableMemoryGb() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kb = 0.0;
  while (in >> key >> kb) {
    std::getline(in, unit);
    if (key == "MemAvailable:") return kb * 1024.0 / 1e9;  // the kernel's kB are KiB
  }
  return 0.0;
}

int slamJobsForMemory(std::vector<double> need_gb, double budget_gb, int max_jobs) {
  const int cap = std::max(1, std::min(max_jobs, static_cast<int>(need_gb.size())));
  if (!(budget_gb > 0.0)) return cap;
  std::sort(need_gb.begin(), need_gb.end(), std::greater<>());
  double sum = 0.0;
  int k = 0;
  while (k < cap && sum + need_gb[static_cast<std::size_t>(k)] <= budget_gb)
    sum += need_gb[static_cast<std::size_t>(k++)];
  return std::max(1, k);
}

int slamJobsThatFit(const std::vector<double>& route_m, int max_jobs, bool clouds_on_disk,
                    std::string* why) {
  std::vector<double> need;
  for (double m : route_m) need.push_back(slamMemoryGb(m / 1000.0, clouds_on_disk));
  const double avail = availableMemoryGb();
  if (why && !need.empty()) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "largest SLAM estimated at %.1f GB, %.1f GB available",
                  *std::max_element(need.begin(), need.end()), avail);
    *why = buf;
  }
  return slamJobsForMemory(std::move(need), 0.9 * avail, max_jobs);
}

int slamJobsToUse(const std::vector<double>& route_m, int requested, int max_auto,
                  bool clouds_on_disk) {
  std::string mem;
  const int cap = requested > 0 ? static_cast<int>(route_m.size()) : max_auto;
  const int fit = slamJobsThatFit(route_m, cap, clouds_on_disk, &mem);
  if (requested > fit)
    logWarn("--slam-jobs " + std::to_string(requested) + " may exceed the memory (" + mem + ")");
  else if (requested == 0 && fit < std::min<int>(max_auto, static_cast<int>(route_m.size())))
    logInfo("  " + std::to_string(fit) + " SLAM run(s) at once to fit the memory (" + mem + ")");
  return requested > 0 ? requested : fit;
}

}  // namespace slamroute::pipeline
