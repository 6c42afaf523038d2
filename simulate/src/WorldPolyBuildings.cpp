// World build step: buildings from a SUMO polygon file (polyconvert output:
// <poly id=".." type="building" shape="x,y x,y ..."> with optional <param
// key="height"/"building:levels">).
#include <pugixml.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "WorldBuild.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::simulate::detail {

namespace {
Polygon2 parseShape(const std::string& shape) {
  Polygon2 out;
  std::istringstream ss(shape);
  std::string tok;
  while (ss >> tok) {
    const auto comma = tok.find(',');
    if (comma == std::string::npos) continue;
    out.emplace_back(std::stod(tok.substr(0, comma)), std::stod(tok.substr(comma + 1)));
  }
  if (out.size() > 3 && (out.front() - out.back()).norm() < 1e-6) out.pop_back();
  return out;
}
}  // namespace

void buildPolyBuildings(BuildContext& ctx, const std::string& poly_file) {
  pugi::xml_document doc;
  const auto res = doc.load_file(poly_file.c_str());
  if (!res)
    throw std::invalid_argument("world.poly_file '" + poly_file + "': " + res.description());
  const auto root = doc.child("additional");
  if (!root)
    throw std::invalid_argument("world.poly_file '" + poly_file + "': no <additional> root");
  std::size_t dropped = 0;
  for (const auto& poly : root.children("poly")) {
    const std::string type = poly.attribute("type").as_string();
    if (type.find("building") == std::string::npos) continue;
    Polygon2 fp;
    try {
      fp = parseShape(poly.attribute("shape").as_string());
    } catch (const std::exception&) {
      throw std::invalid_argument("world.poly_file '" + poly_file + "': bad shape in poly '" +
                                  poly.attribute("id").as_string() + "'");
    }
    if (fp.size() < 3 || std::abs(signedArea(fp)) < 1.0) continue;
    if (signedArea(fp) < 0) std::reverse(fp.begin(), fp.end());
    if (ctx.roads.overlaps(convexHull(fp))) {
      ++dropped;
      continue;
    }
    double height = 0;
    for (const auto& p : poly.children("param")) {
      const std::string k = p.attribute("key").as_string();
      if (k == "height") height = p.attribute("value").as_double();
      if (k == "building:levels" && height <= 0) height = 3.0 * p.attribute("value").as_double();
    }
    if (height <= 0) {
      std::mt19937_64 rng(
          hashSeed(ctx.seed, std::string("poly:") + poly.attribute("id").as_string()));
      height = ctx.cfg.height_min_m + (ctx.cfg.height_max_m - ctx.cfg.height_min_m) *
                                          (static_cast<double>(rng() >> 11) / 9007199254740992.0);
    }
    ctx.placed.add(convexHull(fp));
    ctx.mb.prism(fp, ctx.ground_z - kFoundation_m, ctx.ground_z + height, SurfaceKind::Building);
    ++ctx.stats.buildings;
  }
  if (dropped)
    logInfo("world: dropped " + std::to_string(dropped) + " polygon buildings overlapping roads");
}

}  // namespace slamroute::simulate::detail
