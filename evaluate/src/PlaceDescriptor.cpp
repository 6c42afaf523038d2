// Ring/sector height descriptor and its rotation-searched distance (PlaceDescriptor.hpp).
#include "slamroute/evaluate/PlaceDescriptor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "slamroute/core/ConfigCheck.hpp"

namespace slamroute::evaluate {
namespace {

/// Euclidean norm of each sector's column (over the rings).
std::vector<double> columnNorms(const PlaceDescriptor& d) {
  std::vector<double> n(static_cast<std::size_t>(d.sectors), 0.0);
  for (int r = 0; r < d.rings; ++r)
    for (int s = 0; s < d.sectors; ++s) n[static_cast<std::size_t>(s)] += d.at(r, s) * d.at(r, s);
  for (double& v : n) v = std::sqrt(v);
  return n;
}

/// Mean (1 - cos) over the columns occupied in both when query sector k meets candidate
/// sector k + shift; 1 when no column pair is occupied in both.
double shiftedDistance(const PlaceDescriptor& q, const PlaceDescriptor& c,
                       const std::vector<double>& qn, const std::vector<double>& cn, int shift) {
  double sum = 0.0;
  int used = 0;
  for (int k = 0; k < q.sectors; ++k) {
    const int m = (k + shift) % q.sectors;
    const double norms = qn[static_cast<std::size_t>(k)] * cn[static_cast<std::size_t>(m)];
    if (norms <= 0.0) continue;
    double dot = 0.0;
    for (int r = 0; r < q.rings; ++r) dot += q.at(r, k) * c.at(r, m);
    sum += 1.0 - dot / norms;
    ++used;
  }
  return used > 0 ? sum / used : 1.0;
}

/// Each cell becomes the highest of its ring's and the neighbouring rings' heights, those
/// weighted by exp(-k^2 / (2 sigma^2)) for a ring k away (up to 3 sigma).
std::vector<float> spreadOverRings(const std::vector<float>& h, int rings, int sectors,
                                   double sigma) {
  if (sigma <= 0.0) return h;
  const int reach = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<float> w(static_cast<std::size_t>(reach + 1));
  for (int k = 0; k <= reach; ++k)
    w[static_cast<std::size_t>(k)] = static_cast<float>(std::exp(-0.5 * k * k / (sigma * sigma)));
  std::vector<float> out(h.size(), 0.0f);
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < sectors; ++s) {
      float& cell = out[static_cast<std::size_t>(r * sectors + s)];
      for (int q = std::max(0, r - reach); q <= std::min(rings - 1, r + reach); ++q)
        cell = std::max(cell, w[static_cast<std::size_t>(std::abs(q - r))] *
                                  h[static_cast<std::size_t>(q * sectors + s)]);
    }
  return out;
}

}  // namespace

void PlaceRecognitionConfig::validate() const {
  config::requireRange("rings", rings, 1, 1000);
  config::requireRange("sectors", sectors, 4, 3600);
  config::requirePositive("max_radius_m", max_radius_m);
  config::requireRange("ring_spread", ring_spread, 0.0, static_cast<double>(rings));
  if (!(max_distance > 0.0 && max_distance <= 1.0))
    config::rejectValue("max_distance", max_distance, "in (0, 1]");
  config::requireRange("ring_key_candidates", ring_key_candidates, 1, 100000000);
}

PlaceDescriptor makePlaceDescriptor(const Cloud& body, double sensor_height_m,
                                    const PlaceRecognitionConfig& cfg) {
  PlaceDescriptor d;
  d.rings = cfg.rings;
  d.sectors = cfg.sectors;
  d.height_m.assign(static_cast<std::size_t>(d.rings * d.sectors), 0.0f);
  const double ring_m = cfg.max_radius_m / cfg.rings;
  const double sector_rad = 2.0 * std::numbers::pi / cfg.sectors;
  for (const auto& p : body) {
    const double range = std::hypot(p.x(), p.y());
    if (!(range < cfg.max_radius_m)) continue;
    const int ring = std::min(cfg.rings - 1, static_cast<int>(range / ring_m));
    const double az = std::atan2(p.y(), p.x()) + std::numbers::pi;
    const int sector = std::clamp(static_cast<int>(az / sector_rad), 0, cfg.sectors - 1);
    float& cell = d.height_m[static_cast<std::size_t>(ring * d.sectors + sector)];
    cell = std::max(cell, static_cast<float>(p.z() + sensor_height_m));
  }
  d.height_m = spreadOverRings(d.height_m, d.rings, d.sectors, cfg.ring_spread);
  d.ring_key.assign(static_cast<std::size_t>(d.rings), 0.0f);
  for (int r = 0; r < d.rings; ++r) {
    double sum = 0.0;
    for (int s = 0; s < d.sectors; ++s) sum += d.at(r, s);
    d.ring_key[static_cast<std::size_t>(r)] = static_cast<float>(sum / d.sectors);
  }
  return d;
}

PlaceMatch placeDistance(const PlaceDescriptor& query, const PlaceDescriptor& candidate) {
  if (query.rings != candidate.rings || query.sectors != candidate.sectors)
    throw std::invalid_argument("place descriptors of different sizes (" +
                                std::to_string(query.rings) + "x" + std::to_string(query.sectors) +
                                " and " + std::to_string(candidate.rings) + "x" +
                                std::to_string(candidate.sectors) + ")");
  const std::vector<double> qn = columnNorms(query), cn = columnNorms(candidate);
  PlaceMatch best;
  best.distance = 2.0;
  for (int shift = 0; shift < query.sectors; ++shift) {
    const double d = shiftedDistance(query, candidate, qn, cn, shift);
    if (d < best.distance) {
      best.distance = d;
      best.shift = shift;
    }
  }
  best.distance = std::min(best.distance, 1.0);
  const double sector_rad = 2.0 * std::numbers::pi / query.sectors;
  best.yaw_rad = best.shift * sector_rad;
  if (best.yaw_rad > std::numbers::pi) best.yaw_rad -= 2.0 * std::numbers::pi;
  return best;
}

}  // namespace slamroute::evaluate
