#pragma once
// How many SLAM runs (`evaluate` steps) may run at once: each one's peak memory grows with the
// length of the drive it maps.
#include <string>
#include <vector>

namespace slamroute::pipeline {

/// Peak memory of one SLAM run (`evaluate`) of a drive of `route_km` [GB]; it grows with the
/// length (bench/RESULTS.md "Memory of a SLAM run"). With the keyframe clouds on disk (the
/// default, evaluate.output.keyframe_clouds_on_disk) and the map merged tile by tile: measured
/// 330,444 kB for 14.9 km (default city, qlearning) and 698,780 kB for 74.5 km (Ingolstadt,
/// postman), estimated as 0.3 GB + 0.008 GB/km. With the clouds in memory: 601,096 kB and 2,496,008
/// kB, estimated as 0.3 GB + 0.04 GB/km. Both lie 25-50 % above the measured peaks.
double slamMemoryGb(double route_km, bool clouds_on_disk = true);

/// Memory new processes can have now [GB = 10^9 bytes] (MemAvailable in /proc/meminfo); 0 when
/// unknown.
double availableMemoryGb();

/// SLAM runs to start at once: at most `max_jobs`, and no more than the largest k whose k biggest
/// needs (`need_gb`, one per run) fit in `budget_gb`; at least 1. A budget <= 0 (unknown) limits
/// nothing.
int slamJobsForMemory(std::vector<double> need_gb, double budget_gb, int max_jobs);

/// SLAM runs of drives of `route_m` [m] to start at once (at most `max_jobs`): slamJobsForMemory
/// with each run's slamMemoryGb against 90 % of availableMemoryGb(). `why` (optional) receives
/// "largest SLAM estimated at X GB, Y GB available".
int slamJobsThatFit(const std::vector<double>& route_m, int max_jobs, bool clouds_on_disk,
                    std::string* why = nullptr);

/// The SLAM runs of a stage to start at once: `requested` when > 0 (logging a warning when the
/// memory may not hold them), else as many of `max_auto` as fit (logging when fewer).
int slamJobsToUse(const std::vector<double>& route_m, int requested, int max_auto,
                  bool clouds_on_disk);

}  // namespace slamroute::pipeline
