#pragma once
// A sweep's results: DIR/results.csv (one row per net x variant x planner x seed with every
// metric of its route and SLAM evaluation), DIR/summary.md (mean +- sd per net x variant x
// planner, a plot per headline metric), DIR/failed_tasks.txt and DIR/tasks.csv (each task's
// fate and run time).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "slamroute/pipeline/Sweep.hpp"
#include "slamroute/pipeline/SweepSpec.hpp"

namespace slamroute::pipeline {

/// The metrics of one row: the route's (route.*) and the evaluation's (eval.*) numbers and
/// flags, nested keys joined by dots. Timings (planning time, scans per second, ms per scan) are
/// left out: they vary from run to run and machine to machine, the rest is the same for the
/// same seed.
struct RowResult {
  SweepRow row;
  std::string status;  ///< "ok", or the first task of the row that did not succeed
  std::map<std::string, double> metrics;
};

/// The result of each row read from its run folder; `outcome` gives each task's fate.
std::vector<RowResult> collectResults(const std::vector<SweepRow>& rows,
                                      const SweepOutcome& outcome,
                                      const std::filesystem::path& out);

/// Writes results.csv, summary.md (+ summary/*.png), failed_tasks.txt and tasks.csv under `out`.
void writeSweepResults(const std::vector<RowResult>& results, const SweepOutcome& outcome,
                       const std::filesystem::path& out, const std::string& command);

}  // namespace slamroute::pipeline
