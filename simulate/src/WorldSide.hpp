#pragma once
// Internal: what lines one side of a street (World::build's streetside step). SidePlacer's
// buildings and walls are in WorldBuildings.cpp, its facades in WorldFacades.cpp, its street
// furniture in WorldFurniture.cpp.
#include <algorithm>
#include <random>

#include "WorldBuild.hpp"

namespace slamroute::simulate::detail {

/// Uniform draw in [a, b) from the 53 high bits (std::uniform_real_distribution is not
/// guaranteed identical across standard libraries; this is).
inline double uniform(std::mt19937_64& rng, double a, double b) {
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

/// The right-hand side of `border` (the pavement's outer edge; outward = right normal).
class SidePlacer {
 public:
  SidePlacer(BuildContext& ctx, std::mt19937_64& rng, const Path& border)
      : ctx_(ctx), c_(ctx.cfg), rng_(rng), border_(border) {}

  void rich();
  void wall();
  void open();

 private:
  /// Point `out_m` metres outward of the border at arc length s (negative: on the pavement),
  /// and the street's heading there.
  std::pair<Vec2, double> spot(double s, double out_m) const;

  // WorldBuildings.cpp
  bool place(double s, double frontage, double setback, double depth, double height,
             SurfaceKind kind);
  void tree(double s, double crown_r, double height);
  // WorldFacades.cpp
  /// Building whose front face is centred at `front_centre`; `room_in_front_m` is free space
  /// before it (overhangs and balconies stay within it).
  void building(const Vec2& front_centre, double heading, double frontage, double depth,
                double height, double room_in_front_m);
  // WorldFurniture.cpp
  void lampPosts(double mean_spacing_m, double height_m);
  void lamp(double s, double height_m);
  void parkedCars(double share);
  bool parkedCar(double s, double length_m);
  void signsAndBollards(double mean_spacing_m);
  void busShelter(double s);
  void fence();

  BuildContext& ctx_;
  const WorldConfig& c_;
  std::mt19937_64& rng_;
  const Path& border_;
};

}  // namespace slamroute::simulate::detail
