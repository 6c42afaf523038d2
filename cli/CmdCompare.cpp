// `slamroute compare EST GT [--json] [--segment M]`: ATE / RPE between any two trajectories
// (TUM or KITTI poses, detected by content), associated by timestamp.
#include <cmath>
#include <iomanip>
#include <iostream>

#include "Commands.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/evaluate/Evaluate.hpp"

namespace slamroute::cli {

void registerCompare(CLI::App& app, Context& ctx) {
  struct Opts {
    std::string est, gt;
    bool json = false;
    double segment_m = -1.0;
    double max_dt_s = -1.0;
  };
  auto o = std::make_shared<Opts>();
  auto* sub = app.add_subcommand(
      "compare", "Trajectory metrics (ATE/RPE) between an estimate and ground truth");
  sub->add_option("est", o->est, "estimated trajectory (TUM or KITTI poses)")->required();
  sub->add_option("gt", o->gt, "ground-truth trajectory (TUM or KITTI poses)")->required();
  sub->add_flag("--json", o->json, "print JSON instead of text");
  sub->add_option("--segment", o->segment_m, "extra RPE segment length [m] (default: config)");
  sub->add_option("--max-dt", o->max_dt_s, "timestamp association tolerance [s] (default: config)");
  sub->callback([&ctx, o] {
    ctx.load();
    evaluate::MetricsOptions mo = evaluate::metricsOptions(ctx.cfg.evaluate);
    if (o->segment_m >= 0) {
      if (o->segment_m == 0) throw std::invalid_argument("compare: --segment must be positive");
      mo.segment_m = o->segment_m;
    }
    if (o->max_dt_s >= 0) mo.max_dt_s = o->max_dt_s;
    const Trajectory est = readTrajectory(o->est);
    const Trajectory gt = readTrajectory(o->gt);
    if (est.empty()) throw std::invalid_argument(o->est + ": no poses");
    if (gt.empty()) throw std::invalid_argument(o->gt + ": no poses");
    const evaluate::TrajectoryMetrics m = evaluate::compareTrajectories(est, gt, mo);
    if (o->json) {
      nlohmann::json j = evaluate::trajectoryJson(m);
      j["estimate"] = o->est;
      j["groundtruth"] = o->gt;
      std::cout << j.dump(2) << "\n";
      return;
    }
    auto num = [](double v, int p) {
      std::ostringstream os;
      if (std::isnan(v)) return std::string("n/a (trajectory too short)");
      os << std::fixed << std::setprecision(p) << v;
      return os.str();
    };
    std::cout << "poses matched:   " << m.pairs.size() << " of " << est.size() << "\n"
              << "route length:    " << num(m.route_length_m, 1) << " m\n"
              << "ATE (SE3-aligned): rmse " << num(m.ate.rmse_m, 4) << " m, mean "
              << num(m.ate.mean_m, 4) << " m, median " << num(m.ate.median_m, 4) << " m, max "
              << num(m.ate.max_m, 4) << " m\n"
              << "RPE KITTI 100..800 m: " << num(m.rpe_kitti.trans_pct, 3) << " %, "
              << num(m.rpe_kitti.rot_deg_per_m, 5) << " deg/m (" << m.rpe_kitti.segments
              << " segments)\n"
              << "RPE " << num(m.segment_m, 0) << " m: " << num(m.rpe_segment.trans_pct, 3)
              << " %, " << num(m.rpe_segment.rot_deg_per_m, 5) << " deg/m ("
              << m.rpe_segment.segments << " segments)\n";
  });
}

}  // namespace slamroute::cli
