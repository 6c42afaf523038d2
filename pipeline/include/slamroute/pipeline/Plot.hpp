#pragma once
// Small PNG plots for the reports (run's report.md, sweep's summary.md).
#include <filesystem>
#include <string>
#include <vector>

namespace slamroute::pipeline {

/// A scatter plot of (x, y), y from 0, 640 x 480, written atomically to `path`. With `xticks`,
/// x holds category positions 0..n-1 and the categories' names are written under the axis.
/// Writes nothing for an empty sample.
void scatterPng(const std::filesystem::path& path, const std::vector<double>& x,
                const std::vector<double>& y, const std::string& xlabel, const std::string& ylabel,
                const std::vector<std::string>& xticks = {});

}  // namespace slamroute::pipeline
