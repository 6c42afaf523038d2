// K-means: k-means++ seeding (Arthur & Vassilvitskii 2007) and Lloyd iterations until no point
// changes cluster.
#include "slamroute/core/KMeans.hpp"

#include <limits>
#include <random>
#include <stdexcept>

namespace slamroute {
namespace {

/// Uniform in [0, 1) from the generator's top 53 bits.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

std::vector<double> weightsOf(const std::vector<Point2>& points, const KMeansOptions& o) {
  if (o.weight.empty()) return std::vector<double>(points.size(), 1.0);
  if (o.weight.size() != points.size())
    throw std::invalid_argument("kMeans: one weight per point needed");
  for (double w : o.weight)
    if (!(w > 0.0)) throw std::invalid_argument("kMeans: weights must be positive");
  return o.weight;
}

/// Index drawn with probability proportional to p (all p >= 0); the first index if all are 0.
std::size_t drawProportional(const std::vector<double>& p, std::mt19937_64& rng) {
  double total = 0.0;
  for (double x : p) total += x;
  if (total <= 0.0) return 0;
  double target = uniform01(rng) * total;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (target < p[i]) return i;
    target -= p[i];
  }
  for (std::size_t i = p.size(); i-- > 0;)
    if (p[i] > 0.0) return i;
  return 0;
}

std::vector<Point2> seedCentres(const std::vector<Point2>& pts, const std::vector<double>& w, int k,
                                std::mt19937_64& rng) {
  std::vector<Point2> centres{pts[drawProportional(w, rng)]};
  std::vector<double> d2(pts.size(), std::numeric_limits<double>::infinity());
  while (static_cast<int>(centres.size()) < k) {
    std::vector<double> p(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      d2[i] = std::min(d2[i], (pts[i] - centres.back()).squaredNorm());
      p[i] = w[i] * d2[i];
    }
    centres.push_back(pts[drawProportional(p, rng)]);
  }
  return centres;
}

int nearestCentre(const Point2& p, const std::vector<Point2>& centres) {
  int best = 0;
  for (int c = 1; c < static_cast<int>(centres.size()); ++c)
    if ((p - centres[c]).squaredNorm() < (p - centres[best]).squaredNorm()) best = c;
  return best;
}

/// Recomputes the centres as weighted means; an empty cluster takes the point farthest from
/// its current centre (which then leaves its old cluster).
void updateCentres(const std::vector<Point2>& pts, const std::vector<double>& w,
                   std::vector<int>& label, std::vector<Point2>& centres) {
  const std::size_t k = centres.size();
  std::vector<Point2> sum(k, Point2::Zero());
  std::vector<double> mass(k, 0.0);
  for (std::size_t i = 0; i < pts.size(); ++i)
    sum[label[i]] += w[i] * pts[i], mass[label[i]] += w[i];
  for (std::size_t c = 0; c < k; ++c) {
    if (mass[c] > 0.0) {
      centres[c] = sum[c] / mass[c];
      continue;
    }
    std::size_t far = 0;
    double farD = -1.0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double d = (pts[i] - centres[label[i]]).squaredNorm();
      if (d > farD && mass[label[i]] > w[i]) farD = d, far = i;
    }
    mass[label[far]] -= w[far];
    label[far] = static_cast<int>(c);
    centres[c] = pts[far];
    mass[c] = w[far];
  }
}

}  // namespace

KMeansResult kMeans(const std::vector<Point2>& points, int k, const KMeansOptions& options) {
  if (k < 1 || k > static_cast<int>(points.size()))
    throw std::invalid_argument("kMeans: need 1 <= k <= number of points");
  const std::vector<double> w = weightsOf(points, options);
  std::mt19937_64 rng(options.seed);
  KMeansResult r;
  r.centre = seedCentres(points, w, k, rng);
  r.label.assign(points.size(), -1);
  for (r.iterations = 0; r.iterations < options.maxIterations; ++r.iterations) {
    bool changed = false;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const int c = nearestCentre(points[i], r.centre);
      changed |= c != r.label[i];
      r.label[i] = c;
    }
    if (!changed) break;
    updateCentres(points, w, r.label, r.centre);
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    r.inertia += w[i] * (points[i] - r.centre[r.label[i]]).squaredNorm();
  return r;
}

}  // namespace slamroute
