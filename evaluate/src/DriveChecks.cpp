// checkDriveFiles: every time-stamped file of a drive against the ground truth's time span.
#include "slamroute/evaluate/DriveChecks.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/core/Odometry.hpp"
#include "slamroute/core/Trajectory.hpp"
#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {
namespace fs = std::filesystem;
namespace {

std::string seconds(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f s", t);
  return buf;
}

/// The first i whose time does not increase on times[i-1], or times.size().
std::size_t firstDisorder(const std::vector<double>& times) {
  for (std::size_t i = 1; i < times.size(); ++i)
    if (!(times[i] > times[i - 1])) return i;
  return times.size();
}

/// The span a file must cover: the ground truth's, less a slack of two sample periods (files
/// sampled at other rates start and end up to a period apart).
struct Span {
  double t0 = 0, t1 = 0, slack_s = 0;
};

/// readTum has checked that the ground truth's times increase.
Span groundTruthSpan(const std::vector<double>& times) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < times.size(); ++i) steps.push_back(times[i] - times[i - 1]);
  double median = 0.1;
  if (!steps.empty()) {
    std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2),
                     steps.end());
    median = steps[steps.size() / 2];
  }
  return {times.front(), times.back(), 2.0 * median + 1e-3};
}

/// `times` (rows of `path`) increase and cover `span`; `what` names the rows in the message.
void checkCovers(const fs::path& path, const std::vector<double>& times, const Span& span,
                 const std::string& what) {
  if (times.empty()) throw std::invalid_argument(path.string() + ": no " + what);
  if (const std::size_t i = firstDisorder(times); i < times.size())
    throw std::invalid_argument(path.string() + ": " + what + " " + std::to_string(i + 1) + " at " +
                                seconds(times[i]) + " is not later than the one before");
  if (times.front() > span.t0 + span.slack_s || times.back() < span.t1 - span.slack_s)
    throw std::invalid_argument(path.string() + ": " + what + " span " + seconds(times.front()) +
                                " to " + seconds(times.back()) + " but the ground truth spans " +
                                seconds(span.t0) + " to " + seconds(span.t1) +
                                " (file cut short?)");
}

/// scans/: times.txt lists one time per NNNNNN.bin, no more and no fewer.
void checkScanFiles(const fs::path& dir, std::size_t listed) {
  std::size_t bins = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".bin") ++bins;
  if (bins != listed)
    throw std::invalid_argument((dir / "times.txt").string() + ": lists " + std::to_string(listed) +
                                " scans but the folder holds " + std::to_string(bins) +
                                " .bin files");
}

void checkPoseEdges(const fs::path& path, const Span& span, std::size_t gt_poses) {
  const std::vector<PoseEdge> rows = readPoseEdges(path);
  std::vector<double> times;
  for (const auto& r : rows) times.push_back(r.t);
  checkCovers(path, times, span, "row");
  if (rows.size() != gt_poses)
    throw std::invalid_argument(path.string() + ": " + std::to_string(rows.size()) + " rows for " +
                                std::to_string(gt_poses) +
                                " ground-truth poses (one row per pose)");
}

}  // namespace

void checkDriveFiles(const fs::path& drive, const ScanSource& scans) {
  const fs::path gt_path = drive / drive_files::kGroundTruth;
  std::vector<double> gt_times;
  for (const auto& p : readTum(gt_path)) gt_times.push_back(p.t);
  const Span span = groundTruthSpan(gt_times);

  std::vector<double> scan_times;
  for (std::size_t i = 0; i < scans.size(); ++i) scan_times.push_back(scans.time(i));
  const fs::path scan_dir = drive / drive_files::kScanDir;
  const bool saved_scans = fs::is_directory(scan_dir);
  checkCovers(saved_scans ? scan_dir / "times.txt" : gt_path, scan_times, span, "scan");
  if (saved_scans) checkScanFiles(scan_dir, scan_times.size());

  if (const fs::path odo = drive / drive_files::kOdometry; fs::exists(odo)) {
    std::vector<double> odo_times;
    const WheelOdometry odometry = readOdometryCsv(odo);
    for (const auto& s : odometry.samples()) odo_times.push_back(s.t);
    checkCovers(odo, odo_times, span, "sample");
  }
  if (const fs::path pe = drive / drive_files::kPoseEdges; fs::exists(pe))
    checkPoseEdges(pe, span, gt_times.size());
}

}  // namespace slamroute::evaluate
