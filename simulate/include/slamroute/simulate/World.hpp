#pragma once
// The 3D city the sensors see, built from a SUMO net (the paper uses CARLA's towns; we build our
// own): road surfaces from the lane shapes with their z (an overpass is a real deck with a
// thickness, parapets and pillars, and the street below passes underneath), junction areas,
// curbs/sidewalks, buildings (from a .poly.xml or placed procedurally and deterministically from
// the seed), poles and trees, and a ground plane under everything.
//
// Streets are deliberately unequal for LiDAR matching (paper §3.1 scores edges by how widely the
// surface normals spread): each street is, deterministically from the seed, one of
//   Rich: varied buildings (set-back, frontage, depth, height, gaps), poles and trees;
//   Wall: long uniform walls at a constant set-back (degenerate along the street);
//   Open: open fields, only sparse poles.
// Ray casting uses Embree (hidden behind World; Embree never appears in a public header).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/simulate/Traffic.hpp"
#include "slamroute/simulate/WorldConfig.hpp"

namespace slamroute::simulate {

enum class SurfaceKind : std::uint8_t {
  Ground = 0,
  Road,
  Sidewalk,
  Deck,
  Pillar,
  Parapet,
  Building,
  Wall,
  Pole,
  Tree,
  Vehicle,
  Furniture,  ///< signs, bollards, bus shelters
  ParkedCar,  ///< parked cars beside the pavements (part of the static world)
  Fence,      ///< post-and-rail fences along open streets
  Last = Fence
};
const char* surfaceKindName(SurfaceKind k);

enum class StreetKind : std::uint8_t { Open = 0, Wall, Rich };
const char* streetKindName(StreetKind k);

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;   ///< net frame [m]
  std::vector<Eigen::Vector3i> triangles;  ///< indices into vertices, counter-clockwise = outside
  std::vector<SurfaceKind> kinds;          ///< one per triangle
};

struct RayHit {
  bool hit = false;
  double range_m = 0.0;         ///< distance along the (unit) direction [m]
  Vec3 normal = Vec3::UnitZ();  ///< unit geometric normal facing the ray origin
  SurfaceKind kind = SurfaceKind::Ground;
};

struct WorldStats {
  std::size_t triangles = 0, buildings = 0, walls = 0, poles = 0, trees = 0, pillars = 0;
  std::size_t parked_cars = 0, furniture = 0, fence_posts = 0;
  std::size_t streets_rich = 0, streets_wall = 0, streets_open = 0;
  double ground_z_m = 0.0;
};

class World {
 public:
  /// Builds the city. Same (net, cfg, seed) -> bitwise the same mesh. Throws
  /// std::invalid_argument on a bad config or an unreadable poly_file.
  static World build(const SumoNet& net, const WorldConfig& cfg, std::uint64_t seed);
  /// A world from a plain mesh (tests, analytic scenes). No streets.
  static World fromMesh(TriangleMesh mesh);

  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  ~World();

  const TriangleMesh& mesh() const;
  const WorldStats& stats() const;
  double groundZ() const;  ///< height of the ground plane [m]
  /// Axis-aligned bounds of the mesh: min and max corners [m].
  std::pair<Point3, Point3> bounds() const;

  /// Street class of a SUMO edge (both directions of a street share it). Throws
  /// std::invalid_argument naming the edge when it is not a (non-internal) edge of the net.
  StreetKind streetKind(const std::string& sumo_edge) const;
  /// LiDAR-matching richness of a street in [0, 1], measured in the built scene: horizontal
  /// rays every 5 m from the street's outer border outward (2 m up, 35 m long); coverage = share
  /// hitting structure (buildings, walls, trees, poles), variety = spread of the hit distances
  /// (std / 2.5 m, capped at 1); richness = coverage * (0.4 + 0.6 * variety). Open fields score
  /// ~0, long uniform walls ~0.3–0.4, varied buildings ~0.5–0.9. Throws like streetKind.
  double streetRichness(const std::string& sumo_edge) const;

  /// Nearest hit of one ray (static world plus the given vehicle boxes), or hit = false within
  /// max_range_m. `dir` need not be unit.
  RayHit castRay(const Point3& origin, const Vec3& dir, double max_range_m,
                 const std::vector<VehicleBox>& boxes = {}) const;

  /// Height of the first surface of the static world straight below (x, y, z_from) within
  /// `depth_m` (the road under a wheel: start above the road and under any deck overhead), or
  /// nullopt when there is none [m].
  std::optional<double> surfaceZ(double x, double y, double z_from, double depth_m = 3.0) const;

  /// Binary little-endian PLY (float x,y,z; uchar-count int vertex_indices), written atomically.
  void writePly(const std::filesystem::path& path) const;
  /// Wavefront OBJ (one group per surface kind), written atomically.
  void writeObj(const std::filesystem::path& path) const;
  /// Top-down 8-bit colour PNG: hill-shaded, coloured by height (blue low .. red high) with
  /// roads grey; `metres_per_pixel` > 0. Written atomically.
  void renderTopDownPng(const std::filesystem::path& path, double metres_per_pixel = 0.5) const;

  struct Impl;
  const Impl& impl() const { return *impl_; }  ///< for the sensors (src/ only)

 private:
  explicit World(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace slamroute::simulate
