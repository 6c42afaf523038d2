// PROJ-based conversion between a SUMO net's x/y and WGS84 longitude / latitude.
#include "slamroute/export/GeoProjection.hpp"

#include <proj.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace slamroute::exports {

struct GeoProjection::Handles {
  PJ_CONTEXT* ctx = nullptr;
  PJ* pj = nullptr;
  ~Handles() {
    if (pj) proj_destroy(pj);
    if (ctx) proj_context_destroy(ctx);
  }
};

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

double parseDegrees(const std::string& part, double limit, const std::string& what,
                    const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(part, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != part.size() || !std::isfinite(v) || std::abs(v) > limit)
    throw std::invalid_argument(what + ": '" + text +
                                "' is not LAT,LON in degrees (e.g. 52.5200,13.4050)");
  return v;
}

/// A PROJ string as a CRS definition: PROJ 6+ reads "+proj=..." as a CRS only with +type=crs.
std::string asCrs(const std::string& def) {
  if (def.rfind('+', 0) == 0 && def.find("+type=crs") == std::string::npos)
    return def + " +type=crs";
  return def;
}

/// Projected CRS `source_def` -> WGS84 lon/lat in degrees, longitude first.
std::unique_ptr<GeoProjection::Handles> makeTransform(const std::string& source_def,
                                                      const std::string& where) {
  auto h = std::make_unique<GeoProjection::Handles>();
  h->ctx = proj_context_create();
  proj_log_level(h->ctx, PJ_LOG_NONE);
  PJ* raw = proj_create_crs_to_crs(h->ctx, asCrs(source_def).c_str(),
                                   "+proj=longlat +datum=WGS84 +no_defs +type=crs", nullptr);
  if (raw) {
    h->pj = proj_normalize_for_visualization(h->ctx, raw);
    proj_destroy(raw);
  }
  if (!h->pj)
    throw std::invalid_argument(where + ": PROJ cannot use the projection '" + source_def + "' (" +
                                proj_context_errno_string(h->ctx, proj_context_errno(h->ctx)) +
                                ")");
  return h;
}

std::string localTransverseMercator(const GeoOrigin& o) {
  char buf[200];
  std::snprintf(buf, sizeof(buf),
                "+proj=tmerc +lat_0=%.9f +lon_0=%.9f +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m",
                o.lat_deg, o.lon_deg);
  return buf;
}

}  // namespace

GeoOrigin parseGeoOrigin(const std::string& text, const std::string& what) {
  const auto comma = text.find(',');
  if (comma == std::string::npos)
    throw std::invalid_argument(what + ": '" + text +
                                "' is not LAT,LON in degrees (e.g. 52.5200,13.4050)");
  GeoOrigin o;
  o.lat_deg = parseDegrees(trim(text.substr(0, comma)), 90.0, what, text);
  o.lon_deg = parseDegrees(trim(text.substr(comma + 1)), 180.0, what, text);
  return o;
}

bool hasGeoReference(const SumoNet& net) {
  const std::string p = trim(net.location.proj_parameter);
  return !p.empty() && p != "!";
}

Point2 boundaryCentre(const std::string& boundary) {
  double v[4];
  if (std::sscanf(boundary.c_str(), "%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3]) != 4)
    return Point2::Zero();
  return {0.5 * (v[0] + v[2]), 0.5 * (v[1] + v[3])};
}

std::optional<GeoProjection> GeoProjection::forNet(const SumoNet& net,
                                                   const std::optional<GeoOrigin>& origin) {
  const std::string where = net.source.string();
  if (hasGeoReference(net)) {
    const std::string def = trim(net.location.proj_parameter);
    return GeoProjection(makeTransform(def, where), net.location.net_offset, def);
  }
  if (!origin) return std::nullopt;
  const std::string def = localTransverseMercator(*origin);
  return GeoProjection(makeTransform(def, where), boundaryCentre(net.location.conv_boundary), def);
}

GeoProjection::GeoProjection(std::unique_ptr<Handles> h, Point2 offset, std::string definition)
    : h_(std::move(h)), offset_(std::move(offset)), definition_(std::move(definition)) {}
GeoProjection::GeoProjection(GeoProjection&&) noexcept = default;
GeoProjection& GeoProjection::operator=(GeoProjection&&) noexcept = default;
GeoProjection::~GeoProjection() = default;

LonLat GeoProjection::toLonLat(const Point2& net_xy) const {
  const Point2 p = net_xy - offset_;
  const PJ_COORD out = proj_trans(h_->pj, PJ_FWD, proj_coord(p.x(), p.y(), 0.0, 0.0));
  if (!std::isfinite(out.lp.lam) || !std::isfinite(out.lp.phi))
    throw std::runtime_error("PROJ could not convert net point (" + std::to_string(net_xy.x()) +
                             ", " + std::to_string(net_xy.y()) + ") to longitude / latitude");
  return {out.lp.lam, out.lp.phi};
}

Point2 GeoProjection::toNet(const LonLat& ll) const {
  const PJ_COORD out = proj_trans(h_->pj, PJ_INV, proj_coord(ll.lon_deg, ll.lat_deg, 0.0, 0.0));
  return Point2(out.xy.x, out.xy.y) + offset_;
}

}  // namespace slamroute::exports
