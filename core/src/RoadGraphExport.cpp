// RoadGraph exports for people and GIS tools: GeoJSON, GraphML (Boost's writer) and a PNG map.
// Boost.Graph's GraphML writer trips GCC 12's -Wmaybe-uninitialized inside Boost itself.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graphml.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/RoadGraph.hpp"

namespace slamroute {
using nlohmann::json;

void RoadGraph::writeGeoJson(const std::filesystem::path& path) const {
  // Coordinates are the net's projected metres (x east, y north), not WGS84 degrees.
  json fc = {{"type", "FeatureCollection"}, {"features", json::array()}};
  for (const auto& n : nodes) {
    fc["features"].push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "Point"}, {"coordinates", {n.pos.x(), n.pos.y(), n.pos.z()}}}},
         {"properties", {{"kind", "node"}, {"id", n.id}, {"sumo_junction", n.sumo_junction}}}});
  }
  for (const auto& e : edges) {
    json coords = json::array();
    for (const auto& p : e.polyline) coords.push_back({p.x(), p.y(), p.z()});
    if (coords.size() < 2) {
      const auto& a = nodes[static_cast<std::size_t>(e.u)].pos;
      const auto& b = nodes[static_cast<std::size_t>(e.v)].pos;
      coords = json::array({{a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}});
    }
    fc["features"].push_back({{"type", "Feature"},
                              {"geometry", {{"type", "LineString"}, {"coordinates", coords}}},
                              {"properties",
                               {{"kind", "edge"},
                                {"id", e.id},
                                {"u", e.u},
                                {"v", e.v},
                                {"length", e.length_m},
                                {"weight", e.weight},
                                {"street", e.street},
                                {"sumo_edges", e.sumo_edges}}}});
  }
  writeFileAtomic(path, fc.dump(1) + "\n");
}

void RoadGraph::writeGraphML(const std::filesystem::path& path) const {
  struct V {
    double x = 0, y = 0, z = 0;
    std::string junction;
  };
  struct E {
    int id = 0;
    double length = 0, weight = 0;
    int street = 0;
    std::string sumo_edges;
  };
  using G = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, V, E>;
  G g(nodes.size());
  for (const auto& n : nodes)
    g[static_cast<std::size_t>(n.id)] = {n.pos.x(), n.pos.y(), n.pos.z(), n.sumo_junction};
  for (const auto& e : edges) {
    std::string se;
    for (const auto& s : e.sumo_edges) se += (se.empty() ? "" : " ") + s;
    boost::add_edge(static_cast<std::size_t>(e.u), static_cast<std::size_t>(e.v),
                    E{e.id, e.length_m, e.weight, e.street, se}, g);
  }
  boost::dynamic_properties dp;
  dp.property("x", boost::get(&V::x, g));
  dp.property("y", boost::get(&V::y, g));
  dp.property("z", boost::get(&V::z, g));
  dp.property("sumo_junction", boost::get(&V::junction, g));
  dp.property("id", boost::get(&E::id, g));
  dp.property("length", boost::get(&E::length, g));
  dp.property("weight", boost::get(&E::weight, g));
  dp.property("street", boost::get(&E::street, g));
  dp.property("sumo_edges", boost::get(&E::sumo_edges, g));
  std::ostringstream os;
  boost::write_graphml(os, g, dp, true);
  writeFileAtomic(path, os.str());
}

namespace {

constexpr double kMarginPx = 40, kBarPx = 70;

/// World x/y to image pixels: one scale on both axes, y up.
struct PngFrame {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300, scale = 1.0;
  int rows = 0;
  void grow(const Point3& p) {
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  }
  cv::Point px(const Point3& p) const {
    return cv::Point(static_cast<int>(kMarginPx + (p.x() - xmin) * scale),
                     static_cast<int>(rows - kMarginPx - (p.y() - ymin) * scale));
  }
};

/// The viridis colour of a value in [vmin, vmax]; grey where there is no value.
struct ValueColours {
  double vmin = 1e300, vmax = -1e300;
  cv::Mat colours;
  explicit ValueColours(const std::vector<double>& values) {
    for (double v : values)
      if (std::isfinite(v)) vmin = std::min(vmin, v), vmax = std::max(vmax, v);
    if (!(vmax > vmin)) vmax = vmin + 1.0;
    cv::Mat lut(1, 256, CV_8UC1);
    for (int i = 0; i < 256; ++i) lut.at<uchar>(i) = static_cast<uchar>(i);
    cv::applyColorMap(lut, colours, cv::COLORMAP_VIRIDIS);
  }
  cv::Scalar operator()(double v) const {
    if (!std::isfinite(v)) return cv::Scalar(180, 180, 180);
    const int k = std::clamp(static_cast<int>(255.0 * (v - vmin) / (vmax - vmin)), 0, 255);
    const cv::Vec3b c = colours.at<cv::Vec3b>(0, k);
    return cv::Scalar(c[0], c[1], c[2]);
  }
};

/// An edge's polyline in pixels, shifted shift_px to the right of its travel direction.
std::vector<cv::Point> shiftedPixels(const std::vector<Point3>& world, const PngFrame& frame,
                                     double shift_px) {
  std::vector<cv::Point> pts;
  for (std::size_t k = 0; k < world.size(); ++k) {
    const Point3 a = world[k == 0 ? 0 : k - 1], b = world[k == 0 ? 1 : k];
    Eigen::Vector2d d(b.x() - a.x(), b.y() - a.y());
    const double n = d.norm();
    // Right of travel in the image (y points down): (dy, -dx) in world -> (dy, dx) in pixels.
    Eigen::Vector2d right = Eigen::Vector2d::Zero();
    if (n > 1e-9) right = Eigen::Vector2d(d.y(), -d.x()) / n;
    const cv::Point p0 = frame.px(world[k]);
    pts.emplace_back(p0.x + static_cast<int>(std::lround(right.x() * shift_px)),
                     p0.y - static_cast<int>(std::lround(right.y() * shift_px)));
  }
  return pts;
}

/// Colour bar with the value range, the attribute's name and a 100 m scale bar.
void drawLegend(cv::Mat& img, const ValueColours& colour, const std::string& attribute,
                double scale, int width_px) {
  const int margin = static_cast<int>(kMarginPx);
  const int bx = width_px - static_cast<int>(kBarPx) + 10, by0 = margin, by1 = img.rows - margin;
  for (int y = by0; y <= by1; ++y) {
    const double v = colour.vmax - (colour.vmax - colour.vmin) * (y - by0) / std::max(1, by1 - by0);
    cv::line(img, {bx, y}, {bx + 15, y}, colour(v));
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", colour.vmax);
  cv::putText(img, buf, {bx - 5, by0 - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0));
  std::snprintf(buf, sizeof buf, "%.3g", colour.vmin);
  cv::putText(img, buf, {bx - 5, by1 + 16}, cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0));
  cv::putText(img, attribute, {margin, 22}, cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0));
  const int sb = static_cast<int>(100.0 * scale);
  cv::line(img, {margin, img.rows - 15}, {margin + sb, img.rows - 15}, cv::Scalar(0, 0, 0), 2);
  cv::putText(img, "100 m", {margin + sb + 6, img.rows - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.4,
              cv::Scalar(0, 0, 0));
}

/// The value drawn per edge: `values` (NaN past its end), else the edge's length or weight.
std::vector<double> edgeValues(const std::vector<RoadEdge>& edges, const std::string& attribute,
                               const std::vector<double>& values) {
  std::vector<double> val(edges.size(), 0.0);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!values.empty()) {
      val[i] = i < values.size() ? values[i] : std::numeric_limits<double>::quiet_NaN();
    } else if (attribute == "length") {
      val[i] = edges[i].length_m;
    } else {
      val[i] = edges[i].weight;
    }
  }
  return val;
}

}  // namespace

void RoadGraph::renderPng(const std::filesystem::path& path, const std::string& attribute,
                          const std::vector<double>& values, int width_px) const {
  const std::vector<double> val = edgeValues(edges, attribute, values);
  PngFrame frame;
  for (const auto& n : nodes) frame.grow(n.pos);
  for (const auto& e : edges)
    for (const auto& p : e.polyline) frame.grow(p);
  if (nodes.empty()) frame.xmin = frame.ymin = 0, frame.xmax = frame.ymax = 1;
  const double span = std::max({frame.xmax - frame.xmin, frame.ymax - frame.ymin, 1.0});
  frame.scale = (width_px - 2 * kMarginPx - kBarPx) / span;
  const int height = static_cast<int>((frame.ymax - frame.ymin) * frame.scale + 2 * kMarginPx + 30);
  cv::Mat img(std::max(height, 200), width_px, CV_8UC3, cv::Scalar(255, 255, 255));
  frame.rows = img.rows;
  const ValueColours colour(val);
  // Both directions of a street share a centreline: draw each directed edge shifted a few
  // pixels to the right of its travel direction, and the edges without a value (grey) first so
  // they never hide coloured ones.
  std::vector<std::size_t> order(edges.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return !std::isfinite(val[a]) && std::isfinite(val[b]);
  });
  for (std::size_t i : order) {
    const auto& e = edges[i];
    std::vector<Point3> world = e.polyline;
    if (world.size() < 2)
      world = {nodes[static_cast<std::size_t>(e.u)].pos, nodes[static_cast<std::size_t>(e.v)].pos};
    cv::polylines(img, shiftedPixels(world, frame, 2.5), false, colour(val[i]), 3, cv::LINE_AA);
  }
  for (const auto& n : nodes)
    cv::circle(img, frame.px(n.pos), 4, cv::Scalar(40, 40, 40), -1, cv::LINE_AA);
  drawLegend(img, colour, attribute, frame.scale, width_px);
  std::vector<uchar> png;
  if (!cv::imencode(".png", img, png))
    throw std::runtime_error(path.string() + ": PNG encoding failed");
  writeFileAtomic(path, std::string(png.begin(), png.end()));
}

}  // namespace slamroute
