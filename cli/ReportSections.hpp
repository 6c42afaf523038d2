#pragma once
// The sections of report.md. Each writer appends one part of the Markdown (and the pictures it
// shows) from the run's files, loaded once into ReportData; writeReport lists them in order, so a
// new section is one writer and one entry in that list.
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "Report.hpp"
#include "slamroute/core/RoadGraph.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::cli {

/// A SUMO edge's drift pooled over every planner's drive: length-weighted sums of per_edge.csv's
/// end-to-end drift_pct and its window_drift_pct (along the street; NaN from older files).
struct EdgeDrift {
  double length_m = 0;    ///< driven [m]
  double drift_sum = 0;   ///< sum of drift_pct [%] x length [m]
  double window_sum = 0;  ///< sum of window_drift_pct [%] x length [m]
  /// Drift along the street [%]; end to end where the files predate that figure.
  double alongPct() const {
    return std::isfinite(window_sum) ? window_sum / length_m : drift_sum / length_m;
  }
  EdgeDrift& operator+=(const EdgeDrift& o) {
    length_m += o.length_m;
    drift_sum += o.drift_sum;
    window_sum += o.window_sum;
    return *this;
  }
};
using PooledDrift = std::map<std::string, EdgeDrift>;

/// What the sections read: the inputs and the run's files every section shares.
struct ReportData {
  explicit ReportData(const ReportInputs& inputs);

  const ReportInputs& in;
  std::filesystem::path pictures;  ///< out/report: the PNGs report.md shows
  RoadGraph graph;
  nlohmann::json graph_meta;  ///< graph.json's metadata
  nlohmann::json survey;      ///< survey.json ({} without one)
  /// The simulated city of the first drive with a world.yaml (same net, world config and seed
  /// for every drive of the run); none before any drive.
  std::optional<simulate::World> world;
  PooledDrift drift;  ///< per_edge.csv of every planner, pieces >= 20 m
};

using SectionWriter = void (*)(std::ostringstream& md, const ReportData& data);

void writeHeaderSection(std::ostringstream& md, const ReportData& data);
void writeRoadGraphSection(std::ostringstream& md, const ReportData& data);
void writeResultsSection(std::ostringstream& md, const ReportData& data);
void writeUncertaintySection(std::ostringstream& md, const ReportData& data);
/// aco-ga against postman (cli/ReportCoverage.cpp); nothing unless both were planned.
void writeCoverageVsPostmanSection(std::ostringstream& md, const ReportData& data);
void writePlannerPicturesSection(std::ostringstream& md, const ReportData& data);
void writeWeightVsDriftSection(std::ostringstream& md, const ReportData& data);
void writeDriftByStreetKindSection(std::ostringstream& md, const ReportData& data);
void writeMapCompletenessSection(std::ostringstream& md,
                                 const ReportData& data);  // ReportCompleteness.cpp
void writeStepTimesSection(std::ostringstream& md, const ReportData& data);

/// `v` with `prec` decimals; "–" when not finite.
std::string reportNumber(double v, int prec = 2);
/// j[key] x scale with `prec` decimals; "–" when absent or not a number.
std::string reportNumber(const nlohmann::json& j, const std::string& key, int prec = 2,
                         double scale = 1.0);

/// Reads out/eval/<planner>/per_edge.csv of each planner (missing files add nothing).
PooledDrift pooledDrift(const std::filesystem::path& out, const std::vector<std::string>& planners);

}  // namespace slamroute::cli
