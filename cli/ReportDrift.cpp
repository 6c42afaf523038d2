// The report's test of the paper's premise: does the depth-image edge weight predict the LiDAR
// drift measured on the edge, and which kinds of simulated street drift least.
#include <cmath>

#include "ReportSections.hpp"
#include "slamroute/evaluate/Metrics.hpp"
#include "slamroute/pipeline/Plot.hpp"
#include "slamroute/pipeline/Statistics.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

PooledDrift pooledDrift(const fs::path& out, const std::vector<std::string>& planners) {
  PooledDrift acc;
  for (const auto& p : planners) {
    const fs::path csv = out / "eval" / p / "per_edge.csv";
    if (!fs::exists(csv)) continue;
    for (const auto& r : evaluate::readPerEdgeCsv(csv))
      if (std::isfinite(r.drift_pct) && r.length_m >= 20.0)  // short pieces: drift is noise
        acc[r.edge] += {r.length_m, r.drift_pct * r.length_m, r.window_drift_pct * r.length_m};
  }
  return acc;
}

void writeWeightVsDriftSection(std::ostringstream& md, const ReportData& data) {
  md << "## Does the edge weight predict LiDAR drift?\n\n";
  std::vector<double> w, d;
  for (const auto& e : data.graph.edges)
    for (const auto& se : e.sumo_edges) {
      auto it = data.drift.find(se);
      if (it == data.drift.end() || it->second.length_m <= 0) continue;
      w.push_back(e.weight);
      d.push_back(it->second.alongPct());
    }
  const double rho = pipeline::spearman(w, d);
  md << "Spearman rank correlation between an edge's depth-image weight and the measured "
        "translational drift along it (pooled over all drives, pieces >= 20 m; end to end from "
        "evaluations older than that figure): **rho = "
     << reportNumber(rho, 3) << "** over n = " << w.size()
     << " SUMO edges. The paper's premise predicts rho < 0 (a higher weight, i.e. more varied "
        "surface normals, should mean less drift).\n\n";
  if (w.empty()) return;
  pipeline::scatterPng(data.pictures / "weight_vs_drift.png", w, d, "edge weight", "drift [%]");
  md << "![weight vs drift](report/weight_vs_drift.png)\n\n";
}

/// Length-weighted mean drift per kind of street the simulated world lined the edge with: the
/// ground truth behind the depth-image weight (rich streets should drift least).
void writeDriftByStreetKindSection(std::ostringstream& md, const ReportData& data) {
  if (!data.world) return;
  PooledDrift by_kind;  // street kind -> its edges' sums
  for (const auto& [edge, e] : data.drift) {
    std::string kind;
    try {
      kind = simulate::streetKindName(data.world->streetKind(edge));
    } catch (const std::exception&) {
      continue;  // not a street of this world
    }
    by_kind[kind] += e;
  }
  md << "Drift by the kind of street the simulated city lines it with (all drives pooled, "
        "length-weighted; along the street: over windows of half a visit from each pose of its "
        "first half, averaged; end to end: from a visit's first pose to its last, which the "
        "heading in the turn onto the street can decide):\n\n"
        "| street kind | driven [km] | drift along the street [%] | drift end to end [%] |\n"
        "|---|---|---|---|\n";
  for (const auto& [kind, k] : by_kind)
    md << "| " << kind << " | " << reportNumber(k.length_m / 1000.0, 2) << " | "
       << reportNumber(k.window_sum / k.length_m, 2) << " | "
       << reportNumber(k.drift_sum / k.length_m, 2) << " |\n";
  md << "\n";
}

}  // namespace slamroute::cli
