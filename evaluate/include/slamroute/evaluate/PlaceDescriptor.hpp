#pragma once
// Place recognition for loop-closure candidates: a ring/sector height descriptor of a keyframe's
// cloud in its own body frame (the Scan Context of Kim & Kim, IROS 2018). Rings are radial bins,
// sectors azimuth bins; each cell holds the highest point above the road. A yaw of the vehicle
// only shifts the sectors, so two descriptors are compared under every column shift and the best
// shift gives the yaw between the two scans. The ring key (the mean height per ring) does not
// change with yaw at all and picks the candidates that get the full comparison (PlaceDatabase).
// Unlike the plain Scan Context each cell also takes its neighbouring rings' heights, discounted
// by a Gaussian (ring_spread): a wall a few metres away otherwise changes ring with a 1 m shift
// of the vehicle and the column no longer meets itself (1 - cos = 1).
#include <string>
#include <vector>

#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/PlaceRecognitionConfig.hpp"

namespace slamroute::evaluate {

/// rings x sectors heights above the road in a scan's body frame (after the ring spread); 0 where
/// a cell and its neighbouring rings are empty.
struct PlaceDescriptor {
  int rings = 0, sectors = 0;
  std::vector<float> height_m;  ///< [ring * sectors + sector]: highest point in the cell [m]
  std::vector<float> ring_key;  ///< per ring: mean height over its sectors [m] (yaw-invariant)
  float at(int ring, int sector) const {
    return height_m[static_cast<std::size_t>(ring * sectors + sector)];
  }
};

/// Descriptor of `body` (points in the sensor frame, z up). `sensor_height_m`: the sensor above
/// the road, so that heights count from the road (a cell with only road in it stays ~0). Sector
/// k covers azimuths [-pi + k * 2pi / sectors, -pi + (k + 1) * 2pi / sectors).
PlaceDescriptor makePlaceDescriptor(const Cloud& body, double sensor_height_m,
                                    const PlaceRecognitionConfig& cfg);

struct PlaceMatch {
  double distance = 1.0;  ///< 0: the same heights; 1: no column in common
  int shift = 0;          ///< query sector k matches candidate sector k + shift
  double yaw_rad = 0.0;   ///< yaw of the query's body frame in the candidate's, in (-pi, pi]
};

/// Mean cosine distance (1 - cos) of the column pairs where both descriptors have something,
/// minimised over all column shifts. Throws std::invalid_argument on descriptors of different
/// sizes.
PlaceMatch placeDistance(const PlaceDescriptor& query, const PlaceDescriptor& candidate);

}  // namespace slamroute::evaluate
