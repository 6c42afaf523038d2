#pragma once
// Net coordinates <-> WGS84 longitude / latitude with PROJ. A SUMO net keeps the projection it
// was built with in <location projParameter=... netOffset=...>: net x/y = projected x/y +
// netOffset. Synthetic nets have none (projParameter "!"); they can be placed on the globe with
// a local transverse Mercator around a chosen origin (--geo-origin LAT,LON).
#include <memory>
#include <optional>
#include <string>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Types.hpp"

namespace slamroute::exports {

struct LonLat {
  double lon_deg = 0.0, lat_deg = 0.0;
};

/// Where the centre of a net without geo-reference is put on the globe.
struct GeoOrigin {
  double lat_deg = 0.0, lon_deg = 0.0;
};

/// Parses "LAT,LON" in degrees (latitude in [-90, 90], longitude in [-180, 180]). Throws
/// std::invalid_argument naming `what` (e.g. "--geo-origin") and the value.
GeoOrigin parseGeoOrigin(const std::string& text, const std::string& what);

/// True when the net's <location> carries a projection (projParameter neither empty nor "!").
bool hasGeoReference(const SumoNet& net);

class GeoProjection {
 public:
  /// The net's own projection when it has one (`origin` is then not used); otherwise, with
  /// `origin`, a transverse Mercator (scale 1, WGS84 ellipsoid) whose centre, the origin, is the
  /// centre of the net's convBoundary. nullopt without either. Throws std::invalid_argument
  /// naming the net when PROJ rejects its projParameter.
  static std::optional<GeoProjection> forNet(const SumoNet& net,
                                             const std::optional<GeoOrigin>& origin);

  struct Handles;  ///< PROJ context and transformation (opaque; one thread at a time)

  GeoProjection(GeoProjection&&) noexcept;
  GeoProjection& operator=(GeoProjection&&) noexcept;
  ~GeoProjection();

  LonLat toLonLat(const Point2& net_xy) const;
  Point2 toNet(const LonLat& ll) const;
  /// The projection used, as PROJ reads it ("+proj=utm +zone=33 ...").
  const std::string& definition() const { return definition_; }

 private:
  GeoProjection(std::unique_ptr<Handles> h, Point2 offset, std::string definition);
  std::unique_ptr<Handles> h_;
  Point2 offset_;  ///< net x/y minus offset_ = projected x/y [m]
  std::string definition_;
};

/// The centre of a "xmin,ymin,xmax,ymax" boundary; (0, 0) when it does not parse.
Point2 boundaryCentre(const std::string& boundary);

}  // namespace slamroute::exports
