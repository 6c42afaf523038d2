// World mesh reader (PLY) and map-to-surface distances.
#include "slamroute/evaluate/MapAccuracy.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::evaluate {
namespace {

int typeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

double readBinary(const char* p, const std::string& t) {
  auto get = [&](auto v) {
    std::memcpy(&v, p, sizeof(v));
    return static_cast<double>(v);
  };
  if (t == "char" || t == "int8") return get(std::int8_t{});
  if (t == "uchar" || t == "uint8") return get(std::uint8_t{});
  if (t == "short" || t == "int16") return get(std::int16_t{});
  if (t == "ushort" || t == "uint16") return get(std::uint16_t{});
  if (t == "int" || t == "int32") return get(std::int32_t{});
  if (t == "uint" || t == "uint32") return get(std::uint32_t{});
  if (t == "float" || t == "float32") return get(float{});
  return get(double{});
}

struct Prop {
  std::string name, type, count_type;  // count_type non-empty for lists
};
struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Prop> props;
};

/// Ericson, Real-Time Collision Detection §5.1.5: closest point on triangle abc to p.
Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                  const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = va + vb + vc;
  if (std::abs(denom) < 1e-300) return a;  // degenerate triangle
  const double v = vb / denom, w = vc / denom;
  return a + ab * v + ac * w;
}

/// A PLY header: its format and elements; `pos` ends at the first byte of the body.
struct PlyHeader {
  std::string format;
  std::vector<Element> elems;
};

/// The header line starting at pos (without "\r\n"); pos moves past it.
std::string headerLine(const std::string& data, std::size_t& pos, const std::string& where) {
  const std::size_t e = data.find('\n', pos);
  if (e == std::string::npos) throw std::runtime_error(where + ": truncated PLY header");
  std::string l = data.substr(pos, e - pos);
  if (!l.empty() && l.back() == '\r') l.pop_back();
  pos = e + 1;
  return l;
}

Prop readProperty(std::istringstream& ss) {
  Prop p;
  std::string t;
  ss >> t;
  if (t == "list") {
    ss >> p.count_type >> p.type >> p.name;
  } else {
    p.type = t;
    ss >> p.name;
  }
  return p;
}

PlyHeader readHeader(const std::string& data, std::size_t& pos, const std::string& where) {
  if (headerLine(data, pos, where) != "ply") throw std::runtime_error(where + ": not a PLY file");
  PlyHeader h;
  for (;;) {
    std::istringstream ss(headerLine(data, pos, where));
    std::string kw;
    ss >> kw;
    if (kw == "end_header") break;
    if (kw == "format") {
      ss >> h.format;
    } else if (kw == "element") {
      Element e;
      ss >> e.name >> e.count;
      h.elems.push_back(e);
    } else if (kw == "property") {
      if (h.elems.empty()) throw std::runtime_error(where + ": property before element");
      h.elems.back().props.push_back(readProperty(ss));
    }
  }
  if (h.format != "binary_little_endian" && h.format != "ascii")
    throw std::runtime_error(where + ": unsupported PLY format '" + h.format + "'");
  return h;
}

/// The values of a PLY body, one after the other, in binary (little-endian) or ASCII.
class PlyBody {
 public:
  PlyBody(const std::string& data, std::size_t pos, bool binary, const std::string& where)
      : data_(data),
        pos_(pos),
        binary_(binary),
        where_(where),
        ascii_(binary ? std::string() : data.substr(pos)) {}
  double value(const std::string& type) {
    if (binary_) {
      const int s = typeSize(type);
      if (s == 0) throw std::runtime_error(where_ + ": unknown PLY type '" + type + "'");
      if (pos_ + static_cast<std::size_t>(s) > data_.size())
        throw std::runtime_error(where_ + ": truncated PLY body");
      const double v = readBinary(data_.data() + pos_, type);
      pos_ += static_cast<std::size_t>(s);
      return v;
    }
    double v;
    if (!(ascii_ >> v)) throw std::runtime_error(where_ + ": truncated PLY body");
    return v;
  }

 private:
  const std::string& data_;
  std::size_t pos_;
  bool binary_;
  const std::string& where_;
  std::istringstream ascii_;
};

/// One item of element e: a vertex's x, y, z or a face's vertex list (fanned into triangles);
/// other elements and properties are read past.
void readItem(const Element& e, PlyBody& body, Mesh& mesh) {
  Eigen::Vector3f v = Eigen::Vector3f::Zero();
  for (const Prop& p : e.props) {
    if (!p.count_type.empty()) {
      const int n = static_cast<int>(body.value(p.count_type));
      std::vector<int> idx(static_cast<std::size_t>(std::max(n, 0)));
      for (int k = 0; k < n; ++k)
        idx[static_cast<std::size_t>(k)] = static_cast<int>(body.value(p.type));
      if (e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index"))
        for (int k = 2; k < n; ++k)
          mesh.faces.push_back(
              {idx[0], idx[static_cast<std::size_t>(k - 1)], idx[static_cast<std::size_t>(k)]});
      continue;
    }
    const double x = body.value(p.type);
    if (e.name != "vertex") continue;
    if (p.name == "x") v.x() = static_cast<float>(x);
    if (p.name == "y") v.y() = static_cast<float>(x);
    if (p.name == "z") v.z() = static_cast<float>(x);
  }
  if (e.name == "vertex") mesh.vertices.push_back(v);
}

}  // namespace

Mesh readPly(const std::filesystem::path& path) {
  const std::string data = readFile(path);
  const std::string where = path.string();
  std::size_t pos = 0;
  const PlyHeader header = readHeader(data, pos, where);
  PlyBody body(data, pos, header.format == "binary_little_endian", where);
  Mesh mesh;
  for (const Element& e : header.elems)
    for (std::size_t i = 0; i < e.count; ++i) readItem(e, body, mesh);
  const int nv = static_cast<int>(mesh.vertices.size());
  for (const auto& f : mesh.faces)
    for (int k : f)
      if (k < 0 || k >= nv) throw std::runtime_error(where + ": face index out of range");
  return mesh;
}

MapAccuracyMeter::MapAccuracyMeter(const Mesh& mesh, double max_m,
                                   const Eigen::AlignedBox3f& bounds)
    : mesh_(mesh), max_m_(max_m) {
  if (!(max_m > 0)) throw std::invalid_argument("mapAccuracy: max distance must be positive");
  hist_.assign(static_cast<std::size_t>(std::ceil(max_m / kBinM)) + 1, 0);
  if (bounds.isEmpty()) return;
  // Grid over the bounds' xy (+ one cell).
  const double cell = max_m;
  lo_ = bounds.min().head<2>().cast<double>().array() - cell;
  const Eigen::Vector2d hi = bounds.max().head<2>().cast<double>().array() + cell;
  nx_ = static_cast<int>(std::ceil((hi.x() - lo_.x()) / cell)) + 1;
  ny_ = static_cast<int>(std::ceil((hi.y() - lo_.y()) / cell)) + 1;
  if (static_cast<double>(nx_) * ny_ > 5e7)
    throw std::invalid_argument("mapAccuracy: map too large for the grid");
  const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  // Each triangle's cells (those its xy box overlaps), counted, then placed: one index array,
  // not a list per cell.
  const auto forEachCell = [&](std::size_t f, auto&& fn) {
    Eigen::Vector2d a(1e300, 1e300), b(-1e300, -1e300);
    for (int k : mesh.faces[f]) {
      a = a.cwiseMin(mesh.vertices[static_cast<std::size_t>(k)].head<2>().cast<double>());
      b = b.cwiseMax(mesh.vertices[static_cast<std::size_t>(k)].head<2>().cast<double>());
    }
    const int x0 = std::max(0, static_cast<int>(std::floor((a.x() - lo_.x()) / cell)));
    const int y0 = std::max(0, static_cast<int>(std::floor((a.y() - lo_.y()) / cell)));
    const int x1 = std::min(nx_ - 1, static_cast<int>(std::floor((b.x() - lo_.x()) / cell)));
    const int y1 = std::min(ny_ - 1, static_cast<int>(std::floor((b.y() - lo_.y()) / cell)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        fn(static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(x));
  };
  cell_start_.assign(cells + 1, 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    forEachCell(f, [&](std::size_t c) { ++cell_start_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_faces_.resize(cell_start_[cells]);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    forEachCell(f, [&](std::size_t c) { cell_faces_[fill[c]++] = static_cast<std::uint32_t>(f); });
  seen_.assign(mesh.faces.size(), 0);
}

void MapAccuracyMeter::add(const Cloud& part, std::vector<float>* dist_m) {
  const double cell = max_m_;
  for (const auto& pf : part) {
    const std::uint64_t stamp = ++counter_;
    const Eigen::Vector3d p = pf.cast<double>();
    const int cx = static_cast<int>(std::floor((p.x() - lo_.x()) / cell));
    const int cy = static_cast<int>(std::floor((p.y() - lo_.y()) / cell));
    double best2 = max_m_ * max_m_;
    for (int y = std::max(0, cy - 1); y <= std::min(ny_ - 1, cy + 1); ++y)
      for (int x = std::max(0, cx - 1); x <= std::min(nx_ - 1, cx + 1); ++x) {
        const std::size_t c = static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
                              static_cast<std::size_t>(x);
        for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          const std::uint32_t f = cell_faces_[k];
          if (seen_[f] == stamp) continue;
          seen_[f] = stamp;
          const auto& tri = mesh_.faces[f];
          const Eigen::Vector3d q =
              closestOnTriangle(p, mesh_.vertices[static_cast<std::size_t>(tri[0])].cast<double>(),
                                mesh_.vertices[static_cast<std::size_t>(tri[1])].cast<double>(),
                                mesh_.vertices[static_cast<std::size_t>(tri[2])].cast<double>());
          best2 = std::min(best2, (q - p).squaredNorm());
        }
      }
    const double dist = std::sqrt(best2);
    if (dist >= max_m_)
      ++clamped_;
    else
      ++hist_[std::min(hist_.size() - 1, static_cast<std::size_t>(dist / kBinM))];
    sum_ += dist;
    if (dist_m) dist_m->push_back(static_cast<float>(dist));
  }
}

double MapAccuracyMeter::quantile(std::uint64_t rank) const {
  std::uint64_t below = 0;
  for (std::size_t b = 0; b < hist_.size(); ++b) {
    below += hist_[b];
    if (rank < below) return std::min(max_m_, (static_cast<double>(b) + 0.5) * kBinM);
  }
  return max_m_;  // among the clamped points
}

MapAccuracy MapAccuracyMeter::result() const {
  MapAccuracy out;
  out.points = static_cast<int>(counter_);
  if (counter_ == 0) return out;
  const std::uint64_t n = counter_;
  out.mean_m = sum_ / static_cast<double>(n);
  out.median_m = quantile(n / 2);
  out.p95_m = quantile(std::min(n - 1, static_cast<std::uint64_t>(0.95 * static_cast<double>(n))));
  out.clamped_share = static_cast<double>(clamped_) / static_cast<double>(n);
  return out;
}

MapAccuracy mapAccuracy(const Cloud& map, const Mesh& mesh, double max_m) {
  if (map.empty()) return {};
  Eigen::AlignedBox3f bounds;
  for (const auto& p : map) bounds.extend(p);
  MapAccuracyMeter meter(mesh, max_m, bounds);
  meter.add(map);
  return meter.result();
}

}  // namespace slamroute::evaluate
