#pragma once
// report.md of a pipeline run: reads the files the steps wrote (graph.json, routes, metrics.json,
// per_edge.csv) and writes the Markdown report with its pictures.
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/pipeline/Statistics.hpp"

namespace slamroute::cli {

struct ReportInputs {
  std::string net;            ///< the SUMO net the run used
  std::filesystem::path out;  ///< run folder (report.md goes here)
  std::filesystem::path survey_dir, graph_json;
  std::vector<std::string> planners;  ///< planner names, in table order
  /// The fleet's id (routes/<id>.json, drives/<id>/vehicle_K, eval/<id>/); empty: no fleet.
  std::string fleet;
  /// routes/<p>.json, drives/<p>/, eval/<p>/ under `out`.
  std::string command;  ///< the command line that made the run
  double total_seconds = 0.0;
  std::vector<std::pair<std::string, double>>
      step_seconds;  ///< NaN: kept from an earlier run (--resume)
};

using pipeline::spearman;

/// Writes out/report.md and out/report/*.png. Throws std::runtime_error naming a missing input.
void writeReport(const ReportInputs& in);

}  // namespace slamroute::cli
