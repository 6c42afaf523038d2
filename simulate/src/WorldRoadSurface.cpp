// World build step: the surfaces a vehicle drives on — lanes with camber (falling from the crown
// to the kerbs) and the seeded relief, pavements with kerbs, junction areas — as meshes fine
// enough (road_cell_m) for the relief to show.
#include <algorithm>
#include <cmath>

#include "WorldBuild.hpp"

namespace slamroute::simulate::detail {

namespace {

struct Resampled {
  std::vector<Point3> pts;
  std::vector<double> s;  ///< arc length at each point [m]
};

/// The polyline with every segment cut into pieces of at most `step` (original points kept).
Resampled resample(const std::vector<Point3>& line, double step) {
  Resampled r;
  if (line.empty()) return r;
  r.pts.push_back(line.front());
  r.s.push_back(0.0);
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const double len = (line[i + 1] - line[i]).head<2>().norm();
    if (len < 1e-6) continue;
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    for (int j = 1; j <= n; ++j) {
      r.pts.push_back(line[i] + (line[i + 1] - line[i]) * (static_cast<double>(j) / n));
      r.s.push_back(r.s.back() + len / n);
    }
  }
  return r;
}

/// Rows of lane k at the given offsets left of its centre: z = lane z + road relief - camber.
/// Offsets beyond the edge's borders get the camber of the border (pavements).
std::vector<std::vector<Point3>> laneRows(const BuildContext& ctx, const SumoEdge& e, std::size_t k,
                                          const EdgeProfile& prof,
                                          const std::vector<double>& offsets) {
  const Resampled line = resample(e.lanes[k].shape, ctx.cfg.road_cell_m);
  const double camber = ctx.cfg.road_camber_pct / 100.0,
               length = line.s.empty() ? 0 : line.s.back();
  std::vector<std::vector<Point3>> rows;
  for (double o : offsets) {
    auto row = offsetPolyline(line.pts, o);
    const double r = std::clamp(prof.lane_r[k] + o, 0.0, prof.width);
    const double drop = std::min(kMaxCamberDrop_m, camber * std::abs(prof.crown_r - r));
    for (std::size_t i = 0; i < row.size(); ++i) {
      const double taper =
          std::clamp(std::min(line.s[i], length - line.s[i]) / kCamberTaper_m, 0.0, 1.0);
      row[i].z() += ctx.relief.road(row[i].x(), row[i].y()) - drop * taper;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<double> thickness(const BuildContext& ctx, const std::vector<Point3>& line,
                              double extra) {
  std::vector<double> t(line.size());
  for (std::size_t i = 0; i < line.size(); ++i)
    t[i] = std::clamp(ctx.elevation(line[i]), 0.0, ctx.cfg.deck_thickness_m) + extra;
  return t;
}

}  // namespace

EdgeProfile edgeProfile(const SumoEdge& e, bool two_way) {
  EdgeProfile p;
  for (const auto& l : e.lanes) {
    p.lane_r.push_back(p.width + l.width_m / 2);
    p.width += l.width_m;
  }
  p.crown_r = two_way ? p.width : p.width / 2;
  return p;
}

void buildLaneSurface(BuildContext& ctx, const SumoEdge& e, std::size_t k, const EdgeProfile& prof,
                      bool bridge, bool footpath) {
  const double w = e.lanes[k].width_m;
  const int n = std::max(1, static_cast<int>(std::lround(w / ctx.cfg.road_cell_m)));
  std::vector<double> offsets;
  for (int j = 0; j <= n; ++j) offsets.push_back(-w / 2 + w * j / n);
  auto rows = laneRows(ctx, e, k, prof, offsets);
  if (footpath && !bridge) {
    const double curb = ctx.cfg.curb_height_m;
    for (auto& row : rows)
      for (auto& p : row) p.z() += curb;
    ctx.mb.grid(rows, SurfaceKind::Sidewalk);
    ctx.mb.slabSides(rows.back(), rows.front(),
                     thickness(ctx, rows.back(), curb + kGroundBelowRoad_m + 0.1),
                     SurfaceKind::Sidewalk);
    return;
  }
  ctx.mb.grid(rows, SurfaceKind::Road);
  if (bridge)
    ctx.mb.slabSides(rows.back(), rows.front(), thickness(ctx, rows.back(), 0.0),
                     SurfaceKind::Deck);
}

void buildPavement(BuildContext& ctx, const SumoEdge& e, std::size_t k, const EdgeProfile& prof,
                   double outward) {
  const auto& c = ctx.cfg;
  const double w = e.lanes[k].width_m / 2, sw = c.sidewalk_width_m;
  // rows right to left; `across` = distance of each row from the kerb
  const std::vector<double> offsets = outward < 0 ? std::vector<double>{-w - sw, -w - sw / 2, -w}
                                                  : std::vector<double>{w, w + sw / 2, w + sw};
  auto rows = laneRows(ctx, e, k, prof, offsets);
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const double across = std::abs(offsets[j]) - w;
    for (auto& p : rows[j]) p.z() += c.curb_height_m + 0.02 * across;
  }
  ctx.mb.grid(rows, SurfaceKind::Sidewalk);
  ctx.mb.slabSides(rows.back(), rows.front(),
                   thickness(ctx, rows.back(), c.curb_height_m + kGroundBelowRoad_m + 0.1),
                   SurfaceKind::Sidewalk);
}

void buildJunctionSurface(BuildContext& ctx, const Polygon2& hull, double z) {
  // one subdivision for all triangles of the fan, so that their shared edges have the same
  // vertices (no cracks)
  const auto tris = triangulate(hull);
  double edge = 0;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) edge = std::max(edge, (hull[t[(k + 1) % 3]] - hull[t[k]]).norm());
  const int n = std::clamp(static_cast<int>(std::ceil(edge / (2 * ctx.cfg.road_cell_m))), 1, 12);
  auto lift = [&](double x, double y) { return ctx.relief.road(x, y); };
  for (const auto& t : tris) {
    Point3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = Point3(hull[t[k]].x(), hull[t[k]].y(), z);
    ctx.mb.subdividedTriangle(p[0], p[1], p[2], n, lift, SurfaceKind::Road);
  }
}

}  // namespace slamroute::simulate::detail
