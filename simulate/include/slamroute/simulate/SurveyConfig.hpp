#pragma once
// Parameters of the survey drives (`slamroute survey`): SUMO vehicles on routes that together
// cover the drivable net, recording location traces and depth frames (paper §3.1 input; the
// paper collects them with CARLA vehicles).
namespace slamroute::simulate {

struct SurveyConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  double route_length_m = 2000.0;  ///< covering route length per survey vehicle (greedy cover) [m]
  double depart_interval_s = 2.0;  ///< survey vehicle i departs at i * this [s]
  double traffic_per_km = 2.0;     ///< background vehicles (random trips) per km of drivable road
  bool record_traffic = true;      ///< background vehicles' traces go into traces.csv too
  double trace_hz = 10.0;          ///< trace rate [Hz]
  double step_length_s = 0.1;      ///< SUMO simulation step [s]
  double noise_sigma_m = 0.5;      ///< GPS-like position noise, 1 sigma per axis; 0 = exact [m]
  double noise_tau_s = 2.0;        ///< noise correlation time (Gauss-Markov); 0 = white [s]
  double depth_spacing_m = 50.0;   ///< depth frame every this far per survey vehicle; 0 = none [m]
  double camera_height_m = 1.8;    ///< depth camera above the road [m]
  double time_to_teleport_s = 120.0;  ///< SUMO teleports vehicles stuck this long [s]
  double max_time_s = 3600.0;         ///< stop the survey at this simulation time [s]
};

template <class V>
void visitFields(V& v, SurveyConfig& c) {
  v.field("route_length_m", c.route_length_m, "covering route length per survey vehicle [m]");
  v.field("depart_interval_s", c.depart_interval_s, "departure interval of survey vehicles [s]");
  v.field("traffic_per_km", c.traffic_per_km, "background vehicles per km of drivable road");
  v.field("record_traffic", c.record_traffic, "record background vehicles' traces too");
  v.field("trace_hz", c.trace_hz, "trace rate [Hz]");
  v.field("step_length_s", c.step_length_s, "SUMO simulation step [s]");
  v.field("noise_sigma_m", c.noise_sigma_m, "GPS-like noise sigma per axis, 0 = exact [m]");
  v.field("noise_tau_s", c.noise_tau_s, "noise correlation time, 0 = white [s]");
  v.field("depth_spacing_m", c.depth_spacing_m,
          "depth frame spacing per survey vehicle, 0 = none [m]");
  v.field("camera_height_m", c.camera_height_m, "depth camera height above the road [m]");
  v.field("time_to_teleport_s", c.time_to_teleport_s, "SUMO teleport time [s]");
  v.field("max_time_s", c.max_time_s, "stop the survey at this simulation time [s]");
}

}  // namespace slamroute::simulate
