#pragma once
// Pieces shared by `run` and `experiment`: child steps carrying the global options, and making a
// planned route drivable in SUMO.
#include <filesystem>
#include <string>
#include <vector>

#include "Commands.hpp"
#include "Subprocess.hpp"

namespace slamroute {
struct SumoNet;
}

namespace slamroute::cli {

/// A child step `slamroute [--seed S] [--config C] [--log-level L] ARGS…`; `seed` overrides the
/// context's seed when >= 0.
Step childStep(const Context& ctx, const std::string& label, std::vector<std::string> args,
               const std::filesystem::path& log, long long seed = -1);

/// Length of a planned route [m] (route.json's length_m).
double routeLength(const std::filesystem::path& route_json);

/// Peak memory of one SLAM run (`evaluate`) of a drive of `route_km` [GB]. Keyframes every metre
/// keep their 0.2 m voxel clouds for the map and the loop closures, so it grows with the length:
/// measured peaks 1.16 GB for 14.9 km (default city, qlearning) and 5.55 GB for 74.5 km
/// (Ingolstadt, postman), bench/RESULTS.md "Memory of a SLAM run"; the estimate 0.3 GB +
/// 0.075 GB/km lies above both.
double slamMemoryGb(double route_km);

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
int slamJobsThatFit(const std::vector<double>& route_m, int max_jobs, std::string* why = nullptr);

/// Routes planned on a trace-built graph know its turns only loosely: joins consecutive SUMO
/// edges with the shortest legal detour where SUMO forbids the turn (noted in the route), and
/// writes ROUTE.rou.xml beside it. Throws when the route has no SUMO edges.
void makeRouteDrivable(const SumoNet& net, const std::filesystem::path& route_json);

}  // namespace slamroute::cli
