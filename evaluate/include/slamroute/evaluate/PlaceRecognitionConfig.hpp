#pragma once
// Settings of the place descriptor and its database (PlaceDescriptor.hpp, PlaceDatabase.hpp).
// YAML: evaluate.loop.place.
#include <string>

namespace slamroute::evaluate {

struct PlaceRecognitionConfig {
  int rings = 20;                ///< radial bins out to max_radius_m
  int sectors = 60;              ///< azimuth bins over the full turn (6 deg each)
  double max_radius_m = 80.0;    ///< points farther out (horizontally) are left out [m]
  double ring_spread = 1.0;      ///< Gaussian width of the spread over rings [rings], 0 = none
  double max_distance = 0.3;     ///< a candidate matches below this descriptor distance (0..1)
  int ring_key_candidates = 10;  ///< nearest ring keys that get the full rotation search
  void validate() const;  ///< values that cannot work: std::invalid_argument (PlaceDescriptor.cpp)
};
template <class V>
void visitFields(V& v, PlaceRecognitionConfig& c) {
  v.field("rings", c.rings, "radial bins of the place descriptor");
  v.field("sectors", c.sectors, "azimuth bins of the place descriptor (yaw resolution)");
  v.field("max_radius_m", c.max_radius_m, "descriptor radius [m]");
  v.field("ring_spread", c.ring_spread,
          "cells take neighbouring rings' heights, Gaussian of this width [rings]; 0 = none");
  v.field("max_distance", c.max_distance, "candidate accepted below this distance (0..1)");
  v.field("ring_key_candidates", c.ring_key_candidates,
          "nearest ring keys compared under every rotation");
}

}  // namespace slamroute::evaluate
