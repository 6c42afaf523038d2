// Road-graph extraction time vs number of trace points (paper §3.1), one core.
// Synthetic city: a g x g grid of junctions 100 m apart; vehicles drive random walks (no U-turns)
// at 10 m/s sampled at 10 Hz (1 m apart), right-hand lanes 1.6 m off the centre line, 1 m
// Gaussian GPS noise. The city grows with the number of points (about 4 passes per street), so
// the work per point is constant and the total should grow near-linearly.
// Also times the depth-image score of one 800x600 frame (one core and all cores).
//
//   build-<name>/bench/bench_roadgraph [N ...]     (default: 10000 100000 1000000)
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "slamroute/core/Log.hpp"
#include "slamroute/roadgraph/DepthScore.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"

using namespace slamroute;
using namespace slamroute::roadgraph;

namespace {

Traces cityTraces(std::size_t n_points, int g, std::uint64_t seed) {
  Traces tr;
  tr.source = "synthetic city";
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double sp = 100.0;
  while (tr.points.size() < n_points) {
    const int vid = static_cast<int>(tr.vehicles.size());
    tr.vehicles.push_back("v" + std::to_string(vid));
    int x = static_cast<int>(rng() % static_cast<unsigned>(g));
    int y = static_cast<int>(rng() % static_cast<unsigned>(g));
    int dx = 0, dy = 0;
    double t = 0.0;
    for (int leg = 0; leg < 20 && tr.points.size() < n_points; ++leg) {
      std::vector<std::pair<int, int>> opts;
      for (auto [ax, ay] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        if (ax == -dx && ay == -dy && (dx || dy)) continue;
        if (x + ax < 0 || x + ax >= g || y + ay < 0 || y + ay >= g) continue;
        opts.emplace_back(ax, ay);
      }
      if (opts.empty()) break;
      std::tie(dx, dy) = opts[rng() % opts.size()];
      const Vec3 a(x * sp, y * sp, 0), dir(dx, dy, 0), right(dy, -dx, 0);
      for (double s = 0; s < sp && tr.points.size() < n_points; s += 1.0) {
        TracePoint p;
        p.t = (t += 0.1);
        p.vehicle = vid;
        p.pos = a + dir * s + right * 1.6 + Vec3(noise(rng), noise(rng), 0.2 * noise(rng));
        tr.points.push_back(p);
      }
      x += dx;
      y += dy;
    }
  }
  return tr;
}

}  // namespace

int main(int argc, char** argv) {
  setLogLevel(LogLevel::Warn);
  std::vector<std::size_t> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::stoul(argv[i]));
  if (sizes.empty()) sizes = {10000, 100000, 1000000};
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    std::printf("%10s %6s %9s %13s %12s %9s %10s\n", "points", "grid", "voxels", "intersections",
                "(expected)", "streets", "seconds");
    for (std::size_t n : sizes) {
      // ~4 passes per street: road length 2 g (g - 1) 100 m ~ n / 4.
      const int g = std::max(3, static_cast<int>(std::ceil(std::sqrt(n / 4.0 / 200.0))) + 1);
      const Traces tr = cityTraces(n, g, 42);
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = graphFromTraces(tr, Config{});
      const double sec =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%10zu %3dx%-3d %9zu %13zu %12d %9zu %10.2f\n", n, g, g, r.stats.voxels,
                  r.stats.intersections, g * g - 4, r.stats.streets, sec);
      std::fflush(stdout);
    }
  }
  // Depth score of one frame: a box corner rendered by a pinhole camera.
  DepthImage img;
  img.width = 800;
  img.height = 600;
  img.mm.resize(800 * 600);
  for (int v = 0; v < 600; ++v)
    for (int u = 0; u < 800; ++u) {
      const Vec3 r((u - 399.5) / 400.0, (v - 299.5) / 400.0, 1.0);
      double best = 60.0;
      if (r.y() > 1e-9) best = std::min(best, 1.5 / r.y());
      if (r.x() < -1e-9) best = std::min(best, -3.0 / r.x());
      best = std::min(best, 15.0);
      img.mm[static_cast<std::size_t>(v) * 800 + static_cast<std::size_t>(u)] =
          static_cast<std::uint16_t>(best * 1000);
    }
  const int frames = 40;
  for (int threads : {1, 2}) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism,
                          static_cast<std::size_t>(threads));
    const auto t0 = std::chrono::steady_clock::now();
    double sum = 0;
    std::vector<double> s(frames);
    tbb::parallel_for(0, frames, [&](int i) {
      s[static_cast<std::size_t>(i)] = scoreDepthImage(img, DepthConfig{}).score;
    });
    for (double v : s) sum += v;
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("depth score: %d frames on %d thread(s): %.1f frames/s (score %.3f)\n", frames,
                threads, frames / sec, sum / frames);
  }
  return 0;
}
