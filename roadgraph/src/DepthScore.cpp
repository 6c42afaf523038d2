// Paper §3.1 step 4: LiDAR matching quality from the spread of depth-image normals.
//
// Eq. 3 reprojects each pixel (x, y) with depth D as X = y, Y = D, Z = W - x ("only in the depth
// direction"). The paper does not say in which unit D is compared with pixels; we scale it by
// depth_px_per_m (40 px/m = the pixel footprint of a 90-degree, 800 px wide camera at 10 m), so a
// surface tilted by 45 degrees at 10 m keeps roughly its tilt in the reprojected cloud.
// Eq. 4: each normal is the smallest eigenvector of the covariance of the 14 nearest points
// (3D distance, the point itself included, as a k-d tree k-NN would return). The candidates are
// taken from a small window of the (strided) pixel grid: on a depth image the 3D neighbours of a
// point are its image neighbours, so this equals the k-d tree answer except across depth jumps,
// and costs O(1) per point.
//
// Spread score (the paper only says "the more widely the normals are spread, the higher"): the
// normals' scatter matrix S = 1/N sum n n^T (sign-free, so n and -n count the same) has
// eigenvalues l1 >= l2 >= l3 >= 0 with l1 + l2 + l3 = 1. Its normalised Shannon entropy
//   score = -(sum l_k ln l_k) / ln 3   in [0, 1]
// is 0 when every normal points one way (a single plane: a LiDAR scan of it constrains one
// direction only), about 0.63 for two equally seen orthogonal planes and 1 when normals are spread
// evenly over all three axes (a corner: planes in every direction, what LeGO-LOAM's planar and
// edge features need). It grows with every additional well-represented direction, which is the
// property the paper asks for, and it is invariant to the camera's orientation.
// Frames with fewer than min_normals normals (sky, no returns) score 0.
#include "slamroute/roadgraph/DepthScore.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "PointGrid.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::roadgraph {

DepthImage readDepthPng(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path.string() + ": depth frame missing");
  cv::Mat m;
  try {
    m = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(path.string() + ": depth frame unreadable (" + e.what() + ")");
  }
  if (m.empty()) throw std::runtime_error(path.string() + ": depth frame corrupt or not an image");
  if (m.type() != CV_16UC1)
    throw std::runtime_error(path.string() + ": depth frame is not single-channel 16-bit");
  DepthImage img;
  img.width = m.cols;
  img.height = m.rows;
  img.mm.resize(static_cast<std::size_t>(m.cols) * static_cast<std::size_t>(m.rows));
  for (int y = 0; y < m.rows; ++y) {
    const auto* row = m.ptr<std::uint16_t>(y);
    std::copy(row, row + m.cols, img.mm.begin() + static_cast<long>(y) * m.cols);
  }
  return img;
}

void writeDepthPng(const std::filesystem::path& path, const DepthImage& img) {
  if (img.mm.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height))
    throw std::invalid_argument(path.string() + ": depth image has inconsistent size");
  const cv::Mat m(img.height, img.width, CV_16UC1, const_cast<std::uint16_t*>(img.mm.data()));
  std::vector<uchar> buf;
  if (!cv::imencode(".png", m, buf))
    throw std::runtime_error(path.string() + ": cannot encode depth PNG");
  writeFileAtomic(path, std::string(buf.begin(), buf.end()));
}

namespace {

/// Eq. 3 on every pixel_stride-th pixel: X = y, Y = D, Z = W - x (D scaled to pixel units);
/// pixels without a return (or beyond max_depth_m) are not valid.
struct ReprojectedGrid {
  int gw = 0, gh = 0;
  std::vector<Point3> P;
  std::vector<char> valid;
  std::size_t index(int gx, int gy) const {
    return static_cast<std::size_t>(gy) * static_cast<std::size_t>(gw) +
           static_cast<std::size_t>(gx);
  }
};

ReprojectedGrid reproject(const DepthImage& img, const DepthConfig& cfg, int stride) {
  ReprojectedGrid g;
  g.gw = (img.width + stride - 1) / stride;
  g.gh = (img.height + stride - 1) / stride;
  g.P.resize(static_cast<std::size_t>(g.gw) * static_cast<std::size_t>(g.gh));
  g.valid.assign(g.P.size(), 0);
  for (int gy = 0; gy < g.gh; ++gy)
    for (int gx = 0; gx < g.gw; ++gx) {
      const int x = gx * stride, y = gy * stride;
      const double d = img.at(x, y) / 1000.0;
      if (d <= 0.0 || d > cfg.max_depth_m) continue;
      const std::size_t i = g.index(gx, gy);
      g.P[i] = Point3(y, d * cfg.depth_px_per_m, img.width - x);
      g.valid[i] = 1;
    }
  return g;
}

/// Eq. 4: the normal (smallest eigenvector of the covariance) of the k nearest valid points
/// among those within `window` grid cells of (gx, gy); false at the border or on sparse returns.
bool normalAt(const ReprojectedGrid& g, int gx, int gy, int window, int k,
              std::vector<std::pair<double, int>>& cand, Vec3& n) {
  const std::size_t i = g.index(gx, gy);
  cand.clear();
  for (int ay = std::max(0, gy - window); ay <= std::min(g.gh - 1, gy + window); ++ay)
    for (int ax = std::max(0, gx - window); ax <= std::min(g.gw - 1, gx + window); ++ax) {
      const std::size_t j = g.index(ax, ay);
      if (g.valid[j]) cand.emplace_back((g.P[j] - g.P[i]).squaredNorm(), static_cast<int>(j));
    }
  if (static_cast<int>(cand.size()) < k) return false;
  std::nth_element(cand.begin(), cand.begin() + (k - 1), cand.end());
  const auto point = [&](int q) {
    return g.P[static_cast<std::size_t>(cand[static_cast<std::size_t>(q)].second)];
  };
  Point3 mean = Point3::Zero();
  for (int q = 0; q < k; ++q) mean += point(q);
  mean /= k;
  Mat3 C = Mat3::Zero();
  for (int q = 0; q < k; ++q) {
    const Vec3 d = point(q) - mean;
    C += d * d.transpose();
  }
  C /= k;
  Eigen::SelfAdjointEigenSolver<Mat3> es;
  es.computeDirect(C);
  n = es.eigenvectors().col(0).normalized();
  return n.allFinite();
}

/// The spread of the normals: normalised entropy of the eigenvalues of their scatter matrix S
/// (the sum of n n^T over `count` normals).
void spreadScore(Mat3 S, int count, FrameScore& fs) {
  S /= count;
  Eigen::SelfAdjointEigenSolver<Mat3> es(S);
  Vec3 l = es.eigenvalues().reverse().cwiseMax(0.0);
  l /= std::max(l.sum(), 1e-12);
  fs.eigenvalues = l;
  double h = 0.0;
  for (int q = 0; q < 3; ++q)
    if (l[q] > 1e-12) h -= l[q] * std::log(l[q]);
  fs.score = std::clamp(h / std::log(3.0), 0.0, 1.0);
}

}  // namespace

FrameScore scoreDepthImage(const DepthImage& img, const DepthConfig& cfg) {
  if (img.width <= 0 || img.height <= 0 ||
      img.mm.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height))
    throw std::invalid_argument("depth image has inconsistent size");
  const int k = std::max(3, cfg.normal_neighbours);
  int w = std::max(1, cfg.search_window_px);
  while ((2 * w + 1) * (2 * w + 1) < k) ++w;
  const ReprojectedGrid g = reproject(img, cfg, std::max(1, cfg.pixel_stride));
  Mat3 S = Mat3::Zero();
  int count = 0;
  std::vector<std::pair<double, int>> cand;
  for (int gy = 0; gy < g.gh; ++gy)
    for (int gx = 0; gx < g.gw; ++gx) {
      Vec3 n;
      if (!g.valid[g.index(gx, gy)] || !normalAt(g, gx, gy, w, k, cand, n)) continue;
      S += n * n.transpose();
      ++count;
    }
  FrameScore fs;
  fs.normals = count;
  if (count < std::max(1, cfg.min_normals)) return fs;  // nothing to match against: score 0
  spreadScore(S, count, fs);
  return fs;
}

std::vector<DepthFrame> readDepthIndex(const std::filesystem::path& index_csv) {
  std::ifstream in(index_csv);
  if (!in) throw std::runtime_error(index_csv.string() + ": cannot open depth index");
  std::string line;
  if (!std::getline(in, line))
    throw std::invalid_argument(index_csv.string() + ": empty depth index");
  auto split = [](const std::string& l) {
    std::vector<std::string> f;
    std::string cur;
    for (char c : l) {
      if (c == ',') {
        f.push_back(cur);
        cur.clear();
      } else if (c != '\r') {
        cur.push_back(c);
      }
    }
    f.push_back(cur);
    return f;
  };
  const auto header = split(line);
  auto col = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  };
  const int cx = col("x"), cy = col("y"), cz = col("z"), cf = col("file"), ct = col("t"),
            cv = col("vehicle"), cn = col("frame"), cw = col("width"), ch = col("height");
  if (cx < 0 || cy < 0 || cf < 0)
    throw std::invalid_argument(index_csv.string() + ": depth index needs columns x, y and file");
  std::vector<DepthFrame> frames;
  const auto dir = index_csv.parent_path();
  std::size_t lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line == "\r") continue;
    const auto f = split(line);
    if (f.size() < header.size())
      throw std::invalid_argument(index_csv.string() + ":" + std::to_string(lineno) +
                                  ": too few columns");
    DepthFrame fr;
    try {
      fr.pos = Point3(std::stod(f[static_cast<std::size_t>(cx)]),
                      std::stod(f[static_cast<std::size_t>(cy)]),
                      cz >= 0 ? std::stod(f[static_cast<std::size_t>(cz)]) : 0.0);
      if (ct >= 0) fr.t = std::stod(f[static_cast<std::size_t>(ct)]);
      if (cn >= 0) fr.frame = std::stol(f[static_cast<std::size_t>(cn)]);
      if (cw >= 0 && ch >= 0) {
        fr.width = std::stoi(f[static_cast<std::size_t>(cw)]);
        fr.height = std::stoi(f[static_cast<std::size_t>(ch)]);
      }
    } catch (const std::exception&) {
      throw std::invalid_argument(index_csv.string() + ":" + std::to_string(lineno) +
                                  ": unparsable number");
    }
    if (cv >= 0) fr.vehicle = f[static_cast<std::size_t>(cv)];
    const std::filesystem::path file = f[static_cast<std::size_t>(cf)];
    fr.file = file.is_absolute() ? file : dir / file;
    frames.push_back(std::move(fr));
  }
  return frames;
}

namespace {

/// Frames of one survey come from one camera: a frame of another size than most (a stray file, a
/// frame from another survey) is skipped with an error naming it.
void skipOddSizedFrames(const std::vector<DepthFrame>& frames,
                        const std::vector<std::pair<int, int>>& size, std::vector<double>& score,
                        std::vector<std::string>& error) {
  std::map<std::pair<int, int>, std::size_t> count;
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (!std::isnan(score[i])) ++count[size[i]];
  if (count.size() < 2) return;
  const auto common =
      std::max_element(count.begin(), count.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
      })->first;
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (!std::isnan(score[i]) && size[i] != common) {
      score[i] = std::numeric_limits<double>::quiet_NaN();
      error[i] = frames[i].file.string() + ": " + std::to_string(size[i].first) + " x " +
                 std::to_string(size[i].second) + " px, the survey's other frames are " +
                 std::to_string(common.first) + " x " + std::to_string(common.second) + " px";
    }
}

/// Per frame: its score (NaN when unusable), why it is unusable, and its image size.
struct FrameScores {
  std::vector<double> score;
  std::vector<std::string> error;
  std::vector<std::pair<int, int>> size;
};

/// Scores every frame; frames are independent, so they run on all cores.
FrameScores scoreFrames(const std::vector<DepthFrame>& frames, const DepthConfig& cfg) {
  FrameScores fs;
  fs.score.assign(frames.size(), std::numeric_limits<double>::quiet_NaN());
  fs.error.resize(frames.size());
  fs.size.assign(frames.size(), {0, 0});
  Progress progress("depth frames", frames.size());
  std::mutex mu;
  std::size_t done = 0;
  tbb::parallel_for(std::size_t{0}, frames.size(), [&](std::size_t i) {
    if (!frames[i].pos.allFinite()) {
      fs.error[i] = "frame " + std::to_string(frames[i].frame) + ": NaN position";
    } else {
      try {
        const DepthImage img = readDepthPng(frames[i].file);
        fs.size[i] = {img.width, img.height};
        if (frames[i].width > 0 && (img.width != frames[i].width || img.height != frames[i].height))
          throw std::invalid_argument(frames[i].file.string() + ": " + std::to_string(img.width) +
                                      " x " + std::to_string(img.height) + " px, the index says " +
                                      std::to_string(frames[i].width) + " x " +
                                      std::to_string(frames[i].height) + " px");
        fs.score[i] = scoreDepthImage(img, cfg).score;
      } catch (const std::exception& e) {
        fs.error[i] = e.what();
      }
    }
    std::lock_guard<std::mutex> lock(mu);
    ++done;
    if (done % 64 == 0) progress.update(done);
  });
  progress.finish();
  skipOddSizedFrames(frames, fs.size, fs.score, fs.error);
  return fs;
}

std::size_t logSkippedFrames(const std::vector<std::string>& error) {
  std::size_t failed = 0;
  for (const auto& e : error)
    if (!e.empty() && failed++ < 5) logWarn("depth: skipping frame: " + e);
  if (failed > 5) logWarn("depth: " + std::to_string(failed) + " frames skipped in total");
  return failed;
}

/// Every street's centreline sampled every metre: its first edge's polyline, and for a divided
/// street (two directions on their own carriageways) the other direction's too.
struct StreetSamples {
  int streets = 0;
  std::vector<Point3> points;
  std::vector<int> street;
};

void samplePolyline(const Polyline& pl, int street, StreetSamples& out) {
  for (std::size_t k = 0; k + 1 < pl.size(); ++k) {
    const int m = std::max(1, static_cast<int>(std::ceil((pl[k + 1] - pl[k]).norm())));
    for (int q = 0; q < m; ++q) {
      out.points.push_back(pl[k] + (pl[k + 1] - pl[k]) * (static_cast<double>(q) / m));
      out.street.push_back(street);
    }
  }
  if (!pl.empty()) {
    out.points.push_back(pl.back());
    out.street.push_back(street);
  }
}

StreetSamples streetSamples(const RoadGraph& graph) {
  StreetSamples out;
  for (const auto& e : graph.edges) out.streets = std::max(out.streets, e.street + 1);
  std::vector<int> first(static_cast<std::size_t>(out.streets), -1);
  for (const auto& e : graph.edges)
    if (e.street >= 0 && first[static_cast<std::size_t>(e.street)] < 0)
      first[static_cast<std::size_t>(e.street)] = e.id;
  for (int s = 0; s < out.streets; ++s)
    if (first[static_cast<std::size_t>(s)] >= 0)
      samplePolyline(
          graph.edges[static_cast<std::size_t>(first[static_cast<std::size_t>(s)])].polyline, s,
          out);
  for (const auto& e : graph.edges) {
    if (e.street < 0 || first[static_cast<std::size_t>(e.street)] == e.id) continue;
    const Polyline& f =
        graph.edges[static_cast<std::size_t>(first[static_cast<std::size_t>(e.street)])].polyline;
    if (!std::equal(f.rbegin(), f.rend(), e.polyline.begin(), e.polyline.end()))
      samplePolyline(e.polyline, e.street, out);
  }
  return out;
}

/// Per street, the sum and number of the scores of the frames nearest to it (within
/// frame_max_dist_m); counts scored and unassigned frames and their total in ws.
void framesPerStreet(const std::vector<DepthFrame>& frames, const std::vector<double>& score,
                     const StreetSamples& ss, const DepthConfig& cfg, WeightStats& ws,
                     std::vector<double>& sum, std::vector<int>& cnt, double& total) {
  sum.assign(static_cast<std::size_t>(ss.streets), 0.0);
  cnt.assign(static_cast<std::size_t>(ss.streets), 0);
  total = 0.0;
  const detail::PointGrid grid(ss.points, std::max(cfg.frame_max_dist_m, 1.0));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (std::isnan(score[i])) continue;
    ++ws.scored;
    total += score[i];
    int best = -1;
    double bd = std::numeric_limits<double>::infinity();
    grid.forEachNear(frames[i].pos, cfg.frame_max_dist_m, cfg.frame_max_dist_m, [&](int j) {
      const double d = (ss.points[static_cast<std::size_t>(j)] - frames[i].pos).squaredNorm();
      if (d < bd) {
        bd = d;
        best = ss.street[static_cast<std::size_t>(j)];
      }
    });
    if (best < 0) {
      ++ws.unassigned;
      continue;
    }
    sum[static_cast<std::size_t>(best)] += score[i];
    ++cnt[static_cast<std::size_t>(best)];
  }
}

/// Not one frame measured anything (frames far smaller than the camera's, a stride too coarse
/// for min_normals): weights of 0 would say every street is featureless, so none is used.
void dropAllZeroScores(const FrameScores& fs, const DepthConfig& cfg, WeightStats& ws,
                       std::vector<int>& cnt) {
  const auto& [w, h] = fs.size[static_cast<std::size_t>(
      std::find_if(fs.score.begin(), fs.score.end(), [](double v) { return !std::isnan(v); }) -
      fs.score.begin())];
  logWarn("depth: all " + std::to_string(ws.scored) + " frames scored 0 (" + std::to_string(w) +
          " x " + std::to_string(h) + " px at pixel_stride " + std::to_string(cfg.pixel_stride) +
          ", min_normals " + std::to_string(cfg.min_normals) +
          "): they carry no information and are not used");
  ws.failed += ws.scored;
  ws.scored = 0;
  std::fill(cnt.begin(), cnt.end(), 0);
}

}  // namespace

WeightStats assignDepthWeights(RoadGraph& graph, const std::vector<DepthFrame>& frames,
                               const DepthConfig& cfg) {
  WeightStats ws;
  ws.frames = frames.size();
  ws.fallback_weight = cfg.fallback_weight;
  const FrameScores fs = scoreFrames(frames, cfg);
  ws.failed = logSkippedFrames(fs.error);
  const StreetSamples ss = streetSamples(graph);
  ws.streets = static_cast<std::size_t>(ss.streets);
  std::vector<double> sum;
  std::vector<int> cnt;
  double total = 0.0;
  framesPerStreet(frames, fs.score, ss, cfg, ws, sum, cnt, total);
  ws.mean_score = ws.scored > 0 ? total / static_cast<double>(ws.scored) : 0.0;
  if (ws.scored > 0 && total == 0.0) dropAllZeroScores(fs, cfg, ws, cnt);
  // Documented fallback: a street without a usable frame gets the mean score of all frames; with
  // no usable frame at all every edge gets cfg.fallback_weight (1, RoadEdge's default).
  const double fallback = ws.scored > 0 ? ws.mean_score : cfg.fallback_weight;
  if (ws.scored == 0)
    logWarn("depth: no usable depth frame; every edge gets the fallback weight " +
            std::to_string(cfg.fallback_weight));
  for (const int c : cnt)
    if (c > 0) ++ws.streets_with_frames;
  if (ws.scored > 0 && ws.streets_with_frames < ws.streets)
    logWarn("depth: " + std::to_string(ws.streets - ws.streets_with_frames) +
            " street(s) without a depth frame get the mean score " + std::to_string(fallback));
  for (auto& e : graph.edges) {
    const auto s = static_cast<std::size_t>(e.street);
    e.weight = (e.street >= 0 && cnt[s] > 0) ? sum[s] / cnt[s] : fallback;
  }
  return ws;
}

}  // namespace slamroute::roadgraph
