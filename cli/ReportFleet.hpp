#pragma once
// The fleet's part of report.md (`run --vehicles K`): its routes with one colour per vehicle, a
// table per vehicle, the makespan against the single vehicle's route, the merged map's figures
// and its top view. Writers of their own (ReportSections.hpp), so other sections stay apart.
#include <array>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "ReportSections.hpp"
#include "slamroute/core/RoadGraph.hpp"

namespace slamroute::cli {

/// Vehicle `k`'s colour in the fleet pictures (B, G, R), distinct for the first ten vehicles.
std::array<unsigned char, 3> vehicleColour(std::size_t k);

/// The graph in grey and each vehicle's edges (indices into graph.edges) in its colour, shifted
/// a few pixels apart so that a street two vehicles drive shows both; a legend names them.
void renderFleetRoutesPng(const std::filesystem::path& path, const RoadGraph& graph,
                          const std::vector<std::vector<int>>& vehicle_edges, int width_px = 1200);

/// "## Fleet": the plan (route map, makespan against the bound and the single route).
void writeFleetPlanSection(std::ostringstream& md, const ReportData& data);
/// Per vehicle: length, time, ATE alone / under one alignment before and after the merge,
/// completeness; then the merged map's figures and top view.
void writeFleetResultsSection(std::ostringstream& md, const ReportData& data);

}  // namespace slamroute::cli
