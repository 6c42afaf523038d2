// Correlative scan matching in the ground plane (CorrelativeSearch.hpp).
#include "slamroute/evaluate/CorrelativeSearch.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "slamroute/core/ConfigCheck.hpp"

namespace slamroute::evaluate {

void CorrelativeOptions::validate() const {
  using namespace slamroute::config;
  requirePositive("resolution_m", resolution_m, 10.0);
  requireRange("coarse_cells", coarse_cells, 1, 64);
  requirePositive("sigma_m", sigma_m, 10.0);
  requireNonNegative("window_m", window_m, 500.0);
  requireNonNegative("yaw_window_rad", yaw_window_rad, 3.2);
  requirePositive("yaw_step_rad", yaw_step_rad, 3.2);
  requireNonNegative("separation_m", separation_m, 1000.0);
  requireRange("prune_share", prune_share, 0.0, 1.0);
  requireRange("max_source_points", max_source_points, 1, 1000000);
}

Cloud structureAboveRoad(const Cloud& cloud, double sensor_height_m, double min_above_road_m,
                         double max_above_road_m) {
  Cloud out;
  for (const auto& p : cloud) {
    const double above = p.z() + sensor_height_m;
    if (above >= min_above_road_m && above <= max_above_road_m) out.push_back(p);
  }
  return out;
}

namespace {

/// A grid of values over the ground plane; outside it every value is 0.
struct Grid {
  double x0 = 0, y0 = 0, res = 1;
  int w = 0, h = 0;
  std::vector<float> v;
  float at(int ix, int iy) const {
    return (ix < 0 || iy < 0 || ix >= w || iy >= h) ? 0.f
                                                    : v[static_cast<std::size_t>(iy) * w + ix];
  }
  int cellX(double x) const { return static_cast<int>(std::floor((x - x0) / res)); }
  int cellY(double y) const { return static_cast<int>(std::floor((y - y0) / res)); }
};

/// exp(-d^2 / 2 sigma^2) of the distance from each cell to the nearest occupied cell, cut at
/// 3 sigma; occupied cells are stamped once however many points fall in them.
Grid likelihoodGrid(const Cloud& target, const CorrelativeOptions& o) {
  Grid g;
  g.res = o.resolution_m;
  if (target.empty()) return g;
  double x1 = -1e300, y1 = -1e300;
  g.x0 = g.y0 = 1e300;
  for (const auto& p : target) {
    g.x0 = std::min(g.x0, double(p.x())), g.y0 = std::min(g.y0, double(p.y()));
    x1 = std::max(x1, double(p.x())), y1 = std::max(y1, double(p.y()));
  }
  const int k = static_cast<int>(std::ceil(3.0 * o.sigma_m / g.res));
  g.x0 -= k * g.res, g.y0 -= k * g.res;
  g.w = static_cast<int>(std::ceil((x1 - g.x0) / g.res)) + k + 1;
  g.h = static_cast<int>(std::ceil((y1 - g.y0) / g.res)) + k + 1;
  std::vector<char> occupied(static_cast<std::size_t>(g.w) * g.h, 0);
  for (const auto& p : target)
    occupied[static_cast<std::size_t>(g.cellY(p.y())) * g.w + g.cellX(p.x())] = 1;
  std::vector<float> kernel;
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx)
      kernel.push_back(static_cast<float>(
          std::exp(-(dx * dx + dy * dy) * g.res * g.res / (2 * o.sigma_m * o.sigma_m))));
  g.v.assign(occupied.size(), 0.f);
  for (int iy = 0; iy < g.h; ++iy)
    for (int ix = 0; ix < g.w; ++ix) {
      if (!occupied[static_cast<std::size_t>(iy) * g.w + ix]) continue;
      for (int dy = -k, n = 0; dy <= k; ++dy)
        for (int dx = -k; dx <= k; ++dx, ++n) {
          float& c = g.v[static_cast<std::size_t>(iy + dy) * g.w + ix + dx];
          c = std::max(c, kernel[static_cast<std::size_t>(n)]);
        }
    }
  return g;
}

/// Each cell: the largest value of the c x c cells from it upwards in x and y, so that a block of
/// c x c offsets is bounded by one look-up per point.
Grid blockMaxGrid(const Grid& g, int c) {
  Grid row = g, out = g;
  for (int iy = 0; iy < g.h; ++iy)
    for (int ix = 0; ix < g.w; ++ix) {
      float m = 0.f;
      for (int d = 0; d < c; ++d) m = std::max(m, g.at(ix + d, iy));
      row.v[static_cast<std::size_t>(iy) * g.w + ix] = m;
    }
  for (int iy = 0; iy < g.h; ++iy)
    for (int ix = 0; ix < g.w; ++ix) {
      float m = 0.f;
      for (int d = 0; d < c; ++d) m = std::max(m, row.at(ix, iy + d));
      out.v[static_cast<std::size_t>(iy) * g.w + ix] = m;
    }
  return out;
}

using Cells = std::vector<std::pair<int, int>>;

double meanAt(const Grid& g, const Cells& pts, int ox, int oy) {
  double s = 0;
  for (const auto& [ix, iy] : pts) s += g.at(ix + ox, iy + oy);
  return s / static_cast<double>(pts.size());
}

struct Block {
  double bound;
  int yaw, ox, oy;  ///< yaw index, first fine offset of the block
};

struct Scored {
  double score;
  int yaw, ox, oy;
};

/// The source's cells at each yaw of the window (no offset).
std::vector<Cells> sourceCells(const Grid& g, const Cloud& source, const Pose3& start,
                               const CorrelativeOptions& o, std::vector<double>& yaws) {
  const int n_yaw = static_cast<int>(std::floor(o.yaw_window_rad / o.yaw_step_rad));
  const std::size_t stride =
      std::max<std::size_t>(1, source.size() / static_cast<std::size_t>(o.max_source_points));
  std::vector<Cells> out;
  for (int j = -n_yaw; j <= n_yaw; ++j) {
    const double dyaw = j * o.yaw_step_rad;
    yaws.push_back(dyaw);
    const Pose3 T = start * Eigen::AngleAxisd(dyaw, Vec3::UnitZ());
    Cells cells;
    for (std::size_t i = 0; i < source.size(); i += stride) {
      const Vec3 p = T * source[i].cast<double>();
      cells.emplace_back(g.cellX(p.x()), g.cellY(p.y()));
    }
    out.push_back(std::move(cells));
  }
  return out;
}

/// Fine scores of every offset in the blocks whose bound reaches prune_share of the best so far.
std::vector<Scored> scoreBlocks(const Grid& fine, const Grid& bound,
                                const std::vector<Cells>& cells, int n,
                                const CorrelativeOptions& o) {
  const int c = o.coarse_cells;
  std::vector<Block> blocks;
  for (int j = 0; j < static_cast<int>(cells.size()); ++j)
    for (int oy = -n; oy <= n; oy += c)
      for (int ox = -n; ox <= n; ox += c)
        blocks.push_back({meanAt(bound, cells[j], ox, oy), j, ox, oy});
  std::sort(blocks.begin(), blocks.end(), [](const Block& a, const Block& b) {
    return a.bound != b.bound ? a.bound > b.bound
                              : std::tie(a.yaw, a.oy, a.ox) < std::tie(b.yaw, b.oy, b.ox);
  });
  std::vector<Scored> kept;
  double best = 0.0;
  for (const Block& b : blocks) {
    if (b.bound < o.prune_share * best) break;
    for (int oy = b.oy; oy < std::min(b.oy + c, n + 1); ++oy)
      for (int ox = b.ox; ox < std::min(b.ox + c, n + 1); ++ox) {
        const double s = meanAt(fine, cells[static_cast<std::size_t>(b.yaw)], ox, oy);
        best = std::max(best, s);
        if (s >= o.prune_share * best) kept.push_back({s, b.yaw, ox, oy});
      }
  }
  return kept;
}

}  // namespace

CorrelativeResult correlativeSearch(const Cloud& target, const Cloud& source, const Pose3& start,
                                    const CorrelativeOptions& o) {
  CorrelativeResult r;
  r.best = start;
  if (target.empty() || source.empty()) return r;
  const Grid fine = likelihoodGrid(target, o);            // 1. the target's likelihood
  const Grid bound = blockMaxGrid(fine, o.coarse_cells);  // 2. its block maxima
  std::vector<double> yaws;
  const std::vector<Cells> cells = sourceCells(fine, source, start, o, yaws);  // 3. source per yaw
  r.source_points = static_cast<int>(cells.front().size());
  const int n = static_cast<int>(std::ceil(o.window_m / o.resolution_m));
  const std::vector<Scored> kept = scoreBlocks(fine, bound, cells, n, o);  // 4. branch and bound
  const auto top = std::min_element(kept.begin(), kept.end(), [](const Scored& a, const Scored& b) {
    return a.score != b.score ? a.score > b.score
                              : std::tie(a.yaw, a.oy, a.ox) < std::tie(b.yaw, b.oy, b.ox);
  });
  r.score = top->score;
  r.runner_up = o.prune_share * r.score;  // 5. the best pose well away from it
  for (const Scored& s : kept) {
    const Vec3 d((s.ox - top->ox) * o.resolution_m, (s.oy - top->oy) * o.resolution_m, 0.0);
    if (d.norm() >= o.separation_m && s.score > r.runner_up)
      r.runner_up = s.score, r.runner_up_offset = d;
  }
  r.best = start * Eigen::AngleAxisd(yaws[static_cast<std::size_t>(top->yaw)], Vec3::UnitZ());
  r.best.translation() += Vec3(top->ox * o.resolution_m, top->oy * o.resolution_m, 0.0);
  return r;
}

}  // namespace slamroute::evaluate
