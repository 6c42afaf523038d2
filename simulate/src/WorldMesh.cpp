#include "WorldMesh.hpp"

#include <algorithm>
#include <cmath>

namespace slamroute::simulate::detail {

int MeshBuilder::vertex(const Point3& p) {
  m_.vertices.push_back(p.cast<float>());
  return static_cast<int>(m_.vertices.size()) - 1;
}

void MeshBuilder::tri(int a, int b, int c, SurfaceKind k) {
  m_.triangles.emplace_back(a, b, c);
  m_.kinds.push_back(k);
}

void MeshBuilder::quad(int a, int b, int c, int d, SurfaceKind k) {
  tri(a, b, c, k);
  tri(a, c, d, k);
}

void MeshBuilder::strip(const std::vector<Point3>& left, const std::vector<Point3>& right,
                        SurfaceKind k) {
  const std::size_t n = std::min(left.size(), right.size());
  if (n < 2) return;
  std::vector<int> L(n), R(n);
  for (std::size_t i = 0; i < n; ++i) {
    L[i] = vertex(left[i]);
    R[i] = vertex(right[i]);
  }
  // direction of travel i -> i+1, left is +y: right[i], right[i+1], left[i+1], left[i] is CCW
  for (std::size_t i = 0; i + 1 < n; ++i) quad(R[i], R[i + 1], L[i + 1], L[i], k);
}

void MeshBuilder::slab(const std::vector<Point3>& left, const std::vector<Point3>& right,
                       const std::vector<double>& thickness, SurfaceKind top, SurfaceKind sides) {
  if (std::min({left.size(), right.size(), thickness.size()}) < 2) return;
  strip(left, right, top);
  slabSides(left, right, thickness, sides);
}

void MeshBuilder::slabSides(const std::vector<Point3>& left, const std::vector<Point3>& right,
                            const std::vector<double>& thickness, SurfaceKind sides) {
  const std::size_t n = std::min({left.size(), right.size(), thickness.size()});
  if (n < 2) return;
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) any = any || thickness[i] > 1e-3;
  if (!any) return;
  std::vector<Point3> lb(n), rb(n);
  for (std::size_t i = 0; i < n; ++i) {
    lb[i] = left[i] - Vec3(0, 0, thickness[i]);
    rb[i] = right[i] - Vec3(0, 0, thickness[i]);
  }
  strip(rb, lb, sides);  // bottom, facing down (reversed orientation)
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (thickness[i] <= 1e-3 && thickness[i + 1] <= 1e-3) continue;
    // right side wall and left side wall
    quad(vertex(right[i]), vertex(rb[i]), vertex(rb[i + 1]), vertex(right[i + 1]), sides);
    quad(vertex(left[i + 1]), vertex(lb[i + 1]), vertex(lb[i]), vertex(left[i]), sides);
  }
  if (thickness[0] > 1e-3)
    quad(vertex(left[0]), vertex(lb[0]), vertex(rb[0]), vertex(right[0]), sides);
  if (thickness[n - 1] > 1e-3)
    quad(vertex(right[n - 1]), vertex(rb[n - 1]), vertex(lb[n - 1]), vertex(left[n - 1]), sides);
}

void MeshBuilder::grid(const std::vector<std::vector<Point3>>& rows, SurfaceKind k) {
  if (rows.size() < 2) return;
  std::size_t n = rows.front().size();
  for (const auto& r : rows) n = std::min(n, r.size());
  if (n < 2) return;
  std::vector<std::vector<int>> id(rows.size(), std::vector<int>(n));
  for (std::size_t j = 0; j < rows.size(); ++j)
    for (std::size_t i = 0; i < n; ++i) id[j][i] = vertex(rows[j][i]);
  for (std::size_t j = 0; j + 1 < rows.size(); ++j)
    for (std::size_t i = 0; i + 1 < n; ++i)
      quad(id[j][i], id[j][i + 1], id[j + 1][i + 1], id[j + 1][i], k);
}

void MeshBuilder::prism(const Polygon2& fp, double z0, double z1, SurfaceKind k, bool bottom) {
  const int n = static_cast<int>(fp.size());
  if (n < 3) return;
  Polygon2 p = fp;
  if (signedArea(p) < 0) std::reverse(p.begin(), p.end());
  std::vector<int> lo(n), hi(n);
  for (int i = 0; i < n; ++i) {
    lo[i] = vertex(Point3(p[i].x(), p[i].y(), z0));
    hi[i] = vertex(Point3(p[i].x(), p[i].y(), z1));
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    quad(lo[i], lo[j], hi[j], hi[i], k);
  }
  for (const auto& t : triangulate(p)) {
    tri(hi[t[0]], hi[t[1]], hi[t[2]], k);
    if (bottom) tri(lo[t[0]], lo[t[2]], lo[t[1]], k);
  }
}

void MeshBuilder::box(const Point3& c, double heading, double length, double width, double height,
                      SurfaceKind k) {
  prism(orientedRect(c.head<2>(), heading, length, width), c.z(), c.z() + height, k);
}

void MeshBuilder::cylinder(const Point3& c, double radius, double height, int sides,
                           SurfaceKind k) {
  Polygon2 p;
  for (int i = 0; i < sides; ++i) {
    const double a = 2.0 * M_PI * i / sides;
    p.emplace_back(c.x() + radius * std::cos(a), c.y() + radius * std::sin(a));
  }
  prism(p, c.z(), c.z() + height, k);
}

Polygon2 orientedRect(const Vec2& c, double heading, double length, double width) {
  const Vec2 u(std::cos(heading), std::sin(heading)), v(-u.y(), u.x());
  const Vec2 a = u * (length / 2), b = v * (width / 2);
  return {c - a - b, c + a - b, c + a + b, c - a + b};
}

double signedArea(const Polygon2& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % p.size()];
    s += a.x() * b.y() - b.x() * a.y();
  }
  return s / 2;
}

namespace {
bool separated(const Polygon2& a, const Polygon2& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 e = a[(i + 1) % a.size()] - a[i];
    const Vec2 n(-e.y(), e.x());
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (const auto& p : a) {
      const double d = n.dot(p);
      amin = std::min(amin, d);
      amax = std::max(amax, d);
    }
    for (const auto& p : b) {
      const double d = n.dot(p);
      bmin = std::min(bmin, d);
      bmax = std::max(bmax, d);
    }
    if (amax < bmin || bmax < amin) return true;
  }
  return false;
}
double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}
}  // namespace

bool convexOverlap(const Polygon2& a, const Polygon2& b) {
  if (a.size() < 3 || b.size() < 3) return false;
  return !separated(a, b) && !separated(b, a);
}

Polygon2 convexHull(Polygon2 pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (pts.size() < 3) return pts;
  Polygon2 h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i - 1]) <= 0) --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  return h;
}

Polygon2 inflateConvex(const Polygon2& poly, double d) {
  Polygon2 p = poly;
  if (p.size() < 3) return p;
  if (signedArea(p) < 0) std::reverse(p.begin(), p.end());
  const std::size_t n = p.size();
  Polygon2 out(n);
  auto outward = [&](std::size_t i) {  // outward unit normal of edge i -> i+1 (CCW polygon)
    const Vec2 e = p[(i + 1) % n] - p[i];
    const double len = e.norm();
    return len > 1e-12 ? Vec2(e.y() / len, -e.x() / len) : Vec2(0, 0);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 n1 = outward((i + n - 1) % n), n2 = outward(i);
    const double c = 1.0 + n1.dot(n2);
    // mitred corner: both adjacent edges move out by d (clamped for very sharp corners)
    out[i] = p[i] + (n1 + n2) * (d / std::max(c, 0.25));
  }
  return out;
}

std::vector<std::array<int, 3>> triangulate(const Polygon2& p) {
  std::vector<std::array<int, 3>> out;
  std::vector<int> idx(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) idx[i] = static_cast<int>(i);
  auto inside = [&](const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& q) {
    return cross(a, b, q) > 0 && cross(b, c, q) > 0 && cross(c, a, q) > 0;
  };
  std::size_t guard = 0;
  while (idx.size() > 3 && guard++ < p.size() * p.size() + 10) {
    bool clipped = false;
    for (std::size_t i = 0; i < idx.size(); ++i) {
      const int ia = idx[(i + idx.size() - 1) % idx.size()], ib = idx[i],
                ic = idx[(i + 1) % idx.size()];
      if (cross(p[ia], p[ib], p[ic]) <= 0) continue;
      bool ear = true;
      for (int j : idx)
        if (j != ia && j != ib && j != ic && inside(p[ia], p[ib], p[ic], p[j])) {
          ear = false;
          break;
        }
      if (!ear) continue;
      out.push_back({ia, ib, ic});
      idx.erase(idx.begin() + static_cast<long>(i));
      clipped = true;
      break;
    }
    if (!clipped) break;  // degenerate polygon: fan the rest
  }
  for (std::size_t i = 1; i + 1 < idx.size(); ++i) out.push_back({idx[0], idx[i], idx[i + 1]});
  return out;
}

std::vector<Point3> offsetPolyline(const std::vector<Point3>& line, double offset) {
  const std::size_t n = line.size();
  std::vector<Point3> out(n);
  if (n < 2) return line;
  auto seg = [&](std::size_t i) { return Vec2((line[i + 1] - line[i]).head<2>()); };
  auto dir = [&](std::size_t i) {  // unit 2D direction of segment i -> i+1, skipping repeats
    for (std::size_t j = i; j + 1 < n; ++j)
      if (seg(j).norm() > 1e-6) return Vec2(seg(j).normalized());
    for (std::size_t j = i; j-- > 0;)
      if (seg(j).norm() > 1e-6) return Vec2(seg(j).normalized());
    return Vec2(1, 0);
  };
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 nrm;
    double scale = 1.0;
    if (i == 0) {
      const Vec2 d = dir(0);
      nrm = Vec2(-d.y(), d.x());
    } else if (i == n - 1) {
      const Vec2 d = dir(n - 2);
      nrm = Vec2(-d.y(), d.x());
    } else {
      const Vec2 d0 = dir(i - 1), d1 = dir(i);
      const Vec2 n0(-d0.y(), d0.x()), n1(-d1.y(), d1.x());
      Vec2 m = n0 + n1;
      if (m.norm() < 1e-6) m = n0;
      m.normalize();
      const double c = std::max(0.5, m.dot(n0));  // mitre, clamped at 60 degrees
      nrm = m;
      scale = 1.0 / c;
    }
    out[i] = line[i];
    out[i].head<2>() += nrm * offset * scale;
  }
  return out;
}

std::vector<std::pair<long, long>> KeepOutGrid::cellsOf(const Polygon2& p) const {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& q : p) {
    x0 = std::min(x0, q.x());
    y0 = std::min(y0, q.y());
    x1 = std::max(x1, q.x());
    y1 = std::max(y1, q.y());
  }
  std::vector<std::pair<long, long>> out;
  for (long ix = static_cast<long>(std::floor(x0 / cell_));
       ix <= static_cast<long>(std::floor(x1 / cell_)); ++ix)
    for (long iy = static_cast<long>(std::floor(y0 / cell_));
         iy <= static_cast<long>(std::floor(y1 / cell_)); ++iy)
      out.emplace_back(ix, iy);
  return out;
}

void KeepOutGrid::add(const Polygon2& convex) {
  const int id = static_cast<int>(polys_.size());
  polys_.push_back(convex);
  for (const auto& [ix, iy] : cellsOf(convex)) cells_[key(ix, iy)].push_back(id);
}

bool KeepOutGrid::overlaps(const Polygon2& convex) const {
  for (const auto& [ix, iy] : cellsOf(convex)) {
    const auto it = cells_.find(key(ix, iy));
    if (it == cells_.end()) continue;
    for (int id : it->second)
      if (convexOverlap(polys_[static_cast<std::size_t>(id)], convex)) return true;
  }
  return false;
}

}  // namespace slamroute::simulate::detail
