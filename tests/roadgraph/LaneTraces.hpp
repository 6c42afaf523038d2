#pragma once
// Traces made from a SUMO net's own lane shapes: every passenger lane driven once, junctions
// crossed along the net's connections, so the known answer of a graph built from them is the net.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph::test {

/// A new vehicle (named prefix + its index) drives polyline pl, 1 m apart at 10 Hz; jitter()
/// is added to each point.
template <class Jitter>
void driveAlong(Traces& tr, const Polyline& pl, const std::string& prefix, Jitter jitter) {
  const int vid = static_cast<int>(tr.vehicles.size());
  tr.vehicles.push_back(prefix + std::to_string(vid));
  double t = 0.0;
  for (std::size_t k = 0; k + 1 < pl.size(); ++k) {
    const Vec3 d = pl[k + 1] - pl[k];
    for (double s = 0.0; s < d.norm(); s += 1.0) {
      TracePoint p;
      p.t = (t += 0.1);
      p.vehicle = vid;
      p.pos = pl[k] + d.normalized() * s + jitter();
      tr.points.push_back(p);
    }
  }
}

/// Through a junction from the end of lane shape `la` to the start of `lb` on a cubic Bezier
/// tangent to both (as a turning vehicle drives), not on a straight chord.
inline Polyline junctionCurve(const Polyline& la, const Polyline& lb) {
  const Point3 p0 = la.back(), p3 = lb.front();
  const double d = (p3 - p0).norm();
  const Point3 p1 = p0 + (la.back() - la[la.size() - 2]).normalized() * d / 3.0;
  const Point3 p2 = p3 - (lb[1] - lb.front()).normalized() * d / 3.0;
  Polyline curve;
  const int m = std::max(2, static_cast<int>(std::ceil(d)));
  for (int k = 0; k <= m; ++k) {
    const double t = static_cast<double>(k) / m, u = 1.0 - t;
    curve.push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
  }
  return curve;
}

/// One vehicle per route (SUMO edge ids, consecutive ones joined by a connection): the first
/// lane of each edge, joined through each junction by junctionCurve; 1 m apart at 10 Hz.
inline Traces routeTraces(const SumoNet& net, const std::vector<std::vector<std::string>>& routes) {
  Traces tr;
  tr.source = net.source.string();
  for (const auto& route : routes) {
    Polyline path;
    for (std::size_t i = 0; i < route.size(); ++i) {
      const Polyline& lane = net.findEdge(route[i])->lanes.front().shape;
      if (i > 0) {
        const Polyline curve = junctionCurve(net.findEdge(route[i - 1])->lanes.front().shape, lane);
        path.insert(path.end(), curve.begin() + 1, curve.end() - 1);
      }
      path.insert(path.end(), lane.begin(), lane.end());
    }
    driveAlong(tr, path, "route", [] { return Vec3::Zero().eval(); });
  }
  return tr;
}

/// One vehicle per lane and per connection and pass, 1 m apart at 10 Hz, with Gaussian noise
/// across x/y.
inline Traces laneTraces(const SumoNet& net, double noise_sigma_m, std::uint64_t seed,
                         int passes = 1) {
  Traces tr;
  tr.source = net.source.string();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_sigma_m);
  auto drive = [&](const Polyline& pl) {
    const auto jitter = [&] {
      return noise_sigma_m > 0 ? Vec3(noise(rng), noise(rng), 0.0) : Vec3::Zero().eval();
    };
    driveAlong(tr, pl, "v", jitter);
  };
  for (int pass = 0; pass < passes; ++pass) {
    for (const auto& e : net.edges)
      if (!e.isInternal() && e.allowsPassenger())
        for (const auto& l : e.lanes)
          if (l.allowsPassenger() && l.shape.size() >= 2) drive(l.shape);
    for (const auto& c : net.connections) {
      const auto *a = net.findEdge(c.from), *b = net.findEdge(c.to);
      if (!a || !b || !a->allowsPassenger() || !b->allowsPassenger()) continue;
      if (c.from_lane >= static_cast<int>(a->lanes.size()) ||
          c.to_lane >= static_cast<int>(b->lanes.size()))
        continue;
      const auto& la = a->lanes[static_cast<std::size_t>(c.from_lane)].shape;
      const auto& lb = b->lanes[static_cast<std::size_t>(c.to_lane)].shape;
      if (la.size() < 2 || lb.size() < 2) continue;
      drive(junctionCurve(la, lb));
    }
  }
  return tr;
}

}  // namespace slamroute::roadgraph::test
