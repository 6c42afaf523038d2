// World build step: street furniture and clutter along one side of a street — lamp posts,
// parked cars, signs, bollards, bus shelters, and the post-and-rail fences of open streets.
// Each is a few boxes and prisms, so a LiDAR sees the shapes at a moderate triangle count.
#include <cmath>

#include "WorldSide.hpp"

namespace slamroute::simulate::detail {

namespace {
constexpr double kPavementInset_m = 0.5;  ///< posts stand this far inside the pavement's outer edge
}

void SidePlacer::lampPosts(double mean_spacing_m, double height_m) {
  // every 1 to 1.6 mean spacings (25-40 m for the default 25 m)
  for (double s = uniform(rng_, 2, mean_spacing_m); s < border_.length();
       s += mean_spacing_m * uniform(rng_, 1.0, 1.6))
    lamp(s, height_m + uniform(rng_, -0.5, 0.5));
}

void SidePlacer::lamp(double s, double height_m) {
  const auto [c, heading] = spot(s, -kPavementInset_m);
  if (ctx_.placed.overlaps(orientedRect(c, 0, 0.4, 0.4))) return;
  const double z0 = ctx_.ground_z - kFoundation_m;
  ctx_.mb.cylinder(Point3(c.x(), c.y(), z0), 0.12, height_m + kFoundation_m, 6, SurfaceKind::Pole);
  // the arm reaches out over the road, the lamp head hangs at its end
  const double toward_road = heading + M_PI / 2;
  const Vec2 in(std::cos(toward_road), std::sin(toward_road));
  const double arm =
      1.0 + 0.1 * static_cast<double>(ctx_.stats.poles % 5);  // ends over the pavement
  const Vec2 a = c + in * (arm / 2), h = c + in * arm;
  ctx_.mb.box(Point3(a.x(), a.y(), ctx_.ground_z + height_m - 0.15), toward_road, arm, 0.1, 0.1,
              SurfaceKind::Pole);
  ctx_.mb.box(Point3(h.x(), h.y(), ctx_.ground_z + height_m - 0.35), toward_road, 0.6, 0.3, 0.25,
              SurfaceKind::Pole);
  ++ctx_.stats.poles;
}

void SidePlacer::parkedCars(double share) {
  for (double s = uniform(rng_, 3, 12); s < border_.length() - 3;) {
    const double len = uniform(rng_, 3.8, 5.0);
    if (uniform(rng_, 0, 1) < share && parkedCar(s + len / 2, len)) ++ctx_.stats.parked_cars;
    s += len + uniform(rng_, 0.6, 2.5);
    if (uniform(rng_, 0, 1) < 0.15) s += uniform(rng_, 5, 25);  // a driveway, a free stretch
  }
}

bool SidePlacer::parkedCar(double s, double len) {
  const double width = uniform(rng_, 1.7, 1.95);
  const auto [c, heading] = spot(s, 0.25 + width / 2);  // in the bay beyond the pavement
  const Polygon2 fp = orientedRect(c, heading, len, width);
  if (ctx_.ground_roads.overlaps(fp) || ctx_.placed.overlaps(fp)) return false;
  ctx_.placed.add(fp);
  const double z = ctx_.ground_z;  // the car stands at road level; its wheels reach the ground
  const Vec2 u(std::cos(heading), std::sin(heading)), v(-u.y(), u.x());
  for (int k = 0; k < 4; ++k) {
    const Vec2 w =
        c + u * ((k & 1 ? 1 : -1) * (len / 2 - 0.8)) + v * ((k & 2 ? 1 : -1) * (width / 2 - 0.15));
    ctx_.mb.box(Point3(w.x(), w.y(), z - kGroundBelowRoad_m - 0.1), heading, 0.65, 0.25,
                0.35 + kGroundBelowRoad_m + 0.1, SurfaceKind::ParkedCar);
  }
  const double body_h = uniform(rng_, 0.55, 0.75);
  ctx_.mb.box(Point3(c.x(), c.y(), z + 0.3), heading, len, width, body_h, SurfaceKind::ParkedCar);
  const bool van = uniform(rng_, 0, 1) < 0.2;
  const double cabin = van ? len * 0.8 : len * uniform(rng_, 0.45, 0.6);
  const Vec2 cc = c - u * (van ? len * 0.08 : len * uniform(rng_, 0.0, 0.12));
  ctx_.mb.box(Point3(cc.x(), cc.y(), z + 0.3 + body_h), heading, cabin, width - 0.12,
              van ? uniform(rng_, 0.9, 1.3) : uniform(rng_, 0.4, 0.55), SurfaceKind::ParkedCar);
  return true;
}

void SidePlacer::signsAndBollards(double mean_spacing_m) {
  const double kerb = c_.sidewalk_width_m - 0.35;  // near the kerb, on the pavement
  for (double s = uniform(rng_, 3, mean_spacing_m); s < border_.length() - 2;
       s += mean_spacing_m * uniform(rng_, 0.5, 1.5)) {
    if (uniform(rng_, 0, 1) < 0.6) {
      const auto [c, heading] = spot(s, -kerb);
      const double h = uniform(rng_, 2.2, 2.8);
      ctx_.mb.cylinder(Point3(c.x(), c.y(), ctx_.ground_z - kFoundation_m), 0.04, h + kFoundation_m,
                       6, SurfaceKind::Furniture);
      const double plate = uniform(rng_, 0.5, 0.9);
      ctx_.mb.box(Point3(c.x(), c.y(), ctx_.ground_z + h - plate), heading + M_PI / 2, plate, 0.04,
                  plate, SurfaceKind::Furniture);
    } else {
      const int n = 2 + static_cast<int>(uniform(rng_, 0, 5));
      for (int k = 0; k < n; ++k) {
        const auto [c, heading] = spot(s + 1.5 * k, -kerb);
        (void)heading;
        ctx_.mb.cylinder(Point3(c.x(), c.y(), ctx_.ground_z - kFoundation_m), 0.09,
                         0.9 + kFoundation_m, 6, SurfaceKind::Furniture);
      }
    }
    ++ctx_.stats.furniture;
  }
}

void SidePlacer::busShelter(double s) {
  const auto [c, heading] = spot(s, 1.0);  // just beyond the pavement
  const Polygon2 fp = orientedRect(c, heading, 4.0, 1.8);
  if (ctx_.ground_roads.overlaps(fp) || ctx_.placed.overlaps(fp)) return;
  ctx_.placed.add(fp);
  const Vec2 u(std::cos(heading), std::sin(heading)), out(u.y(), -u.x());
  const double z = ctx_.ground_z - kFoundation_m, h = 2.4 + kFoundation_m;
  const Vec2 back = c + out * 0.75, l = c - u * 1.85, r = c + u * 1.85;
  ctx_.mb.box(Point3(back.x(), back.y(), z), heading, 3.8, 0.08, h, SurfaceKind::Furniture);
  ctx_.mb.box(Point3(l.x(), l.y(), z), heading, 0.08, 1.5, h, SurfaceKind::Furniture);
  ctx_.mb.box(Point3(r.x(), r.y(), z), heading, 0.08, 1.5, h, SurfaceKind::Furniture);
  ctx_.mb.box(Point3(c.x(), c.y(), ctx_.ground_z + 2.4), heading, 4.0, 1.8, 0.12,
              SurfaceKind::Furniture);
  ++ctx_.stats.furniture;
}

void SidePlacer::fence() {
  // post-and-rail, some metres beyond the pavement: posts every 2-3 m, two rails, a gate now
  // and then; it stops where it would reach a road or junction
  const double off = uniform(rng_, 1.5, 6.0), h = uniform(rng_, 1.0, 1.4);
  const double z0 = ctx_.ground_z - kFoundation_m;
  bool have_prev = false;
  Vec2 prev(0, 0);
  for (double s = uniform(rng_, 0.5, 3.0); s < border_.length(); s += uniform(rng_, 2.0, 3.0)) {
    const auto [p, heading] = spot(s, off + uniform(rng_, -0.08, 0.08));
    if (ctx_.ground_roads.overlaps(orientedRect(p, heading, 0.3, 0.3)) ||
        ctx_.placed.overlaps(orientedRect(p, heading, 0.3, 0.3))) {
      have_prev = false;
      continue;
    }
    ctx_.mb.box(Point3(p.x(), p.y(), z0), heading, 0.12, 0.12, h + kFoundation_m,
                SurfaceKind::Fence);
    ++ctx_.stats.fence_posts;
    const bool gate = uniform(rng_, 0, 1) < 0.04;
    if (have_prev && !gate) {
      const Vec2 m = (prev + p) / 2, d = p - prev;
      const double a = std::atan2(d.y(), d.x());
      for (double rail : {0.35, h - 0.25})
        ctx_.mb.box(Point3(m.x(), m.y(), ctx_.ground_z + rail), a, d.norm(), 0.05, 0.12,
                    SurfaceKind::Fence);
    }
    prev = p;
    have_prev = true;
  }
}

}  // namespace slamroute::simulate::detail
