#include "EvaluationJson.hpp"

#include <cmath>
#include <limits>

namespace slamroute::evaluate {
using nlohmann::json;

namespace {

/// A figure: null in the file stands for NaN (nlohmann writes NaN and infinities as null).
double figure(const json& j, const char* key) {
  const json& v = j.at(key);
  return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}

json loopJson(const LoopRecord& l) {
  return {{"old_keyframe", l.old_keyframe},
          {"new_keyframe", l.new_keyframe},
          {"t_old", l.t_old},
          {"t_new", l.t_new},
          {"fitness_m2", l.fitness_m2},
          {"correction_m", l.correction_m},
          {"correction_z_m", l.correction_z_m},
          {"by_place", l.by_place},
          {"t_old_new", {l.t_old_new.x(), l.t_old_new.y(), l.t_old_new.z()}},
          {"yaw_old_new_deg", l.yaw_old_new_deg}};
}

LoopRecord loopFromJson(const json& j) {
  LoopRecord l;
  l.old_keyframe = j.at("old_keyframe").get<long long>();
  l.new_keyframe = j.at("new_keyframe").get<long long>();
  l.t_old = figure(j, "t_old");
  l.t_new = figure(j, "t_new");
  l.fitness_m2 = figure(j, "fitness_m2");
  l.correction_m = figure(j, "correction_m");
  if (j.contains("correction_z_m")) l.correction_z_m = figure(j, "correction_z_m");
  l.by_place = j.at("by_place").get<bool>();
  const json& t = j.at("t_old_new");
  l.t_old_new = Vec3(t.at(0).get<double>(), t.at(1).get<double>(), t.at(2).get<double>());
  l.yaw_old_new_deg = figure(j, "yaw_old_new_deg");
  return l;
}

TrajectorySummary trajectoryFromJson(const json& j) {
  TrajectorySummary t;
  t.poses_matched = j.at("poses_matched").get<long long>();
  t.ate_rmse_m = figure(j, "ate_rmse_m");
  t.ate_mean_m = figure(j, "ate_mean_m");
  t.ate_median_m = figure(j, "ate_median_m");
  t.ate_max_m = figure(j, "ate_max_m");
  t.rpe_trans_pct = figure(j, "rpe_trans_pct");
  t.rpe_rot_deg_per_m = figure(j, "rpe_rot_deg_per_m");
  t.rpe_segments = j.at("rpe_segments").get<long long>();
  t.rpe_segment_m = figure(j, "rpe_segment_m");
  t.rpe_segment_trans_pct = figure(j, "rpe_segment_trans_pct");
  t.rpe_segment_rot_deg_per_m = figure(j, "rpe_segment_rot_deg_per_m");
  t.rpe_segment_count = j.at("rpe_segment_count").get<long long>();
  t.route_length_m = figure(j, "route_length_m");
  t.evaluated_length_m = figure(j, "evaluated_length_m");
  if (j.contains("end_drift_pct")) t.end_drift_pct = figure(j, "end_drift_pct");
  const json& a = j.at("alignment_T_gt_est");
  const json& tr = a.at("t");
  t.alignment_t = Vec3(tr.at(0).get<double>(), tr.at(1).get<double>(), tr.at(2).get<double>());
  for (std::size_t i = 0; i < 4; ++i) t.alignment_q_xyzw[i] = a.at("q_xyzw").at(i).get<double>();
  return t;
}

json stretchJson(const UnreliableStretch& s) {
  return {{"first_scan", s.first_scan},
          {"last_scan", s.last_scan},
          {"t_start", s.t_start},
          {"t_end", s.t_end},
          {"reasons", s.reasons}};
}

Reliability reliabilityFromJson(const json& j) {
  Reliability r;
  r.unreliable_scans = j.at("unreliable_scans").get<long long>();
  r.unreliable_share = figure(j, "unreliable_share");
  r.by_reason = j.at("by_reason").get<std::map<std::string, long long>>();
  for (const json& s : j.at("stretches"))
    r.stretches.push_back({s.at("first_scan").get<long long>(), s.at("last_scan").get<long long>(),
                           figure(s, "t_start"), figure(s, "t_end"),
                           s.at("reasons").get<std::map<std::string, long long>>()});
  return r;
}

json timingJson(const TimingMsPerScan& t) {
  return {{"projection", t.projection}, {"ground", t.ground},
          {"clustering", t.clustering}, {"features", t.features},
          {"odometry", t.odometry},     {"mapping", t.mapping},
          {"local_map", t.local_map},   {"loop_closure", t.loop_closure},
          {"pose_graph", t.pose_graph}, {"total", t.total}};
}

TimingMsPerScan timingFromJson(const json& j) {
  return {figure(j, "projection"), figure(j, "ground"),       figure(j, "clustering"),
          figure(j, "features"),   figure(j, "odometry"),     figure(j, "mapping"),
          figure(j, "local_map"),  figure(j, "loop_closure"), figure(j, "pose_graph"),
          figure(j, "total")};
}

void addCoverageJson(const EdgeCoverage& c, json& j) {
  j["edges_visited"] = c.edges_visited;
  j["coverage_edge_pct"] = c.coverage_edge_pct ? json(*c.coverage_edge_pct) : json(nullptr);
  if (c.edges_total) j["edges_total"] = *c.edges_total;
  if (!c.note.empty()) j["coverage_note"] = c.note;
  if (c.directed) sumoCoverageToJson(*c.directed, j);
}

EdgeCoverage coverageFromJson(const json& j) {
  EdgeCoverage c;
  c.edges_visited = j.at("edges_visited").get<long long>();
  if (j.contains("edges_total")) c.edges_total = j["edges_total"].get<long long>();
  if (!j.at("coverage_edge_pct").is_null()) c.coverage_edge_pct = figure(j, "coverage_edge_pct");
  c.note = j.value("coverage_note", std::string());
  c.directed = sumoCoverageFromJson(j);
  return c;
}

/// The map figures under `prefix` ("map_" or "map_aligned_").
void addMapJson(const MapFigures& m, const std::string& prefix, json& j) {
  j[prefix + "mean_dist_m"] = m.mean_m;
  j[prefix + "median_dist_m"] = m.median_m;
  j[prefix + "p95_dist_m"] = m.p95_m;
  j[prefix + "far_share"] = m.far_share;
}

MapFigures mapFromJson(const json& j, const std::string& prefix) {
  return {figure(j, (prefix + "mean_dist_m").c_str()),
          figure(j, (prefix + "median_dist_m").c_str()), figure(j, (prefix + "p95_dist_m").c_str()),
          figure(j, (prefix + "far_share").c_str())};
}

void addMapAccuracyJson(const EvaluationResult& r, json& j) {
  j["map_points"] = r.map_points;
  j["map_mean_dist_m"] = nullptr;
  j["map_p95_dist_m"] = nullptr;
  if (!r.map || !r.map_aligned) return;
  addMapJson(*r.map, "map_", j);
  j["map_accuracy_max_m"] = r.map_accuracy_max_m;  // distances are clamped here
  addMapJson(*r.map_aligned, "map_aligned_", j);
}

json completenessJson(const MapCompletenessFigures& m) {
  return {{"street_radius_m", m.street_radius_m},
          {"cells", m.cells},
          {"unknown_share", m.unknown_share},
          {"frontier_share", m.frontier_share},
          {"mean_frontier_probability", m.mean_frontier_probability}};
}

MapCompletenessFigures completenessFromJson(const json& j) {
  return {figure(j, "street_radius_m"), j.at("cells").get<long long>(), figure(j, "unknown_share"),
          figure(j, "frontier_share"), figure(j, "mean_frontier_probability")};
}

void addSlamJson(const EvaluationResult& r, json& j) {
  j["scans"] = r.scans;
  j["scan_stride"] = r.scan_stride;
  j["keyframes"] = r.keyframes;
  j["loop_closures"] = r.loops.size();
  j["loop_closures_by_place"] = r.loopClosuresByPlace();
  j["loop_candidates"] = r.loop_candidates;
  j["loops_rejected_correction"] = r.loops_rejected_correction;
  j["loops_rejected_ambiguous"] = r.loops_rejected_ambiguous;
  json loops = json::array();
  for (const auto& l : r.loops) loops.push_back(loopJson(l));
  j["loops"] = loops;
}

void addMotionPriorJson(const EvaluationResult& r, json& j) {
  j["initial_pose"] = r.trajectory ? "ground-truth pose of the first scan and motion to the "
                                     "second (estimate is in the world frame)"
                                   : "identity (no ground truth)";
  j["gyro_standstill_s"] = r.gyro_standstill_s;
  j["gyro_bias_deg_s"] = r.gyro_bias_deg_s;
  j["motion_prior"] =
      r.wheel_odometry ? "wheel odometry + gyro (odometry.csv)" : "constant velocity";
  if (r.odometry_prior_sigma_deg) j["odometry_prior_sigma_deg"] = *r.odometry_prior_sigma_deg;
  if (r.wheel_scale) j["wheel_scale"] = *r.wheel_scale;
  if (r.imu_pitch_bias_deg) j["imu_pitch_bias_deg"] = *r.imu_pitch_bias_deg;
}

}  // namespace

json toJson(const TrajectorySummary& t) {
  json j;
  j["poses_matched"] = t.poses_matched;
  j["ate_rmse_m"] = t.ate_rmse_m;
  j["ate_mean_m"] = t.ate_mean_m;
  j["ate_median_m"] = t.ate_median_m;
  j["ate_max_m"] = t.ate_max_m;
  j["rpe_trans_pct"] = t.rpe_trans_pct;
  j["rpe_rot_deg_per_m"] = t.rpe_rot_deg_per_m;
  j["rpe_segments"] = t.rpe_segments;
  j["rpe_segment_m"] = t.rpe_segment_m;
  j["rpe_segment_trans_pct"] = t.rpe_segment_trans_pct;
  j["rpe_segment_rot_deg_per_m"] = t.rpe_segment_rot_deg_per_m;
  j["rpe_segment_count"] = t.rpe_segment_count;
  j["route_length_m"] = t.route_length_m;
  j["evaluated_length_m"] = t.evaluated_length_m;
  if (t.end_drift_pct) j["end_drift_pct"] = *t.end_drift_pct;
  const Vec3& a = t.alignment_t;
  const auto& q = t.alignment_q_xyzw;
  j["alignment_T_gt_est"] = {{"t", {a.x(), a.y(), a.z()}}, {"q_xyzw", {q[0], q[1], q[2], q[3]}}};
  return j;
}

json toJson(const Reliability& r) {
  json stretches = json::array();
  for (const auto& s : r.stretches) stretches.push_back(stretchJson(s));
  return {{"unreliable_scans", r.unreliable_scans},
          {"unreliable_share", r.unreliable_share},
          {"by_reason", r.by_reason},
          {"stretches", stretches},
          {"reliable", r.reliable()}};
}

json toJson(const EvaluationResult& r) {
  json j = r.trajectory ? toJson(*r.trajectory) : json::object();
  if (!r.trajectory) j["trajectory_metrics"] = "skipped: no ground truth";
  addMotionPriorJson(r, j);
  addSlamJson(r, j);
  if (r.drift_by_label) {
    json d = json::object();
    for (const auto& [label, ld] : *r.drift_by_label)
      d[label] = {{"driven_m", ld.driven_m},
                  {"drift_pct", ld.drift_pct},
                  {"window_drift_pct", ld.window_drift_pct}};
    j["drift_by_label"] = d;
  }
  addCoverageJson(r.coverage, j);
  addMapAccuracyJson(r, j);
  if (r.map_completeness) j["map_completeness"] = completenessJson(*r.map_completeness);
  j["timing_ms_per_scan"] = timingJson(r.timing_ms_per_scan);
  j["scans_per_s"] = r.scans_per_s;
  j["reliability"] = toJson(r.reliability);
  return j;
}

EvaluationResult evaluationFromJson(const json& j) {
  EvaluationResult r;
  if (j.contains("ate_rmse_m")) r.trajectory = trajectoryFromJson(j);
  r.gyro_standstill_s = figure(j, "gyro_standstill_s");
  r.gyro_bias_deg_s = figure(j, "gyro_bias_deg_s");
  r.wheel_odometry = j.at("motion_prior").get<std::string>() != "constant velocity";
  if (j.contains("odometry_prior_sigma_deg"))
    r.odometry_prior_sigma_deg = figure(j, "odometry_prior_sigma_deg");
  if (j.contains("wheel_scale")) r.wheel_scale = figure(j, "wheel_scale");
  if (j.contains("imu_pitch_bias_deg")) r.imu_pitch_bias_deg = figure(j, "imu_pitch_bias_deg");
  r.scans = j.at("scans").get<long long>();
  r.scan_stride = j.at("scan_stride").get<long long>();
  r.keyframes = j.at("keyframes").get<long long>();
  r.loop_candidates = j.at("loop_candidates").get<long long>();
  r.loops_rejected_correction = j.at("loops_rejected_correction").get<long long>();
  r.loops_rejected_ambiguous = j.at("loops_rejected_ambiguous").get<long long>();
  for (const json& l : j.at("loops")) r.loops.push_back(loopFromJson(l));
  if (j.contains("drift_by_label")) {
    r.drift_by_label.emplace();
    for (const auto& [label, d] : j["drift_by_label"].items())
      (*r.drift_by_label)[label] = {figure(d, "driven_m"), figure(d, "drift_pct"),
                                    d.contains("window_drift_pct")
                                        ? figure(d, "window_drift_pct")
                                        : std::numeric_limits<double>::quiet_NaN()};
  }
  r.coverage = coverageFromJson(j);
  r.map_points = j.at("map_points").get<long long>();
  if (j.contains("map_median_dist_m")) {
    r.map = mapFromJson(j, "map_");
    r.map_aligned = mapFromJson(j, "map_aligned_");
    r.map_accuracy_max_m = figure(j, "map_accuracy_max_m");
  }
  if (j.contains("map_completeness"))
    r.map_completeness = completenessFromJson(j["map_completeness"]);
  r.timing_ms_per_scan = timingFromJson(j.at("timing_ms_per_scan"));
  r.scans_per_s = figure(j, "scans_per_s");
  r.reliability = reliabilityFromJson(j.at("reliability"));
  return r;
}

}  // namespace slamroute::evaluate
