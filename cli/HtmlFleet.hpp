#pragma once
// The fleet's part of report.html (`run --vehicles K`): each vehicle's route in its own colour
// (the colours of report.md's fleet map), each vehicle's merged trajectory for the slider
// (HtmlFleetDrives.hpp), the merged map from above, and the fleet's tables (the same as
// report.md's: ReportFleetTables.hpp).
#include <nlohmann/json.hpp>

#include "HtmlLayers.hpp"
#include "Report.hpp"

namespace slamroute::cli {

/// Adds data["fleet"] and the fleet's tables to data["tables"] when routes/<fleet>.json exists.
void addFleetData(nlohmann::json& data, const ReportInputs& in, const SumoNet& net,
                  const MapFrame& frame);

}  // namespace slamroute::cli
