#pragma once
// Internal: shared state of World::build's steps (WorldRoads.cpp, WorldBuildings.cpp).
#include <cstdint>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include "WorldMesh.hpp"
#include "WorldRelief.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate::detail {

struct BuildContext {
  const SumoNet& net;
  const WorldConfig& cfg;
  std::uint64_t seed;
  TriangleMesh mesh;
  MeshBuilder mb{mesh};
  WorldStats stats;
  double ground_z = 0.0;
  KeepOutGrid roads{25.0};         ///< lanes + sidewalks (+ clearance) and junction areas
  KeepOutGrid ground_roads{25.0};  ///< lanes and junctions at ground level (pillars avoid them)
  KeepOutGrid placed{25.0};        ///< buildings, walls and tree crowns placed so far
  std::unordered_map<std::string, StreetKind> street_kind;   ///< by street key
  std::unordered_map<std::string, std::string> edge_street;  ///< edge id -> street key
  Relief relief;

  BuildContext(const SumoNet& n, const WorldConfig& c, std::uint64_t s)
      : net(n), cfg(c), seed(s), relief(c, s) {}
  double elevation(const Point3& p) const { return p.z() - ground_z; }
  bool elevatedEdge(const SumoEdge& e) const;
};

/// 64-bit mix of the seed and a string (FNV-1a + splitmix64): per-street random streams that
/// do not depend on the order streets are processed in.
std::uint64_t hashSeed(std::uint64_t seed, const std::string& key);

/// Cross-section of an edge: lane centres from its right border, its width, and where the
/// crown is (the street's middle: the left border of a two-way street's edge, else its middle).
struct EdgeProfile {
  std::vector<double> lane_r;
  double width = 0, crown_r = 0;
};
EdgeProfile edgeProfile(const SumoEdge& e, bool two_way);
/// Road surface (or raised footpath) of lane k, with camber and relief; decks get their slab.
void buildLaneSurface(BuildContext& ctx, const SumoEdge& e, std::size_t k, const EdgeProfile& prof,
                      bool bridge, bool footpath);
/// Pavement beside lane k (outward -1: right of it, +1: left), its top curb_height_m above the
/// road's edge, falling 2 % towards the road; its sides reach into the ground.
void buildPavement(BuildContext& ctx, const SumoEdge& e, std::size_t k, const EdgeProfile& prof,
                   double outward);
/// Junction area (convex hull at height z), subdivided so the relief shows on it.
void buildJunctionSurface(BuildContext& ctx, const Polygon2& hull, double z);

void buildRoads(BuildContext& ctx);       ///< lanes, decks, sidewalks, parapets, junctions, pillars
void buildGround(BuildContext& ctx);      ///< ground plane under everything
void buildStreetside(BuildContext& ctx);  ///< street classes, buildings, walls, poles, trees
void buildPolyBuildings(BuildContext& ctx, const std::string& poly_file);

}  // namespace slamroute::simulate::detail
