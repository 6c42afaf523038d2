// The files of a fleet evaluation (JSON only here, at the file boundary).
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/evaluate/Fleet.hpp"
#include "slamroute/evaluate/Output.hpp"

namespace slamroute::evaluate {
namespace fs = std::filesystem;
namespace {

nlohmann::json vehicleJson(const FleetVehicleResult& v, const std::string& folder) {
  return {{"id", v.id},
          {"folder", folder},
          {"keyframes", v.keyframes},
          {"own_ate_rmse_m", v.own_ate_rmse_m},
          {"common_ate_before_m", v.common_ate_before_m},
          {"common_ate_after_m", v.common_ate_after_m},
          {"completeness_pct", v.completeness_pct}};
}

std::string closuresCsv(const FleetResult& r) {
  std::ostringstream os;
  os << "vehicle_a,keyframe_a,t_a,vehicle_b,keyframe_b,t_b,x,y,z,yaw_deg,qx,qy,qz,qw,fitness_m2,"
        "horizontal_conditioning\n";
  for (const auto& c : r.closures) {
    const Vec3 t = c.T_a_b.translation();
    const double yaw = std::atan2(c.T_a_b.linear()(1, 0), c.T_a_b.linear()(0, 0)) * 180.0 / M_PI;
    const Eigen::Quaterniond q(c.T_a_b.rotation());
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "%d,%d,%.3f,%d,%d,%.3f,%.4f,%.4f,%.4f,%.3f,%.9f,%.9f,%.9f,%.9f,%.5f,%.4f\n",
                  c.vehicle_a, c.keyframe_a, c.t_a, c.vehicle_b, c.keyframe_b, c.t_b, t.x(), t.y(),
                  t.z(), yaw, q.x(), q.y(), q.z(), q.w(), c.fitness_m2, c.horizontal_conditioning);
    os << buf;
  }
  return os.str();
}

/// The aligned merged map from above, coloured like a single drive's map_error_top.png.
void writeMergedMapImage(const fs::path& png, const FleetResult& r) {
  const Cloud aligned = transformed(r.map, r.T_gt_est);
  Eigen::AlignedBox3f bounds;
  for (const auto& p : aligned) bounds.extend(p);
  MapErrorImage image(bounds, 1000);
  image.add(aligned, r.map_aligned_dist_m.data());
  char title[200];
  std::snprintf(title, sizeof title,
                "Merged map from above, one alignment for all vehicles: distance to the world "
                "surface (median %.2f m)",
                r.map_aligned_accuracy.median_m);
  image.write(png, title, mapErrorImageTop(r.map_aligned_accuracy.p95_m, r.map_accuracy_max_m));
}

}  // namespace

void writeFleetOutputs(const fs::path& out, const FleetResult& r,
                       const std::vector<std::string>& folders) {
  fs::create_directories(out);
  nlohmann::json vs = nlohmann::json::array();
  for (std::size_t v = 0; v < r.vehicles.size(); ++v) {
    vs.push_back(vehicleJson(r.vehicles[v], folders[v]));
    writeTum(out / ("merged_" + folders[v] + ".tum"), r.vehicles[v].merged);
  }
  const nlohmann::json j = {{"vehicles", vs},
                            {"closures", r.closures.size()},
                            {"closure_candidates", r.candidates},
                            {"closures_inconsistent", r.inconsistent},
                            {"common_ate_before_m", r.common_ate_before_m},
                            {"common_ate_after_m", r.common_ate_after_m},
                            {"completeness_pct", r.completeness_pct},
                            {"facade_samples", r.facade_samples},
                            {"map_mean_dist_m", r.map_accuracy.mean_m},
                            {"map_median_dist_m", r.map_accuracy.median_m},
                            {"map_p95_dist_m", r.map_accuracy.p95_m},
                            {"map_far_share", r.map_accuracy.clamped_share},
                            {"map_aligned_mean_dist_m", r.map_aligned_accuracy.mean_m},
                            {"map_aligned_median_dist_m", r.map_aligned_accuracy.median_m},
                            {"map_aligned_p95_dist_m", r.map_aligned_accuracy.p95_m},
                            {"map_aligned_far_share", r.map_aligned_accuracy.clamped_share},
                            {"map_accuracy_max_m", r.map_accuracy_max_m},
                            {"map_points", r.map_points}};
  writeFileAtomic(out / "fleet_closures.csv", closuresCsv(r));
  if (!r.map.empty()) writePcd(out / "merged_map.pcd", r.map);
  if (!r.map_aligned_dist_m.empty()) writeMergedMapImage(out / "merged_map_error_top.png", r);
  writeFileAtomic(out / "fleet_metrics.json", j.dump(2) + "\n");
}

}  // namespace slamroute::evaluate
