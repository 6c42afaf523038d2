// World build steps: street classes and what lines each street — varied buildings, parked cars,
// lamp posts, signs and trees (Rich), long walls with pillars and gates (Wall), or open fields
// behind fences (Open). Deterministic: each street draws from its own random stream seeded by
// (seed, street key), so the result does not depend on the order streets are visited in.
#include <algorithm>
#include <cmath>

#include "WorldSide.hpp"

namespace slamroute::simulate::detail {

std::uint64_t hashSeed(std::uint64_t seed, const std::string& key) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char ch : key) h = (h ^ ch) * 1099511628211ULL;
  std::uint64_t z = h ^ (seed + 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::pair<Vec2, double> SidePlacer::spot(double s, double out_m) const {
  const auto [p, t] = border_.at(s);
  return {p + Vec2(t.y(), -t.x()) * out_m, std::atan2(t.y(), t.x())};
}

void SidePlacer::rich() {
  const double gap_scale = uniform(rng_, 0.3, 1.0);  // per-side density
  for (double s = 2.0; s < border_.length() - 2.0;) {
    const double f = uniform(rng_, c_.frontage_min_m, c_.frontage_max_m);
    const double setback = uniform(rng_, c_.setback_min_m, c_.setback_max_m);
    const double depth = uniform(rng_, c_.building_depth_min_m, c_.building_depth_max_m);
    const double u = uniform(rng_, 0, 1);
    const double height = c_.height_min_m + (c_.height_max_m - c_.height_min_m) * u * u;
    double gap = uniform(rng_, 0, c_.gap_max_m) * gap_scale;
    if (uniform(rng_, 0, 1) < 0.1) gap += uniform(rng_, 10, 30);  // an empty lot now and then
    const double ff = std::min(f, border_.length() - 2.0 - s);
    if (ff > 4.0 && place(s + ff / 2, ff, setback, depth, height, SurfaceKind::Building))
      ++ctx_.stats.buildings;
    s += ff + gap;
  }
  parkedCars(uniform(rng_, 0.3, 0.8));
  lampPosts(c_.pole_spacing_m, uniform(rng_, 7.0, 10.0));
  signsAndBollards(45.0);
  if (border_.length() > 60 && uniform(rng_, 0, 1) < 0.4)
    busShelter(uniform(rng_, 20, border_.length() - 20));
  for (double s = uniform(rng_, 2, c_.tree_spacing_m); s < border_.length();
       s += c_.tree_spacing_m * uniform(rng_, 0.6, 1.4))
    tree(s, uniform(rng_, 1.2, 2.6), uniform(rng_, 4.0, 9.0));
}

void SidePlacer::wall() {
  // long walls at one set-back, but no period along them: pieces of random length, height
  // steps, pillars at irregular spacing, gates
  double h = c_.wall_height_m;
  double next_gate = uniform(rng_, 20, 70);
  for (double s = 1.0; s + 1.0 < border_.length();) {
    const double len = std::min(uniform(rng_, 3.0, 9.0), border_.length() - 1.0 - s);
    if (len < 1.0) break;
    if (s > next_gate) {
      s += uniform(rng_, 3.0, 5.0);
      next_gate = s + uniform(rng_, 25, 80);
      continue;
    }
    if (uniform(rng_, 0, 1) < 0.3) h = c_.wall_height_m * uniform(rng_, 0.75, 1.4);
    if (place(s + len / 2, len, c_.wall_setback_m, 0.4, h, SurfaceKind::Wall)) {
      ++ctx_.stats.walls;
      for (double p = s + uniform(rng_, 0.3, 3.0); p < s + len; p += uniform(rng_, 2.5, 9.0)) {
        const auto [c, heading] = spot(p, c_.wall_setback_m - 0.1);
        ctx_.mb.box(Point3(c.x(), c.y(), ctx_.ground_z - kFoundation_m), heading, 0.5, 0.5,
                    h + 0.3 + kFoundation_m, SurfaceKind::Wall);
      }
    }
    s += len;
  }
  parkedCars(uniform(rng_, 0.0, 0.4));
  lampPosts(c_.pole_spacing_m, 8.0);
}

void SidePlacer::open() {
  fence();
  for (double s = uniform(rng_, 5, c_.open_pole_spacing_m); s < border_.length();
       s += c_.open_pole_spacing_m * uniform(rng_, 0.7, 1.3))
    lamp(s, 7.0);
  signsAndBollards(120.0);
}

bool SidePlacer::place(double s, double frontage, double setback, double depth, double height,
                       SurfaceKind kind) {
  const auto [front, heading] = spot(s, setback);
  const Vec2 out(std::sin(heading), -std::cos(heading));
  const Vec2 c = front + out * (depth / 2);
  // neighbours may touch (the check is a little smaller than what is built)
  const Polygon2 fp = orientedRect(c, heading, frontage, depth);
  const Polygon2 check = orientedRect(c, heading, std::max(0.1, frontage - 0.2), depth);
  if (ctx_.roads.overlaps(check) || ctx_.placed.overlaps(check)) return false;
  ctx_.placed.add(fp);
  if (kind == SurfaceKind::Building)
    building(front, heading, frontage, depth, height, setback - c_.road_clearance_m);
  else
    ctx_.mb.prism(fp, ctx_.ground_z - kFoundation_m, ctx_.ground_z + height, kind, false);
  return true;
}

void SidePlacer::tree(double s, double crown_r, double height) {
  const auto [c, heading] = spot(s, crown_r + c_.road_clearance_m + 0.3);
  (void)heading;
  const Polygon2 crown = orientedRect(c, 0, 2 * crown_r, 2 * crown_r);
  if (ctx_.roads.overlaps(crown) || ctx_.placed.overlaps(crown)) return;
  ctx_.placed.add(crown);
  const double trunk = std::min(2.5, height * 0.4);
  ctx_.mb.cylinder(Point3(c.x(), c.y(), ctx_.ground_z - kFoundation_m), 0.2, trunk + kFoundation_m,
                   6, SurfaceKind::Tree);
  ctx_.mb.cylinder(Point3(c.x(), c.y(), ctx_.ground_z + trunk), crown_r, height - trunk, 8,
                   SurfaceKind::Tree);
  ++ctx_.stats.trees;
}

namespace {

std::string streetKey(const SumoEdge& e) {
  if (e.from.empty() || e.to.empty()) return e.id;
  return std::min(e.from, e.to) + "|" + std::max(e.from, e.to);
}

}  // namespace

void buildStreetside(BuildContext& ctx) {
  const auto& c = ctx.cfg;
  std::unordered_map<std::string, bool> has_reverse;
  for (const auto& e : ctx.net.edges) has_reverse[e.from + "\x1f" + e.to] = true;
  // classes first (per street key, independent of order)
  for (const auto& e : ctx.net.edges) {
    const std::string key = streetKey(e);
    ctx.edge_street[e.id] = key;
    if (ctx.street_kind.count(key)) continue;
    std::mt19937_64 rng(hashSeed(ctx.seed, "class:" + key));
    const double u = uniform(rng, 0, 1);
    ctx.street_kind[key] = u < c.rich_share                  ? StreetKind::Rich
                           : u < c.rich_share + c.wall_share ? StreetKind::Wall
                                                             : StreetKind::Open;
  }
  for (const auto& [key, kind] : ctx.street_kind) {
    if (kind == StreetKind::Rich)
      ++ctx.stats.streets_rich;
    else if (kind == StreetKind::Wall)
      ++ctx.stats.streets_wall;
    else
      ++ctx.stats.streets_open;
  }
  if (!c.poly_file.empty()) return;  // buildings come from the polygon file instead
  // Placement in net order (deterministic); each side has its own random stream.
  for (const auto& e : ctx.net.edges) {
    if (e.lanes.empty() || e.lanes.front().shape.size() < 2 || ctx.elevatedEdge(e)) continue;
    const StreetKind kind = ctx.street_kind.at(ctx.edge_street.at(e.id));
    std::vector<Path> sides;
    const SumoLane& first = e.lanes.front();
    sides.emplace_back(offsetPolyline(first.shape, -(first.width_m / 2 + c.sidewalk_width_m)));
    if (!has_reverse.count(e.to + "\x1f" + e.from)) {
      const SumoLane& last = e.lanes.back();
      auto left = offsetPolyline(last.shape, last.width_m / 2 + c.sidewalk_width_m);
      std::reverse(left.begin(), left.end());
      sides.emplace_back(std::move(left));
    }
    for (std::size_t k = 0; k < sides.size(); ++k) {
      std::mt19937_64 rng(hashSeed(ctx.seed, "side:" + e.id + ":" + std::to_string(k)));
      SidePlacer placer(ctx, rng, sides[k]);
      if (kind == StreetKind::Rich)
        placer.rich();
      else if (kind == StreetKind::Wall)
        placer.wall();
      else
        placer.open();
    }
  }
}

}  // namespace slamroute::simulate::detail
