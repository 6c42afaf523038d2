#pragma once
// Keyframe place descriptors with a k-d tree over their ring keys: a query finds the keyframes
// whose ring keys are nearest (nanoflann, grown as keyframes come), compares those under every
// rotation (placeDistance) and returns the ones closer than the configured distance.
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/PlaceDescriptor.hpp"

namespace slamroute::evaluate {

struct PlaceCandidate {
  int keyframe = -1;
  double distance = 1.0;  ///< placeDistance of the query to this keyframe's descriptor
  double yaw_rad = 0.0;   ///< yaw of the query's body frame in the keyframe's (PlaceMatch)
};

struct PlaceQuery {
  /// Only keyframes up to this index are candidates (the caller leaves out the recent ones, e.g.
  /// those of the last 30 s, which look like the query because they are next to it).
  int newest_keyframe = std::numeric_limits<int>::max();
  /// Optional gate: only keyframes stored within gate_radius_m of this position (e.g. the
  /// odometry's estimate of the query keyframe, in the frame the positions were added in).
  std::optional<Vec3> gate_centre;
  double gate_radius_m = 0.0;
};

class PlaceDatabase {
 public:
  /// Validates `cfg` (PlaceRecognitionConfig::validate).
  explicit PlaceDatabase(PlaceRecognitionConfig cfg);
  ~PlaceDatabase();
  PlaceDatabase(const PlaceDatabase&) = delete;
  PlaceDatabase& operator=(const PlaceDatabase&) = delete;

  /// Stores a keyframe's descriptor (made with this database's config) and position.
  void add(int keyframe, PlaceDescriptor descriptor, const Vec3& position);
  std::size_t size() const;
  /// Candidates for `descriptor` with a distance below cfg.max_distance, best first (ties: the
  /// older keyframe first). At most cfg.ring_key_candidates are compared.
  std::vector<PlaceCandidate> query(const PlaceDescriptor& descriptor,
                                    const PlaceQuery& q = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace slamroute::evaluate
