// World build step: a building's volumes and facade. A building is a ground storey with door
// recesses, a body with recessed window columns (and on some, floor bands and balconies), and on
// taller ones a set-back top volume; every measure is drawn per building, so no two neighbours
// are alike and nothing repeats along a street. Insets are notches in the footprint, so a facade
// costs tens of triangles, not thousands.
#include <cmath>

#include "WorldSide.hpp"

namespace slamroute::simulate::detail {

namespace {

/// Local frame of a building: a along the street, b from the front face into the building.
struct Frame {
  Vec2 front, u, n;
  Vec2 at(double a, double b) const { return front + u * a + n * b; }
};

/// Footprint [-f/2, f/2] x [b0, b1] with rectangular notches (a0, a1, depth) cut into its front.
Polygon2 notchedFootprint(const Frame& fr, double f, double b0, double b1,
                          const std::vector<std::array<double, 3>>& notches) {
  Polygon2 p{fr.at(-f / 2, b1), fr.at(-f / 2, b0)};
  for (const auto& [a0, a1, d] : notches) {
    p.push_back(fr.at(a0, b0));
    p.push_back(fr.at(a0, b0 + d));
    p.push_back(fr.at(a1, b0 + d));
    p.push_back(fr.at(a1, b0));
  }
  p.push_back(fr.at(f / 2, b0));
  p.push_back(fr.at(f / 2, b1));
  return p;
}

/// Heights of a building's parts [m].
struct Storeys {
  double z, ground_h, body_top, storey;
};

/// Floor bands on some buildings, balconies in one to three columns on others (where `reach`, the
/// free space before the body, allows).
void facadeDetails(BuildContext& ctx, std::mt19937_64& rng, const Frame& fr, double heading,
                   double f, double shift, const Storeys& st, double reach) {
  if (uniform(rng, 0, 1) < 0.5) {
    for (double h = st.ground_h + st.storey; h < st.body_top - 1.0; h += st.storey) {
      const Vec2 c = fr.at(0, shift - 0.07);
      ctx.mb.box(Point3(c.x(), c.y(), st.z + h - 0.15), heading, f, 0.14, 0.25,
                 SurfaceKind::Building);
    }
  }
  if (!(reach > 0.7 && uniform(rng, 0, 1) < 0.45)) return;
  const int cols = 1 + static_cast<int>(uniform(rng, 0, 3));
  for (int k = 0; k < cols; ++k) {
    const double a = -f / 2 + f * (k + uniform(rng, 0.25, 0.75)) / cols;
    const double w = std::min(f / cols - 0.4, uniform(rng, 1.8, 3.2));
    for (double h = st.ground_h + st.storey; h < st.body_top - 2.0; h += st.storey) {
      const Vec2 c = fr.at(a, shift - reach / 2);
      ctx.mb.box(Point3(c.x(), c.y(), st.z + h - 0.2), heading, w, reach, 0.2,
                 SurfaceKind::Building);
      const Vec2 rail = fr.at(a, shift - reach + 0.04);
      ctx.mb.box(Point3(rail.x(), rail.y(), st.z + h), heading, w, 0.08, 1.0,
                 SurfaceKind::Building);
    }
  }
}

/// Set-back top volume, narrower than the body, from body_top to height.
void topVolume(BuildContext& ctx, std::mt19937_64& rng, const Frame& fr, double f, double depth,
               double shift, const Storeys& st, double height) {
  const double back = uniform(rng, 1.5, std::max(1.6, depth / 3));
  const double l = uniform(rng, 0, f / 4), r = uniform(rng, 0, f / 4);
  const double b1 = depth - uniform(rng, 0, depth / 4);
  if (b1 - back < 3 || f - l - r < 4) return;
  const Frame tf{fr.at((l - r) / 2, 0), fr.u, fr.n};
  ctx.mb.prism(notchedFootprint(tf, f - l - r, shift + back, b1, {}), st.z + st.body_top - 0.05,
               st.z + height, SurfaceKind::Building, false);
}

}  // namespace

void SidePlacer::building(const Vec2& front, double heading, double f, double depth, double height,
                          double room_in_front) {
  const Frame fr{front, Vec2(std::cos(heading), std::sin(heading)),
                 Vec2(std::sin(heading), -std::cos(heading))};
  const double z = ctx_.ground_z;
  const double ground_h = height > 7 ? uniform(rng_, 3.2, 4.6) : height;
  // ground storey: one or two door recesses
  std::vector<std::array<double, 3>> doors;
  const int n_doors = f > 12 ? 2 : 1;
  for (int k = 0; k < n_doors; ++k) {
    const double w = uniform(rng_, 1.1, 2.2);
    const double a = -f / 2 + f * (k + uniform(rng_, 0.2, 0.8)) / n_doors;
    doors.push_back({a - w / 2, a + w / 2, uniform(rng_, 0.3, 0.8)});
  }
  ctx_.mb.prism(notchedFootprint(fr, f, 0, depth, doors), z - kFoundation_m, z + ground_h,
                SurfaceKind::Building, false);
  if (height <= ground_h + 0.5) return;
  const bool top = height > 14 && uniform(rng_, 0, 1) < 0.55;
  const double top_h = top ? uniform(rng_, 3.0, std::min(9.0, height / 3)) : 0.0;
  const double body_top = height - top_h;
  // body: flush, set back or overhanging the ground storey; window columns at jittered spacing
  const double shift = uniform(rng_, -std::min(0.6, room_in_front - 0.2), 0.6);
  const double pitch = uniform(rng_, 2.3, 3.8),
               win = uniform(rng_, 0.9, 1.5) * std::min(1.0, pitch / 2.6);
  const double inset = uniform(rng_, 0.15, 0.35);
  std::vector<std::array<double, 3>> windows;
  for (double a = -f / 2 + uniform(rng_, 0.8, pitch); a + win / 2 < f / 2 - 0.6; a += pitch) {
    const double c = a + uniform(rng_, -0.2, 0.2);
    if (c - win / 2 > -f / 2 + 0.6) windows.push_back({c - win / 2, c + win / 2, inset});
  }
  ctx_.mb.prism(notchedFootprint(fr, f, shift, depth, windows), z + ground_h, z + body_top,
                SurfaceKind::Building, false);
  const double storey = uniform(rng_, 2.9, 3.6);
  const Storeys st{z, ground_h, body_top, storey};
  facadeDetails(ctx_, rng_, fr, heading, f, shift, st, std::min(1.3, room_in_front + shift - 0.2));
  if (top) topVolume(ctx_, rng_, fr, f, depth, shift, st, height);
}

}  // namespace slamroute::simulate::detail
