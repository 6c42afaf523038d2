#pragma once
// The fleet's figures as tables, built once from the run's files and shown by both report.md
// (ReportFleet.cpp) and report.html (HtmlFleet.cpp), so the two never disagree.
#include <string>
#include <vector>

#include "Report.hpp"
#include "slamroute/core/FleetRoute.hpp"

namespace slamroute::cli {

struct FleetTable {
  std::string title;
  std::vector<std::string> head;
  std::vector<std::vector<std::string>> rows;  ///< cells already formatted ("–" when unknown)
};

/// Makespan against the lower bound and the single-vehicle route, total, balance, coverage.
FleetTable fleetMakespanTable(const ReportInputs& in, const FleetRoute& f);
/// One row per vehicle (route, drive, ATE alone / under one alignment, facades) and the merge.
FleetTable fleetVehicleTable(const ReportInputs& in, const FleetRoute& f);
/// The merged map's closures, ATE, accuracy and completeness; no rows before the evaluation.
FleetTable fleetMergedMapTable(const ReportInputs& in);

/// "Campaign time in SUMO: ..." against the single postman route; "" unless both were driven.
std::string fleetCampaignTimeText(const ReportInputs& in);

/// The Markdown of a table (head row, separator, rows) and a blank line.
std::string markdownTable(const FleetTable& t);

}  // namespace slamroute::cli
