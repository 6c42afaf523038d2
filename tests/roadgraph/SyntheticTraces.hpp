#pragma once
// Synthetic location traces with known answers for the roadgraph tests: vehicles drive given
// road polylines (right-hand traffic, lane offset), sampled every `spacing_m`, with Gaussian
// GPS-like noise from a fixed seed.
#include <random>
#include <string>
#include <vector>

#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph::testing {

struct Road {
  Polyline pts;
  bool two_way = true;
};

inline Polyline line(Point3 a, Point3 b) { return {a, b}; }

inline Traces makeTraces(const std::vector<Road>& roads, double noise_sigma_m = 0.0,
                         std::uint64_t seed = 7, double spacing_m = 1.0, int passes = 1,
                         double lane_offset_m = 1.6) {
  Traces tr;
  tr.source = "synthetic";
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  auto drive = [&](const Polyline& pl, const std::string& name) {
    const int vid = static_cast<int>(tr.vehicles.size());
    tr.vehicles.push_back(name);
    double t = 0.0;
    for (std::size_t k = 0; k + 1 < pl.size(); ++k) {
      const Vec3 d = pl[k + 1] - pl[k];
      const double len = d.norm();
      const Vec3 dir = d / len;
      const Vec3 right(dir.y(), -dir.x(), 0.0);
      for (double s = 0.0; s < len; s += spacing_m) {
        TracePoint p;
        p.t = t;
        t += 0.1;
        p.vehicle = vid;
        p.pos = pl[k] + dir * s + right * lane_offset_m;
        if (noise_sigma_m > 0)
          p.pos += Vec3(noise(rng), noise(rng), 0.2 * noise(rng)) * noise_sigma_m;
        p.speed = spacing_m * 10.0;
        tr.points.push_back(p);
      }
    }
  };
  for (int pass = 0; pass < passes; ++pass)
    for (std::size_t i = 0; i < roads.size(); ++i) {
      drive(roads[i].pts, "r" + std::to_string(i) + "f" + std::to_string(pass));
      if (roads[i].two_way)
        drive(Polyline(roads[i].pts.rbegin(), roads[i].pts.rend()),
              "r" + std::to_string(i) + "b" + std::to_string(pass));
    }
  return tr;
}

/// Plus: two 200 m roads crossing at the origin.
inline std::vector<Road> plusRoads() {
  return {{line({-100, 0, 0}, {100, 0, 0})}, {line({0, -100, 0}, {0, 100, 0})}};
}

/// Grid of n x n junctions `spacing` apart; lines overhang the outer junctions by `overhang`.
inline std::vector<Road> gridRoads(int n, double spacing, double overhang) {
  std::vector<Road> roads;
  const double lo = -overhang, hi = (n - 1) * spacing + overhang;
  for (int i = 0; i < n; ++i) {
    roads.push_back({line({lo, i * spacing, 0}, {hi, i * spacing, 0})});
    roads.push_back({line({i * spacing, lo, 0}, {i * spacing, hi, 0})});
  }
  return roads;
}

}  // namespace slamroute::roadgraph::testing
