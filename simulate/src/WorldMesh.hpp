#pragma once
// Internal: appending primitives (strips, slabs, prisms, boxes, cylinders) to a TriangleMesh,
// and small 2D polygon helpers used to keep buildings off the roads.
#include <array>
#include <unordered_map>
#include <vector>

#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate::detail {

using Vec2 = Eigen::Vector2d;
using Polygon2 = std::vector<Vec2>;  ///< counter-clockwise

class MeshBuilder {
 public:
  explicit MeshBuilder(TriangleMesh& mesh) : m_(mesh) {}
  int vertex(const Point3& p);
  void tri(int a, int b, int c, SurfaceKind k);
  void quad(int a, int b, int c, int d, SurfaceKind k);  ///< a-b-c-d counter-clockwise
  /// Horizontal-ish strip between a left and a right border (same length), facing up.
  void strip(const std::vector<Point3>& left, const std::vector<Point3>& right, SurfaceKind k);
  /// Closed vertical prism over a simple polygon footprint (CCW), from z0 to z1, with top and
  /// bottom caps (ear clipping for concave footprints).
  void prism(const Polygon2& footprint, double z0, double z1, SurfaceKind k, bool bottom = true);
  /// Oriented box: centre of the bottom face, heading [rad] of the length axis, extents.
  void box(const Point3& bottom_centre, double heading, double length, double width, double height,
           SurfaceKind k);
  /// Vertical n-gon cylinder.
  void cylinder(const Point3& bottom_centre, double radius, double height, int sides,
                SurfaceKind k);
  /// Slab whose top follows the strip and whose bottom is `thickness[i]` below it (per point);
  /// sides are closed. Degenerate (zero-thickness) sides are skipped.
  void slab(const std::vector<Point3>& left, const std::vector<Point3>& right,
            const std::vector<double>& thickness, SurfaceKind top, SurfaceKind sides);
  /// The bottom and the side walls of such a slab without its top (a grid() lies there).
  void slabSides(const std::vector<Point3>& left, const std::vector<Point3>& right,
                 const std::vector<double>& thickness, SurfaceKind sides);
  /// Surface through rows of points (same length each), ordered right to left across the
  /// direction of travel, facing up; neighbouring rows share their vertices.
  void grid(const std::vector<std::vector<Point3>>& rows, SurfaceKind k);
  /// Triangle a-b-c (counter-clockwise from above) cut into n x n pieces, each new vertex lifted
  /// by lift(x, y).
  template <class Lift>
  void subdividedTriangle(const Point3& a, const Point3& b, const Point3& c, int n, Lift lift,
                          SurfaceKind k);

 private:
  TriangleMesh& m_;
};

template <class Lift>
void MeshBuilder::subdividedTriangle(const Point3& a, const Point3& b, const Point3& c, int n,
                                     Lift lift, SurfaceKind k) {
  // vertex (i, j), i + j <= n: a + (b - a) i / n + (c - a) j / n
  std::vector<int> idx;
  auto at = [&](int i, int j) { return idx[static_cast<std::size_t>(i * (n + 1) + j)]; };
  idx.assign(static_cast<std::size_t>((n + 1) * (n + 1)), -1);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      Point3 p = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
      p.z() += lift(p.x(), p.y());
      idx[static_cast<std::size_t>(i * (n + 1) + j)] = vertex(p);
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      tri(at(i, j), at(i + 1, j), at(i, j + 1), k);
      if (i + j + 1 < n) tri(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), k);
    }
}

/// Oriented rectangle footprint (CCW) centred at c.
Polygon2 orientedRect(const Vec2& c, double heading, double length, double width);
/// Convex polygons intersect (separating axis theorem). Both CCW or CW.
bool convexOverlap(const Polygon2& a, const Polygon2& b);
/// Convex hull (Andrew's monotone chain), CCW.
Polygon2 convexHull(Polygon2 pts);
/// Polygon grown outward by `d` along each vertex's averaged normal (approximate for convex).
Polygon2 inflateConvex(const Polygon2& p, double d);
double signedArea(const Polygon2& p);
/// Ear-clipping triangulation of a simple polygon (CCW); returns index triples.
std::vector<std::array<int, 3>> triangulate(const Polygon2& p);

/// Left/right offsets of a 3D polyline in the xy plane (mitred, clamped), keeping z.
std::vector<Point3> offsetPolyline(const std::vector<Point3>& line, double offset);

/// A uniform grid over the plane holding convex "keep-out" polygons (roads, junctions, placed
/// buildings) for fast overlap queries.
class KeepOutGrid {
 public:
  explicit KeepOutGrid(double cell_m = 20.0) : cell_(cell_m) {}
  void add(const Polygon2& convex);
  bool overlaps(const Polygon2& convex) const;

 private:
  long key(long ix, long iy) const { return ix * 73856093L ^ iy * 19349663L; }
  double cell_;
  std::vector<Polygon2> polys_;
  std::unordered_map<long, std::vector<int>> cells_;
  std::vector<std::pair<long, long>> cellsOf(const Polygon2& p) const;
};

}  // namespace slamroute::simulate::detail
