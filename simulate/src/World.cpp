// World::build reads as the steps of building the city; the steps live in WorldRoads.cpp,
// WorldBuildings.cpp and WorldPolyBuildings.cpp; export in WorldExport.cpp.
#include "slamroute/simulate/World.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "WorldBoxes.hpp"
#include "WorldBuild.hpp"
#include "WorldImpl.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::simulate {

const char* surfaceKindName(SurfaceKind k) {
  static const char* names[] = {"ground",  "road",      "sidewalk",   "deck", "pillar",
                                "parapet", "building",  "wall",       "pole", "tree",
                                "vehicle", "furniture", "parked_car", "fence"};
  return names[static_cast<int>(k)];
}

const char* streetKindName(StreetKind k) {
  static const char* names[] = {"open", "wall", "rich"};
  return names[static_cast<int>(k)];
}

namespace {

void validate(const WorldConfig& c) {
  auto bad = [](const std::string& m) { throw std::invalid_argument("simulate.world: " + m); };
  if (c.sidewalk_width_m < 0 || c.curb_height_m < 0 || c.deck_thickness_m < 0) bad("negative size");
  if (c.rich_share < 0 || c.wall_share < 0 || c.rich_share + c.wall_share > 1.0)
    bad("rich_share and wall_share must be >= 0 and sum to <= 1");
  if (c.frontage_min_m <= 0 || c.frontage_max_m < c.frontage_min_m) bad("frontage range");
  if (c.building_depth_min_m <= 0 || c.building_depth_max_m < c.building_depth_min_m)
    bad("depth range");
  if (c.height_min_m <= 0 || c.height_max_m < c.height_min_m) bad("height range");
  if (c.setback_min_m < 0 || c.setback_max_m < c.setback_min_m) bad("setback range");
  if (c.pole_spacing_m <= 0 || c.tree_spacing_m <= 0 || c.open_pole_spacing_m <= 0)
    bad("spacing <= 0");
  if (c.elevated_min_m <= 0) bad("elevated_min_m must be > 0");
  if (c.road_camber_pct < 0 || c.road_camber_pct > 10) bad("road_camber_pct must be in [0, 10]");
  if (c.undulation_m < 0 || c.undulation_m > 0.2) bad("undulation_m must be in [0, 0.2]");
  if (c.undulation_wavelength_m < 2) bad("undulation_wavelength_m must be >= 2");
  if (c.road_roughness_m < 0 || c.road_roughness_m > 0.05)
    bad("road_roughness_m must be in [0, 0.05]");
  if (c.verge_roughness_m < 0 || c.verge_roughness_m > 0.1)
    bad("verge_roughness_m must be in [0, 0.1]");
  if (c.road_cell_m < 0.25 || c.road_cell_m > 10) bad("road_cell_m must be in [0.25, 10]");
  if (c.ground_cell_m < 0.5 || c.ground_cell_m > 50) bad("ground_cell_m must be in [0.5, 50]");
  if (c.ground_detail_reach_m < 0) bad("ground_detail_reach_m must be >= 0");
}

/// Ground level: the median junction height (most junctions sit on the ground; a bridge's
/// junctions, if any, are the minority).
double groundLevel(const SumoNet& net) {
  std::vector<double> z;
  for (const auto& j : net.junctions) z.push_back(j.pos.z());
  if (z.empty())
    for (const auto& e : net.edges)
      for (const auto& l : e.lanes)
        for (const auto& p : l.shape) z.push_back(p.z());
  if (z.empty()) return 0.0;
  std::nth_element(z.begin(), z.begin() + static_cast<long>(z.size() / 2), z.end());
  return z[z.size() / 2];
}

struct SideStats {
  double length = 0, coverage = 0, variety = 0;
};

/// Street richness from the built scene (paper §3.1's premise: more structure in more
/// directions -> better LiDAR matching): horizontal rays every 5 m from the street's outer
/// border outward (2 m above the road, 35 m long); coverage = share that hit structure;
/// variety = spread of the hit distances (varied set-backs) — a long uniform wall has coverage
/// but no variety, an open field neither.
SideStats measureSide(const World& w, const std::vector<Point3>& border) {
  SideStats st;
  std::vector<double> d;
  std::size_t n = 0;
  for (std::size_t i = 0; i + 1 < border.size(); ++i) {
    const Vec3 seg = border[i + 1] - border[i];
    const double len = seg.head<2>().norm();
    if (len < 1e-6) continue;
    const Vec3 out(seg.y() / len, -seg.x() / len, 0.0);
    for (double s = 2.5; s < len; s += 5.0) {
      const Point3 o = border[i] + seg * (s / len) + Vec3(0, 0, 2.0);
      ++n;
      const RayHit h = w.castRay(o, out, 35.0);
      if (h.hit && h.kind != SurfaceKind::Ground && h.kind != SurfaceKind::Road &&
          h.kind != SurfaceKind::Sidewalk && h.kind != SurfaceKind::Deck)
        d.push_back(h.range_m);
    }
    st.length += len;
  }
  if (n == 0) return st;
  st.coverage = static_cast<double>(d.size()) / static_cast<double>(n);
  if (d.size() >= 2) {
    double m = 0, v = 0;
    for (double x : d) m += x;
    m /= static_cast<double>(d.size());
    for (double x : d) v += (x - m) * (x - m);
    st.variety = std::min(1.0, std::sqrt(v / static_cast<double>(d.size())) / 2.5);
  }
  return st;
}

void measureStreets(const World& w, const SumoNet& net, const WorldConfig& cfg,
                    const std::unordered_map<std::string, std::string>& edge_street,
                    const std::unordered_map<std::string, StreetKind>& kinds,
                    std::unordered_map<std::string, StreetInfo>& out) {
  std::unordered_map<std::string, bool> pair;
  for (const auto& e : net.edges) pair[e.from + "\x1f" + e.to] = true;
  struct Acc {
    double len = 0, cov = 0, var = 0;
  };
  std::unordered_map<std::string, Acc> acc;
  for (const auto& e : net.edges) {
    if (e.lanes.empty() || e.lanes.front().shape.size() < 2) continue;
    const auto& key = edge_street.at(e.id);
    std::vector<std::vector<Point3>> sides;
    const auto& f = e.lanes.front();
    sides.push_back(detail::offsetPolyline(f.shape, -(f.width_m / 2 + cfg.sidewalk_width_m)));
    if (!pair.count(e.to + "\x1f" + e.from)) {
      const auto& l = e.lanes.back();
      auto left = detail::offsetPolyline(l.shape, l.width_m / 2 + cfg.sidewalk_width_m);
      std::reverse(left.begin(), left.end());
      sides.push_back(std::move(left));
    }
    for (const auto& s : sides) {
      const SideStats st = measureSide(w, s);
      auto& a = acc[key];
      a.len += st.length;
      a.cov += st.coverage * st.length;
      a.var += st.variety * st.length;
    }
  }
  for (const auto& e : net.edges) {
    const auto& key = edge_street.at(e.id);
    StreetInfo info;
    info.kind = kinds.at(key);
    const auto it = acc.find(key);
    if (it != acc.end() && it->second.len > 0) {
      const double cov = it->second.cov / it->second.len, var = it->second.var / it->second.len;
      info.richness = std::clamp(cov * (0.4 + 0.6 * var), 0.0, 1.0);
    }
    out[e.id] = info;
  }
}

}  // namespace

World::World(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;
World::~World() = default;

World World::build(const SumoNet& net, const WorldConfig& cfg, std::uint64_t seed) {
  validate(cfg);
  detail::BuildContext ctx(net, cfg, seed);
  ctx.ground_z = groundLevel(net);
  detail::buildRoads(ctx);
  detail::buildStreetside(ctx);
  if (!cfg.poly_file.empty()) detail::buildPolyBuildings(ctx, cfg.poly_file);
  detail::buildGround(ctx);

  auto impl = std::make_unique<Impl>();
  impl->ground_z = ctx.ground_z;
  impl->stats = ctx.stats;
  impl->stats.ground_z_m = ctx.ground_z;
  impl->stats.triangles = ctx.mesh.triangles.size();
  impl->mesh = std::move(ctx.mesh);
  impl->scene = detail::EmbreeScene(impl->mesh);
  World w(std::move(impl));
  measureStreets(w, net, cfg, ctx.edge_street, ctx.street_kind, w.impl_->streets);
  if (!cfg.poly_file.empty()) {
    // with real buildings the class follows what was measured
    for (auto& [id, info] : w.impl_->streets)
      info.kind = info.richness > 0.45   ? StreetKind::Rich
                  : info.richness > 0.15 ? StreetKind::Wall
                                         : StreetKind::Open;
  }
  const auto& s = w.impl_->stats;
  logInfo("world: " + std::to_string(s.triangles) + " triangles, " + std::to_string(s.buildings) +
          " buildings, " + std::to_string(s.walls) + " wall pieces, " + std::to_string(s.poles) +
          " poles, " + std::to_string(s.trees) + " trees, " + std::to_string(s.parked_cars) +
          " parked cars, " + std::to_string(s.furniture) + " signs/bollards/shelters, " +
          std::to_string(s.fence_posts) + " fence posts, " + std::to_string(s.pillars) +
          " pillars; streets rich/wall/open " + std::to_string(s.streets_rich) + "/" +
          std::to_string(s.streets_wall) + "/" + std::to_string(s.streets_open));
  return w;
}

World World::fromMesh(TriangleMesh mesh) {
  if (mesh.kinds.size() != mesh.triangles.size())
    throw std::invalid_argument("World::fromMesh: one kind per triangle required");
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= mesh.vertices.size())
        throw std::invalid_argument("World::fromMesh: triangle index out of range");
  auto impl = std::make_unique<Impl>();
  double zmin = std::numeric_limits<double>::infinity();
  for (const auto& v : mesh.vertices) zmin = std::min<double>(zmin, v.z());
  impl->ground_z = std::isfinite(zmin) ? zmin : 0.0;
  impl->stats.triangles = mesh.triangles.size();
  impl->stats.ground_z_m = impl->ground_z;
  impl->mesh = std::move(mesh);
  impl->scene = detail::EmbreeScene(impl->mesh);
  return World(std::move(impl));
}

const TriangleMesh& World::mesh() const { return impl_->mesh; }
const WorldStats& World::stats() const { return impl_->stats; }
double World::groundZ() const { return impl_->ground_z; }

std::pair<Point3, Point3> World::bounds() const {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo;
  for (const auto& v : impl_->mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  if (impl_->mesh.vertices.empty()) return {Point3::Zero(), Point3::Zero()};
  return {lo.cast<double>(), hi.cast<double>()};
}

StreetKind World::streetKind(const std::string& e) const {
  const auto it = impl_->streets.find(e);
  if (it == impl_->streets.end())
    throw std::invalid_argument("World::streetKind: '" + e + "' is not an edge of the world's net");
  return it->second.kind;
}

double World::streetRichness(const std::string& e) const {
  const auto it = impl_->streets.find(e);
  if (it == impl_->streets.end())
    throw std::invalid_argument("World::streetRichness: '" + e +
                                "' is not an edge of the world's net");
  return it->second.richness;
}

std::optional<double> World::surfaceZ(double x, double y, double z_from, double depth_m) const {
  const RayHit h = castRay(Point3(x, y, z_from), -Vec3::UnitZ(), depth_m);
  if (!h.hit) return std::nullopt;
  return z_from - h.range_m;
}

RayHit World::castRay(const Point3& origin, const Vec3& dir_in, double max_range,
                      const std::vector<VehicleBox>& boxes) const {
  RayHit out;
  const double n = dir_in.norm();
  if (n < 1e-12 || max_range <= 0) return out;
  const Vec3 dir = dir_in / n;
  unsigned prim = 0;
  Eigen::Vector3f ng;
  const float t = impl_->scene.intersect1(origin.cast<float>(), dir.cast<float>(), 0.0f,
                                          static_cast<float>(max_range), &prim, &ng);
  if (std::isfinite(t)) {
    out.hit = true;
    out.range_m = t;
    out.normal = ng.cast<double>().normalized();
    if (out.normal.dot(dir) > 0) out.normal = -out.normal;
    out.kind = impl_->mesh.kinds[prim];
  }
  for (const auto& b : boxes) {
    double tb;
    Vec3 nb;
    if (detail::intersectBox(detail::prepareBox(b), origin, dir, out.hit ? out.range_m : max_range,
                             &tb, &nb)) {
      out.hit = true;
      out.range_m = tb;
      out.normal = nb;
      out.kind = SurfaceKind::Vehicle;
    }
  }
  return out;
}

}  // namespace slamroute::simulate
