// The report's map-completeness section: per planner, how much of the streets' surroundings the
// evaluated map has seen (metrics.json "map_completeness", EvaluateCompleteness.hpp) and the
// GP frontier-probability picture.
#include <filesystem>

#include "EvaluateCompleteness.hpp"
#include "ReportSections.hpp"
#include "slamroute/pipeline/JsonFile.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

void writeMapCompletenessSection(std::ostringstream& md, const ReportData& data) {
  std::ostringstream rows, pictures;
  double radius_m = 0.0;
  for (const auto& p : data.in.planners) {
    const fs::path ev = data.in.out / "eval" / p;
    const json m =
        pipeline::readJsonIfPresent(ev / "metrics.json").value("map_completeness", json());
    if (!m.is_object()) continue;
    radius_m = m.value("street_radius_m", 0.0);
    rows << "| " << p << " | " << reportNumber(m, "unknown_share", 1, 100.0) << " | "
         << reportNumber(m, "frontier_share", 2, 100.0) << " | "
         << reportNumber(m, "mean_frontier_probability", 4) << " |\n";
    if (fs::exists(ev / kFrontierPng))
      pictures << "![" << p << " frontier probability](eval/" << p << "/" << kFrontierPng
               << ")\n\n";
  }
  if (rows.str().empty()) return;
  md << "## Map completeness (GP occupancy)\n\n"
     << "The scans at the SLAM estimate in an occupancy grid (" << reportNumber(radius_m, 0)
     << " m around the streets): the share never seen, the share of frontier cells (seen ground "
        "next to unseen), and the mean GP frontier probability. Pictures: white ground, blue "
        "obstacle, grey unseen, red where the frontier probability is high.\n\n"
     << "| planner | unknown [%] | frontier [%] | mean frontier probability |\n|---|---|---|---|\n"
     << rows.str() << "\n"
     << pictures.str();
}

}  // namespace slamroute::cli
