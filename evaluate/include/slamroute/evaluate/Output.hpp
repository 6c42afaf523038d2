#pragma once
// Output files of an evaluation: the map as binary PCD and the PNG plots.
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/evaluate/CloudStore.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {

/// PCD v0.7, binary, fields x y z (float32); readable by PCL's pcl::io::loadPCDFile. Atomic.
void writePcd(const std::filesystem::path& path, const Cloud& cloud);

/// writePcd for a cloud that comes part by part (the SLAM map, tile by tile): the parts wait in
/// an unnamed file beside `path` (the header needs the point count) and commit() writes the
/// file atomically; without commit() nothing is left. Throws std::runtime_error naming the folder
/// or the file on a write error.
class PcdWriter {
 public:
  explicit PcdWriter(std::filesystem::path path);
  void add(const Cloud& part);
  void commit();
  std::size_t points() const { return points_; }

 private:
  std::filesystem::path path_;
  CloudStore parts_;
  std::size_t points_ = 0;
};
/// A square top view: world x/y to pixel (column, row; row 0 at the top), one scale on both
/// axes, the box [lo, hi] centred with `margin_px` around its longer side.
struct TopViewFrame {
  TopViewFrame() = default;
  TopViewFrame(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int size_px, int margin_px);
  Eigen::Vector2d pixel(double x, double y) const;
  double scale = 0;  ///< px per m (0: no box)
  int size = 0;      ///< [px]
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
};

/// Top view of the SLAM map coloured by its points' distances to the world surface (the map
/// accuracy), the mean per pixel: where the map is off and by how much. Fed part by part, like
/// the map (MapTiles.hpp); holds one sum and one count per pixel.
class MapErrorImage {
 public:
  /// `bounds`: a box holding the map (its xy fills the image).
  MapErrorImage(const Eigen::AlignedBox3f& bounds, int size_px);
  /// Points and their distances [m], one per point.
  void add(const Cloud& part, const float* dist_m);
  /// Mean distance of the points that fall on the pixel of world point (x, y); NaN where none.
  double meanAt(double x, double y) const;
  /// PNG with a colour bar from 0 to `top_m` (red: `top_m` and more) and a scale bar; `title`
  /// goes on top.
  void write(const std::filesystem::path& path, const std::string& title, double top_m) const;

 private:
  bool pixel(double x, double y, int& col, int& row) const;
  std::size_t at(int row, int col) const;  ///< index of a pixel in sum_ / count_
  int size_ = 0, margin_ = 0;
  TopViewFrame frame_;
  std::vector<float> sum_;
  std::vector<std::uint32_t> count_;
};

/// The top of a map-error image's colour scale for an aligned map with this p95 distance and
/// the accuracy's clamp [m].
double mapErrorImageTop(double aligned_p95_m, double max_m);

/// Top view: ground truth (green) and aligned estimate (red), same scale on both axes.
void plotTopView(const std::filesystem::path& path, const TrajectoryMetrics& m, int size_px);
/// Line plot of y against x (x ascending, both axes from 0) with labelled ticks and a grid;
/// y_max > 0 fixes the top of the y axis, else 1.1 x the largest y. Written atomically.
void plotCurve(const std::filesystem::path& path, const std::vector<double>& x,
               const std::vector<double>& y, const std::string& title, int size_px,
               double y_max = 0.0);
/// ATE (after alignment) against distance travelled along the ground truth.
void plotErrorAlongDistance(const std::filesystem::path& path, const TrajectoryMetrics& m,
                            int size_px);

}  // namespace slamroute::evaluate
