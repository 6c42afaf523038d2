// Calibrates the EIF's motion noise (rl.eif) on measured SLAM drift, then checks it: how well the
// predicted C_k along each drive ranks the measured error along it (Spearman).
//   bench_eif_calibration RUN_DIR... (folders of `run` / `experiment`: graph/, routes/, drives/,
//   eval/; every drive with an evaluation is used; nothing is written)
//
// Fit. Over a street piece of length L driven once, a random-walk motion noise of q m^2 per metre
// gives a position error increment of variance q L. evaluate's per_edge.csv gives, per SUMO edge,
// the relative translation error over each visit (drift_pct) and the rotation error per metre:
// delta = drift_pct / 100 * L, so delta^2 / L = (drift_pct / 100)^2 L estimates q on that edge
// (likewise (rot_rad_per_m)^2 L the heading noise). The EIF scales the noise by
// 1 + gain * (1 - w) for an edge of normalised weight w, so a least-squares line of those
// estimates against (1 - w), over the pieces >= 20 m, gives q (its value at w = 1) and
// gain = slope / q. The position noise splits along:cross track as 2:1.
//
// Check. For each drive: C_k after each planned edge (rl::predictUncertainty with the given
// noise), against the position error when the vehicle leaves that edge's last SUMO edge in the
// drive; Spearman per drive, for the shipped defaults and the fitted values. The error is taken
// in the frame the estimate starts in (evaluate starts it at the ground-truth pose), not after
// the ATE's alignment: C_k predicts the error grown since the start, and an alignment fitted to
// the whole drive moves error from the end to the start.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/core/Route.hpp"
#include "slamroute/evaluate/Metrics.hpp"
#include "slamroute/pipeline/Statistics.hpp"
#include "slamroute/rl/PlanGraph.hpp"
#include "slamroute/rl/Uncertainty.hpp"

using namespace slamroute;
namespace fs = std::filesystem;

namespace {

struct DriveFiles {
  std::string name;
  fs::path route, gt, pose_edges, estimate, per_edge, graph;
};

std::vector<DriveFiles> findDrives(const fs::path& run) {
  std::vector<DriveFiles> out;
  if (!fs::exists(run / "eval")) return out;
  for (const auto& e : fs::directory_iterator(run / "eval")) {
    const std::string id = e.path().filename().string();
    DriveFiles d{run.filename().string() + "/" + id,
                 run / "routes" / (id + ".json"),
                 run / "drives" / id / "groundtruth.tum",
                 run / "drives" / id / "pose_edges.csv",
                 e.path() / "estimate.tum",
                 e.path() / "per_edge.csv",
                 run / "graph" / "graph.json"};
    if (fs::exists(d.route) && fs::exists(d.gt) && fs::exists(d.estimate) && fs::exists(d.per_edge))
      out.push_back(d);
  }
  return out;
}

/// SUMO edge -> normalised weight of the planning-graph edge that carries it.
std::map<std::string, double> sumoWeights(const RoadGraph& g, const rl::PlanGraph& pg) {
  std::map<std::string, double> w;
  for (int e = 0; e < pg.m; ++e)
    for (const auto& s :
         g.edges[static_cast<std::size_t>(pg.edge_orig[static_cast<std::size_t>(e)])].sumo_edges)
      w[s] = pg.weight[static_cast<std::size_t>(e)];
  return w;
}

struct Sample {
  double x;          ///< 1 - normalised weight
  double q_xy, q_h;  ///< per-metre variance estimates [m^2/m], [rad^2/m]
};

void addSamples(const DriveFiles& d, const std::map<std::string, double>& weight,
                std::vector<Sample>& out) {
  for (const auto& r : evaluate::readPerEdgeCsv(d.per_edge)) {
    if (!weight.count(r.edge)) continue;
    const double len = r.length_m / std::max(r.visits, 1);
    const double drift = r.drift_pct / 100.0, rot = r.rot_deg_per_m * M_PI / 180.0;
    if (len < 20.0 || !std::isfinite(drift) || !std::isfinite(rot)) continue;
    out.push_back({1.0 - weight.at(r.edge), drift * drift * len, rot * rot * len});
  }
}

/// Least-squares line y = a + b x; returns {a, b}.
std::pair<double, double> fitLine(const std::vector<Sample>& s, double Sample::*y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(s.size());
  for (const auto& p : s) {
    sx += p.x;
    sy += p.*y;
    sxx += p.x * p.x;
    sxy += p.x * p.*y;
  }
  const double den = n * sxx - sx * sx;
  const double b = std::abs(den) > 1e-12 ? (n * sxy - sx * sy) / den : 0.0;
  return {(sy - b * sx) / n, b};
}

rl::EifConfig fitNoise(const std::vector<Sample>& s) {
  rl::EifConfig c;
  auto [a, b] = fitLine(s, &Sample::q_xy);
  if (a <= 0) {  // the line crosses zero before w = 1: keep the mean as the base, no weight effect
    double m = 0;
    for (const auto& p : s) m += p.q_xy / static_cast<double>(s.size());
    a = m;
    b = 0;
  }
  c.poor_weight_gain = std::max(b / a, 0.0);
  c.long_var_per_m = a * 2.0 / 3.0;
  c.lat_var_per_m = a / 3.0;
  double h = 0;
  for (const auto& p : s)
    h += p.q_h / (1.0 + c.poor_weight_gain * p.x) / static_cast<double>(s.size());
  c.heading_var_per_m = h;
  std::printf(
      "fit over %zu street pieces >= 20 m: q = %.3g m^2/m at weight 1 (line %.3g + %.3g (1-w)),"
      " poor_weight_gain = %.2f, heading %.3g rad^2/m\n",
      s.size(), a, a, b, c.poor_weight_gain, c.heading_var_per_m);
  return c;
}

/// Position error at the end of each maximal run of the drive on one SUMO edge.
struct EdgeVisit {
  std::string edge;
  double error_m;
};

std::vector<EdgeVisit> errorAlongDrive(const DriveFiles& d) {
  evaluate::MetricsOptions opt;
  const auto m = evaluate::compareTrajectories(readTum(d.estimate), readTum(d.gt), opt);
  const auto pe = evaluate::readPoseEdges(d.pose_edges);
  std::map<long long, std::string> at;  // time [ms] -> edge
  for (const auto& p : pe) at[std::llround(p.t * 1000)] = p.edge;
  std::vector<EdgeVisit> out;
  for (std::size_t i = 0; i < m.pairs.size(); ++i) {
    const auto it = at.find(std::llround(m.pairs[i].t * 1000));
    if (it == at.end() || it->second.empty() || it->second[0] == ':') continue;
    if (out.empty() || out.back().edge != it->second) out.push_back({it->second, 0.0});
    out.back().error_m = (m.pairs[i].est.translation() - m.pairs[i].gt.translation()).norm();
  }
  return out;
}

struct Correlation {
  double rho = std::nan("");
  std::size_t steps = 0;  ///< planned edges matched to the drive
};

/// Spearman of C_k and the error when the drive leaves each planned edge.
Correlation driveCorrelation(const DriveFiles& d, const RoadGraph& g, const rl::PlanGraph& pg,
                             const std::vector<EdgeVisit>& along, const rl::EifConfig& eif) {
  const Route r = Route::readJson(d.route);
  std::vector<int> local_of(g.edges.size(), -1);
  for (int e = 0; e < pg.m; ++e)
    local_of[static_cast<std::size_t>(pg.edge_orig[static_cast<std::size_t>(e)])] = e;
  std::vector<int> edges;
  for (int e : r.edges) {
    if (e < 0 || static_cast<std::size_t>(e) >= local_of.size() ||
        local_of[static_cast<std::size_t>(e)] < 0)
      return {};  // planned on another graph
    edges.push_back(local_of[static_cast<std::size_t>(e)]);
  }
  const int start = pg.node_local[static_cast<std::size_t>(r.nodes.front())];
  const auto series = rl::predictUncertainty(pg, eif, start, edges);
  std::vector<double> c, err;
  std::size_t j = 0;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto& s = g.edges[static_cast<std::size_t>(r.edges[k])].sumo_edges;
    if (s.empty()) continue;
    std::size_t f = j;
    while (f < along.size() && along[f].edge != s.back()) ++f;
    if (f == along.size()) continue;  // not driven as planned (legalised away): skip this step
    j = f + 1;
    c.push_back(series.c_m2[k]);
    err.push_back(along[f].error_m);
  }
  return {pipeline::spearman(c, err), c.size()};
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<DriveFiles> drives;
  for (int i = 1; i < argc; ++i)
    for (auto& d : findDrives(argv[i])) drives.push_back(d);
  if (drives.empty()) {
    std::fprintf(stderr, "usage: bench_eif_calibration RUN_DIR... (no evaluated drives found)\n");
    return 2;
  }
  std::vector<Sample> samples;
  std::map<fs::path, std::pair<RoadGraph, rl::PlanGraph>> graphs;
  for (const auto& d : drives) {
    if (!graphs.count(d.graph)) {
      RoadGraph g = RoadGraph::readJson(d.graph);
      rl::PlanGraph pg = rl::PlanGraph::build(g);
      graphs.emplace(d.graph, std::make_pair(std::move(g), std::move(pg)));
    }
    const auto& [g, pg] = graphs.at(d.graph);
    addSamples(d, sumoWeights(g, pg), samples);
  }
  const rl::EifConfig fitted = fitNoise(samples), shipped;  // shipped: the config defaults
  std::printf(
      "\n| drive | planned edges matched | Spearman(C_k, error) rl.eif defaults | fitted here "
      "|\n|---|---|---|---|\n");
  std::vector<double> rho_shipped, rho_fitted;
  for (const auto& d : drives) {
    const auto& [g, pg] = graphs.at(d.graph);
    const auto along = errorAlongDrive(d);
    const Correlation a = driveCorrelation(d, g, pg, along, shipped);
    const Correlation b = driveCorrelation(d, g, pg, along, fitted);
    rho_shipped.push_back(a.rho);
    rho_fitted.push_back(b.rho);
    std::printf("| %s | %zu | %.3f | %.3f |\n", d.name.c_str(), a.steps, a.rho, b.rho);
  }
  const auto ms = pipeline::meanSd(rho_shipped), mf = pipeline::meanSd(rho_fitted);
  std::printf("| mean +- sd over %zu drives | | %.3f +- %.3f | %.3f +- %.3f |\n", drives.size(),
              ms.mean, ms.sd, mf.mean, mf.sd);
  std::printf(
      "\nrl.eif: long_var_per_m %.4g, lat_var_per_m %.4g, heading_var_per_m %.4g, "
      "poor_weight_gain %.3g\n",
      fitted.long_var_per_m, fitted.lat_var_per_m, fitted.heading_var_per_m,
      fitted.poor_weight_gain);
  return 0;
}
