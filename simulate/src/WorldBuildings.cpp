// World build steps: street classes and what lines each street — varied buildings, poles and
// trees (Rich), long uniform walls (Wall) or open fields with sparse poles (Open). Deterministic:
// each street draws from its own random stream seeded by (seed, street key), so the result does
// not depend on the order streets are visited in.
#include <algorithm>
#include <cmath>

#include "WorldBuild.hpp"

namespace slamroute::simulate::detail {

std::uint64_t hashSeed(std::uint64_t seed, const std::string& key) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char ch : key) h = (h ^ ch) * 1099511628211ULL;
  std::uint64_t z = h ^ (seed + 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

namespace {

/// Uniform draw in [a, b) from the 53 high bits (std::uniform_real_distribution is not
/// guaranteed identical across standard libraries; this is).
double uniform(std::mt19937_64& rng, double a, double b) {
  return a + (b - a) * static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
}

/// Arc-length parametrised 2D view of a polyline.
struct Path {
  std::vector<Point3> pts;
  std::vector<double> s;
  explicit Path(std::vector<Point3> p) : pts(std::move(p)), s(pts.size(), 0.0) {
    for (std::size_t i = 1; i < pts.size(); ++i)
      s[i] = s[i - 1] + (pts[i] - pts[i - 1]).head<2>().norm();
  }
  double length() const { return s.empty() ? 0.0 : s.back(); }
  /// Point and unit tangent at arc length t.
  std::pair<Vec2, Vec2> at(double t) const {
    std::size_t i = 0;
    while (i + 2 < pts.size() && s[i + 1] < t) ++i;
    const double len = std::max(1e-9, s[i + 1] - s[i]);
    const double f = std::clamp((t - s[i]) / len, 0.0, 1.0);
    const Vec2 a = pts[i].head<2>(), b = pts[i + 1].head<2>();
    Vec2 d = b - a;
    d = d.norm() > 1e-9 ? Vec2(d.normalized()) : Vec2(1, 0);
    return {a + f * (b - a), d};
  }
};

std::string streetKey(const SumoEdge& e) {
  if (e.from.empty() || e.to.empty()) return e.id;
  return std::min(e.from, e.to) + "|" + std::max(e.from, e.to);
}

class SidePlacer {
 public:
  SidePlacer(BuildContext& ctx, std::mt19937_64& rng, const Path& border)
      : ctx_(ctx), c_(ctx.cfg), rng_(rng), border_(border) {}

  /// Right-hand side of `border` (outward = right normal).
  void rich() {
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
    for (double s = uniform(rng_, 2, c_.pole_spacing_m); s < border_.length();
         s += c_.pole_spacing_m)
      pole(s, 7.0 + uniform(rng_, 0, 3));
    for (double s = uniform(rng_, 2, c_.tree_spacing_m); s < border_.length();
         s += c_.tree_spacing_m * uniform(rng_, 0.6, 1.4))
      tree(s, uniform(rng_, 1.2, 2.6), uniform(rng_, 4.0, 9.0));
  }

  void wall() {
    // long uniform walls: constant set-back and height, pieces follow the street's curvature
    const double piece = 6.0;
    for (double s = 1.0; s + 1.0 < border_.length(); s += piece) {
      const double len = std::min(piece, border_.length() - 1.0 - s);
      if (len < 1.0) break;
      if (place(s + len / 2, len + 0.05, c_.wall_setback_m, 0.4, c_.wall_height_m,
                SurfaceKind::Wall))
        ++ctx_.stats.walls;
    }
  }

  void open() {
    for (double s = uniform(rng_, 5, c_.open_pole_spacing_m); s < border_.length();
         s += c_.open_pole_spacing_m)
      pole(s, 7.0);
  }

 private:
  /// Rectangle centred at arc length s, `setback` behind the border, `depth` deep.
  bool place(double s, double frontage, double setback, double depth, double height,
             SurfaceKind kind) {
    const auto [p, t] = border_.at(s);
    const Vec2 out(t.y(), -t.x());  // right normal
    const Vec2 c = p + out * (setback + depth / 2);
    const Polygon2 fp = orientedRect(c, std::atan2(t.y(), t.x()), frontage, depth);
    if (ctx_.roads.overlaps(fp) || ctx_.placed.overlaps(fp)) return false;
    ctx_.placed.add(fp);
    ctx_.mb.prism(fp, ctx_.ground_z - 0.05, ctx_.ground_z + height, kind);
    return true;
  }
  void pole(double s, double height) {
    const auto [p, t] = border_.at(s);
    const Vec2 out(t.y(), -t.x());
    const Vec2 c = p - out * 0.5;  // on the sidewalk, 0.5 m inside its outer edge
    if (ctx_.placed.overlaps(orientedRect(c, 0, 0.4, 0.4))) return;
    ctx_.mb.cylinder(Point3(c.x(), c.y(), ctx_.ground_z), 0.12, height, 6, SurfaceKind::Pole);
    ++ctx_.stats.poles;
  }
  void tree(double s, double crown_r, double height) {
    const auto [p, t] = border_.at(s);
    const Vec2 out(t.y(), -t.x());
    const Vec2 c = p + out * (crown_r + c_.road_clearance_m + 0.3);
    const Polygon2 crown = orientedRect(c, 0, 2 * crown_r, 2 * crown_r);
    if (ctx_.roads.overlaps(crown) || ctx_.placed.overlaps(crown)) return;
    ctx_.placed.add(crown);
    const double trunk = std::min(2.5, height * 0.4);
    ctx_.mb.cylinder(Point3(c.x(), c.y(), ctx_.ground_z - 0.05), 0.2, trunk + 0.1, 6,
                     SurfaceKind::Tree);
    ctx_.mb.cylinder(Point3(c.x(), c.y(), ctx_.ground_z + trunk), crown_r, height - trunk, 8,
                     SurfaceKind::Tree);
    ++ctx_.stats.trees;
  }

  BuildContext& ctx_;
  const WorldConfig& c_;
  std::mt19937_64& rng_;
  const Path& border_;
};

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
    if (kind == StreetKind::Rich) ++ctx.stats.streets_rich;
    else if (kind == StreetKind::Wall) ++ctx.stats.streets_wall;
    else ++ctx.stats.streets_open;
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
      if (kind == StreetKind::Rich) placer.rich();
      else if (kind == StreetKind::Wall) placer.wall();
      else placer.open();
    }
  }
}

}  // namespace slamroute::simulate::detail
