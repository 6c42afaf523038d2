// World build steps: road surfaces (with z: bridge decks with thickness), sidewalks with curbs,
// parapets on bridges, junction areas, bridge pillars and the ground plane.
#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_set>

#include "WorldBuild.hpp"

namespace slamroute::simulate::detail {

namespace {

bool pedestrianOnly(const SumoLane& l) {
  if (l.allow.empty()) return false;
  for (const auto& a : l.allow)
    if (a != "pedestrian") return false;
  return true;
}

Polygon2 segmentQuad(const std::vector<Point3>& left, const std::vector<Point3>& right,
                     std::size_t i) {
  return convexHull(
      {left[i].head<2>(), left[i + 1].head<2>(), right[i + 1].head<2>(), right[i].head<2>()});
}

/// Adds the keep-out quads of a strip between two borders (grown by `grow` metres).
void keepOutStrip(KeepOutGrid& grid, const std::vector<Point3>& left,
                  const std::vector<Point3>& right, double grow) {
  for (std::size_t i = 0; i + 1 < left.size() && i + 1 < right.size(); ++i) {
    Polygon2 q = segmentQuad(left, right, i);
    if (q.size() >= 3) grid.add(grow > 0 ? inflateConvex(q, grow) : q);
  }
}

std::vector<Point3> raised(std::vector<Point3> line, double dz) {
  for (auto& p : line) p.z() += dz;
  return line;
}

std::unordered_set<std::string> directedPairs(const SumoNet& net) {
  std::unordered_set<std::string> s;
  for (const auto& e : net.edges) s.insert(e.from + "\x1f" + e.to);
  return s;
}

/// Pavement (raised by the curb height, its sides the kerb) or, on bridges, a parapet along one
/// outer border of lane k. `outward` is +1 for the left border, -1 for the right one.
void sideOfEdge(BuildContext& ctx, const SumoEdge& e, std::size_t k, const EdgeProfile& prof,
                double outward, bool bridge) {
  const auto& c = ctx.cfg;
  const SumoLane& lane = e.lanes[k];
  const double w = lane.width_m / 2;
  const auto inner = offsetPolyline(lane.shape, outward * w);
  const double far = bridge ? w + 0.3 : w + c.sidewalk_width_m;
  const auto outer = offsetPolyline(lane.shape, outward * far);
  const auto& l = outward > 0 ? outer : inner;
  const auto& r = outward > 0 ? inner : outer;
  keepOutStrip(ctx.roads, l, r, c.road_clearance_m);
  if (!bridge) {
    buildPavement(ctx, e, k, prof, outward);
    return;
  }
  ctx.mb.slab(raised(l, c.parapet_height_m), raised(r, c.parapet_height_m),
              std::vector<double>(l.size(), c.parapet_height_m), SurfaceKind::Parapet,
              SurfaceKind::Parapet);
}

void buildLanes(BuildContext& ctx) {
  const auto& c = ctx.cfg;
  const auto pairs = directedPairs(ctx.net);
  for (const auto& e : ctx.net.edges) {
    if (e.lanes.empty()) continue;
    const bool bridge = ctx.elevatedEdge(e);
    const bool two_way = pairs.count(e.to + "\x1f" + e.from) > 0;
    const EdgeProfile prof = edgeProfile(e, two_way);
    for (std::size_t k = 0; k < e.lanes.size(); ++k) {
      const SumoLane& lane = e.lanes[k];
      if (lane.shape.size() < 2) continue;
      const double w = lane.width_m / 2;
      const auto left = offsetPolyline(lane.shape, w), right = offsetPolyline(lane.shape, -w);
      buildLaneSurface(ctx, e, k, prof, bridge, pedestrianOnly(lane));
      keepOutStrip(ctx.roads, left, right, c.road_clearance_m);
      for (std::size_t i = 0; i + 1 < left.size(); ++i)
        if (ctx.elevation(lane.shape[i]) < c.elevated_min_m ||
            ctx.elevation(lane.shape[i + 1]) < c.elevated_min_m)
          ctx.ground_roads.add(inflateConvex(segmentQuad(left, right, i), 0.5));
    }
    // pavements: right of the rightmost lane; also left of the leftmost one on one-way streets
    // (two-way streets: the opposite edge brings its own right pavement)
    const SumoLane& first = e.lanes.front();
    if (first.shape.size() >= 2 && !pedestrianOnly(first))
      sideOfEdge(ctx, e, 0, prof, -1.0, bridge);
    const SumoLane& last = e.lanes.back();
    if (last.shape.size() >= 2 && !two_way && !pedestrianOnly(last))
      sideOfEdge(ctx, e, e.lanes.size() - 1, prof, +1.0, bridge);
  }
}

void buildJunctions(BuildContext& ctx) {
  const auto& c = ctx.cfg;
  std::unordered_map<std::string, std::vector<Point3>> ends;
  for (const auto& e : ctx.net.edges)
    for (const auto& lane : e.lanes) {
      if (lane.shape.size() < 2) continue;
      const double w = lane.width_m / 2;
      for (double off : {w, -w}) {
        const auto b = offsetPolyline(lane.shape, off);
        if (!e.to.empty()) ends[e.to].push_back(b.back());
        if (!e.from.empty()) ends[e.from].push_back(b.front());
      }
    }
  for (const auto& j : ctx.net.junctions) {
    auto it = ends.find(j.id);
    Polygon2 pts;
    double z = j.pos.z();
    if (it != ends.end() && !it->second.empty()) {
      z = 0;
      for (const auto& p : it->second) {
        pts.push_back(p.head<2>());
        z += p.z();
      }
      z /= static_cast<double>(it->second.size());
    }
    Polygon2 hull = convexHull(pts);
    const bool has_area = hull.size() >= 3 && std::abs(signedArea(hull)) > 1.0;
    if (has_area) {
      if (ctx.elevation(Point3(0, 0, z)) > 0.3) {
        ctx.mb.prism(hull, z - std::min(c.deck_thickness_m, ctx.elevation(Point3(0, 0, z))),
                     z - 0.01, SurfaceKind::Road);
      } else {
        buildJunctionSurface(ctx, hull, z - 0.01);
      }
    }
    // keep-out: the junction area grown by the clearance (a disc-like square for points)
    Polygon2 keep = has_area ? hull : orientedRect(j.pos.head<2>(), 0.0, 2.0, 2.0);
    ctx.roads.add(inflateConvex(keep, c.junction_clearance_m));
    if (ctx.elevation(Point3(0, 0, z)) < c.elevated_min_m)
      ctx.ground_roads.add(inflateConvex(keep, 0.5));
  }
}

void buildPillars(BuildContext& ctx) {
  const auto& c = ctx.cfg;
  if (c.pillar_spacing_m <= 0) return;
  for (const auto& e : ctx.net.edges) {
    if (!ctx.elevatedEdge(e)) continue;
    const Polyline& s = e.shape.size() >= 2 ? e.shape : e.lanes.front().shape;
    double next = c.pillar_spacing_m / 2, acc = 0;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
      const double len = (s[i + 1] - s[i]).head<2>().norm();
      while (len > 1e-9 && next <= acc + len) {
        const double f = (next - acc) / len;
        const Point3 p = s[i] + f * (s[i + 1] - s[i]);
        next += c.pillar_spacing_m;
        const double top = p.z() - c.deck_thickness_m;
        if (ctx.elevation(p) < c.elevated_min_m || top <= ctx.ground_z) continue;
        const double h = std::atan2(s[i + 1].y() - s[i].y(), s[i + 1].x() - s[i].x());
        const double a = 2 * c.pillar_half_size_m;
        const Polygon2 fp = orientedRect(p.head<2>(), h, a, a);
        if (ctx.ground_roads.overlaps(fp)) continue;  // never block the street below
        ctx.mb.prism(fp, ctx.ground_z - kFoundation_m, top, SurfaceKind::Pillar);
        ++ctx.stats.pillars;
      }
      acc += len;
    }
  }
}

/// Squares of kBlockCells x kBlockCells ground cells within ground_detail_reach_m of a lane,
/// sorted (the mesh must not depend on hash order).
constexpr int kBlockCells = 8;

std::vector<std::pair<long, long>> groundBlocksNearLanes(const BuildContext& ctx) {
  const double block = kBlockCells * ctx.cfg.ground_cell_m, reach = ctx.cfg.ground_detail_reach_m;
  std::set<std::pair<long, long>> blocks;
  auto mark = [&](const Point3& p) {
    const long bx0 = static_cast<long>(std::floor((p.x() - reach) / block));
    const long bx1 = static_cast<long>(std::floor((p.x() + reach) / block));
    const long by0 = static_cast<long>(std::floor((p.y() - reach) / block));
    const long by1 = static_cast<long>(std::floor((p.y() + reach) / block));
    for (long bx = bx0; bx <= bx1; ++bx)
      for (long by = by0; by <= by1; ++by) blocks.emplace(bx, by);
  };
  const double step = std::max(1.0, std::min(block, reach) / 2);
  for (const auto& e : ctx.net.edges)
    for (const auto& l : e.lanes)
      for (std::size_t i = 0; i + 1 < l.shape.size(); ++i) {
        const double len = (l.shape[i + 1] - l.shape[i]).head<2>().norm();
        const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
        for (int j = 0; j <= n; ++j)
          mark(l.shape[i] + (l.shape[i + 1] - l.shape[i]) * (static_cast<double>(j) / n));
      }
  return {blocks.begin(), blocks.end()};
}

/// Rough ground (verges, fields) near the lanes, kGroundBelowRoad_m below the road level plus
/// the verge relief; blocks share the vertices of their common borders bit for bit.
void buildRoughGround(BuildContext& ctx) {
  const double cell = ctx.cfg.ground_cell_m, base = ctx.ground_z - kGroundBelowRoad_m;
  for (const auto& [bx, by] : groundBlocksNearLanes(ctx)) {
    std::vector<std::vector<Point3>> rows;
    for (int j = 0; j <= kBlockCells; ++j) {  // right to left when travelling along +x
      std::vector<Point3> row;
      const double y = static_cast<double>(by * kBlockCells + j) * cell;
      for (int i = 0; i <= kBlockCells; ++i) {
        const double x = static_cast<double>(bx * kBlockCells + i) * cell;
        row.emplace_back(x, y, base + ctx.relief.verge(x, y));
      }
      rows.push_back(std::move(row));
    }
    ctx.mb.grid(rows, SurfaceKind::Ground);
  }
}

}  // namespace

bool BuildContext::elevatedEdge(const SumoEdge& e) const {
  for (const auto& l : e.lanes)
    for (const auto& p : l.shape)
      if (elevation(p) >= cfg.elevated_min_m) return true;
  return false;
}

void buildRoads(BuildContext& ctx) {
  buildLanes(ctx);
  buildJunctions(ctx);
  buildPillars(ctx);
}

void buildGround(BuildContext& ctx) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& v : ctx.mesh.vertices) {
    x0 = std::min<double>(x0, v.x());
    y0 = std::min<double>(y0, v.y());
    x1 = std::max<double>(x1, v.x());
    y1 = std::max<double>(y1, v.y());
  }
  if (x0 > x1) x0 = y0 = -100, x1 = y1 = 100;
  const double m = ctx.cfg.ground_margin_m, z = ctx.ground_z - kBasePlaneBelow_m;
  const int a = ctx.mb.vertex(Point3(x0 - m, y0 - m, z)),
            b = ctx.mb.vertex(Point3(x1 + m, y0 - m, z)),
            cc = ctx.mb.vertex(Point3(x1 + m, y1 + m, z)),
            d = ctx.mb.vertex(Point3(x0 - m, y1 + m, z));
  ctx.mb.quad(a, b, cc, d, SurfaceKind::Ground);
  buildRoughGround(ctx);
}

}  // namespace slamroute::simulate::detail
