// bench_drive: wall time of a ~1 km drive on the default city (SUMO + traffic + ground truth),
// without scans and with --save-scans for each LiDAR preset (machine: 2 cores).
//   build-X/bench/bench_drive [OUT_TMP_DIR]
// Figures go to bench/RESULTS.md, section "Drive".
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace fs = std::filesystem;
using namespace slamroute;

namespace {

std::uintmax_t folderBytes(const fs::path& dir) {
  std::uintmax_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) n += e.file_size();
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  setLogLevel(LogLevel::Warn);
  const fs::path tmp = argc > 1 ? fs::path(argv[1]) : fs::temp_directory_path() / "bench_drive";
  fs::create_directories(tmp);
  // Avenue R2 from C0 over the overpass to C3, then north and east: 964 m, 4 edges.
  const fs::path route = tmp / "route_1km.json";
  std::ofstream(route) << R"(["R2C0_R2C1","R2C1_R2C3","R2C3_R1C3","R1C3_R1C4"])";
  struct Case {
    const char* name;
    const char* preset;
    bool scans;
  };
  const Case cases[] = {{"no scans (ground truth + traffic + world.ply)", "vlp16", false},
                        {"--save-scans --sensor vlp16", "vlp16", true},
                        {"--save-scans --sensor hdl32", "hdl32", true},
                        {"--save-scans --sensor paper", "paper", true}};
  std::printf("%-48s %6s %6s %9s %9s %10s\n", "case", "poses", "km", "wall [s]", "CPU [s]",
              "disk [MB]");
  for (const Case& c : cases) {
    simulate::Config cfg;
    cfg.lidar.preset = c.preset;
    simulate::DriveOptions o;
    o.net = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
    o.route_file = route;
    o.out_dir = tmp / "drive";
    o.save_scans = c.scans;
    o.seed = 42;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const simulate::DriveResult r = simulate::runDrive(o, cfg);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::printf("%-48s %6zu %6.3f %9.2f %9.2f %10.1f\n", c.name, r.groundtruth.size(),
                r.driven_m / 1000.0, wall, cpu, static_cast<double>(folderBytes(o.out_dir)) / 1e6);
    std::fflush(stdout);
    fs::remove_all(o.out_dir);
  }
  return 0;
}
