// The fleet's route map: one colour per vehicle.
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <stdexcept>

#include "ReportFleet.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::cli {
namespace {

/// World x/y to pixels: the graph's box, one scale, y up.
struct Frame {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300, scale = 1.0;
  int margin = 30, legend = 0, rows = 0;
  void grow(const Point3& p) {
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  }
  cv::Point2d px(const Point3& p) const {
    return {margin + (p.x() - xmin) * scale, rows - margin - (p.y() - ymin) * scale};
  }
};

Frame graphFrame(const RoadGraph& g, int width_px, int legend_rows) {
  Frame f;
  for (const auto& n : g.nodes) f.grow(n.pos);
  for (const auto& e : g.edges)
    for (const auto& p : e.polyline) f.grow(p);
  if (g.nodes.empty()) f.xmin = f.ymin = 0, f.xmax = f.ymax = 1;
  f.scale = (width_px - 2 * f.margin) / std::max({f.xmax - f.xmin, f.ymax - f.ymin, 1.0});
  f.legend = 22 * legend_rows + 10;
  f.rows = static_cast<int>((f.ymax - f.ymin) * f.scale) + 2 * f.margin + f.legend;
  return f;
}

std::vector<Point3> edgeLine(const RoadGraph& g, const RoadEdge& e) {
  if (e.polyline.size() >= 2) return e.polyline;
  return {g.nodes[static_cast<std::size_t>(e.u)].pos, g.nodes[static_cast<std::size_t>(e.v)].pos};
}

/// The edge's pixels moved `shift_px` to the right of its travel direction.
std::vector<cv::Point> shifted(const std::vector<Point3>& line, const Frame& f, double shift_px) {
  std::vector<cv::Point> out;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const cv::Point2d a = f.px(line[i > 0 ? i - 1 : 0]), b = f.px(line[i > 0 ? i : 1]);
    cv::Point2d d = b - a;
    const double n = std::max(1e-9, std::hypot(d.x, d.y));
    const cv::Point2d right(-d.y / n, d.x / n);  // image rows grow downwards
    const cv::Point2d p = f.px(line[i]) + right * shift_px;
    out.emplace_back(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
  }
  return out;
}

cv::Scalar scalar(std::size_t k) {
  const auto c = vehicleColour(k);
  return {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
}

void drawLegend(cv::Mat& img, std::size_t vehicles) {
  for (std::size_t k = 0; k < vehicles; ++k) {
    const int y = 10 + 22 * static_cast<int>(k);
    cv::rectangle(img, {10, y}, {34, y + 14}, scalar(k), cv::FILLED);
    cv::putText(img, "vehicle " + std::to_string(k), {42, y + 13}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
}

}  // namespace

std::array<unsigned char, 3> vehicleColour(std::size_t k) {
  // Ten colours told apart easily (matplotlib's tab10), as B, G, R.
  static const std::array<std::array<unsigned char, 3>, 10> palette = {{{180, 119, 31},
                                                                        {14, 127, 255},
                                                                        {44, 160, 44},
                                                                        {40, 39, 214},
                                                                        {189, 103, 148},
                                                                        {75, 86, 140},
                                                                        {194, 119, 227},
                                                                        {34, 189, 188},
                                                                        {207, 190, 23},
                                                                        {127, 127, 127}}};
  return palette[k % palette.size()];
}

void renderFleetRoutesPng(const std::filesystem::path& path, const RoadGraph& graph,
                          const std::vector<std::vector<int>>& vehicle_edges, int width_px) {
  const Frame f = graphFrame(graph, width_px, static_cast<int>(vehicle_edges.size()));
  cv::Mat img(std::max(f.rows, 200), width_px, CV_8UC3, cv::Scalar(255, 255, 255));
  for (const auto& e : graph.edges)
    cv::polylines(img, shifted(edgeLine(graph, e), f, 0.0), false, cv::Scalar(215, 215, 215), 7,
                  cv::LINE_AA);
  const double K = static_cast<double>(vehicle_edges.size());
  for (std::size_t k = 0; k < vehicle_edges.size(); ++k) {
    const double shift = 2.0 + 3.0 * (static_cast<double>(k) - 0.5 * (K - 1.0));
    for (int e : vehicle_edges[k]) {
      if (e < 0 || static_cast<std::size_t>(e) >= graph.edges.size()) continue;
      const auto line = edgeLine(graph, graph.edges[static_cast<std::size_t>(e)]);
      cv::polylines(img, shifted(line, f, shift), false, scalar(k), 3, cv::LINE_8);
    }
  }
  drawLegend(img, vehicle_edges.size());
  std::vector<uchar> png;
  if (!cv::imencode(".png", img, png))
    throw std::runtime_error(path.string() + ": PNG encoding failed");
  writeFileAtomic(path, std::string(png.begin(), png.end()));
}

}  // namespace slamroute::cli
