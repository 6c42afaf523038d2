// Map completeness from a drive's scans: unknown / frontier share near the streets, GP picture.
#include "slamroute/explore/MapCompleteness.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "ExploreRun.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/explore/GpFrontier.hpp"

namespace slamroute::explore {

namespace {

/// The scan taken at time t (scan times ascend), if one is within 1 ms of it.
std::optional<std::size_t> scanAt(const ScanSource& scans, double t, std::size_t from) {
  while (from < scans.size() && scans.time(from) < t - 1e-3) ++from;
  if (from < scans.size() && std::abs(scans.time(from) - t) <= 1e-3) return from;
  return std::nullopt;
}

}  // namespace

OccupancyGrid occupancyFromScans(const ScanSource& scans, const Trajectory& poses,
                                 const RoadGraph& g, const GridConfig& cfg, double spacing_m) {
  const auto [lo, hi] = streetBounds(g, cfg.margin_m);
  OccupancyGrid grid(lo, hi, cfg.cell_m);
  const double mount = scans.spec().mount_height_m;
  std::optional<Vec3> last;
  std::size_t next_scan = 0, used = 0;
  for (const StampedPose& p : poses) {
    const Pose3& T = p.T_world_body;
    if (last && (T.translation() - *last).norm() < spacing_m) continue;
    const std::optional<std::size_t> i = scanAt(scans, p.t, next_scan);
    if (!i) continue;
    next_scan = *i;
    last = T.translation();
    ++used;
    std::vector<Point3> pts;
    for (const ScanPoint& q : scans.scan(*i).points) pts.push_back(T * Point3(q.x, q.y, q.z));
    grid.addScan(pts, T.translation(), T.translation().z() - mount, cfg.max_range_m,
                 cfg.ground_tol_m, cfg.ground_grade);
  }
  if (used == 0)
    throw std::invalid_argument("map completeness: none of the " + std::to_string(poses.size()) +
                                " poses has a scan at its time");
  return grid;
}

std::vector<bool> streetMask(const OccupancyGrid& grid, const RoadGraph& g,
                             double street_radius_m) {
  std::vector<bool> mask(grid.size(), false);
  const int reach = static_cast<int>(std::ceil(street_radius_m / grid.cellSize()));
  auto disc = [&](const Point3& p) {
    const auto c = grid.cellOf(p.x(), p.y());
    if (!c) return;
    for (int dr = -reach; dr <= reach; ++dr)
      for (int dc = -reach; dc <= reach; ++dc) {
        const int col = grid.col(*c) + dc, row = grid.row(*c) + dr;
        if (!grid.inside(col, row)) continue;
        const int idx = row * grid.width() + col;
        if ((grid.centre(idx) - p.head<2>()).norm() <= street_radius_m)
          mask[static_cast<std::size_t>(idx)] = true;
      }
  };
  for (const RoadEdge& e : g.edges)
    for (std::size_t i = 0; i + 1 < e.polyline.size(); ++i) {
      const Point3 a = e.polyline[i], b = e.polyline[i + 1];
      const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / grid.cellSize())));
      for (int k = 0; k <= n; ++k) disc(a + (b - a) * (static_cast<double>(k) / n));
    }
  return mask;
}

MapCompleteness mapCompleteness(const OccupancyGrid& grid, const std::vector<bool>& mask,
                                const GpConfig& gp) {
  const GpFrontierMap map(grid, gp);
  MapCompleteness m;
  std::size_t unknown = 0, frontier = 0;
  double p_sum = 0.0;
  for (int i = 0; i < static_cast<int>(grid.size()); ++i) {
    if (!mask[static_cast<std::size_t>(i)]) continue;
    ++m.cells;
    unknown += grid.at(i) == Cell::Unknown;
    frontier += grid.isFrontier(i);
    p_sum += map.frontierProbability(i);
  }
  if (m.cells == 0) return m;
  const double n = static_cast<double>(m.cells);
  m.unknown_share = static_cast<double>(unknown) / n;
  m.frontier_share = static_cast<double>(frontier) / n;
  m.mean_frontier_probability = p_sum / n;
  return m;
}

void writeFrontierProbabilityPng(const std::filesystem::path& path, const OccupancyGrid& grid,
                                 const std::vector<bool>& mask, const GpConfig& gp) {
  const GpFrontierMap map(grid, gp);
  cv::Mat img(grid.height(), grid.width(), CV_8UC3, cv::Scalar(0, 0, 0));
  for (int i = 0; i < static_cast<int>(grid.size()); ++i) {
    if (!mask[static_cast<std::size_t>(i)]) continue;
    const Cell c = grid.at(i);
    cv::Vec3b px = c == Cell::Unknown  ? cv::Vec3b(110, 110, 110)
                   : c == Cell::Ground ? cv::Vec3b(255, 255, 255)
                                       : cv::Vec3b(200, 90, 40);
    const double p = std::clamp(map.frontierProbability(i) * 10.0, 0.0, 1.0);  // 0.1 = full red
    if (p > 0)
      px = cv::Vec3b(static_cast<uchar>(px[0] * (1 - p)), static_cast<uchar>(px[1] * (1 - p)),
                     static_cast<uchar>(px[2] * (1 - p) + 255 * p));
    img.at<cv::Vec3b>(grid.height() - 1 - grid.row(i), grid.col(i)) = px;
  }
  std::vector<uchar> buf;
  if (!cv::imencode(".png", img, buf))
    throw std::runtime_error(path.string() + ": PNG encoding failed");
  writeFileAtomic(path, std::string(buf.begin(), buf.end()));
}

}  // namespace slamroute::explore
