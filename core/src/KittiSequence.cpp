// KITTI odometry sequence folders (KittiSequence.hpp).
#include "slamroute/core/KittiSequence.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute {
namespace fs = std::filesystem;
namespace {

std::invalid_argument bad(const fs::path& p, const std::string& what) {
  return std::invalid_argument(p.string() + ": " + what);
}

/// The numbers after "Tr:" on one line of calib.txt (throws naming the file on a bad one).
std::vector<double> numbersAfterKey(const fs::path& calib, const std::string& line) {
  std::istringstream in(line.substr(line.find(':') + 1));
  std::vector<double> v;
  std::string tok;
  while (in >> tok) {
    std::size_t used = 0;
    try {
      v.push_back(std::stod(tok, &used));
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != tok.size()) throw bad(calib, "Tr: not a number '" + tok + "'");
  }
  return v;
}

/// velodyne/ holds exactly NNNNNN.bin for NNNNNN = 0 .. n-1.
void checkScanFiles(const fs::path& velodyne, const fs::path& times, std::size_t n) {
  std::size_t bins = 0;
  for (const auto& e : fs::directory_iterator(velodyne)) bins += e.path().extension() == ".bin";
  if (bins != n)
    throw bad(velodyne, std::to_string(bins) + " scans (.bin) for " + std::to_string(n) +
                            " times in " + times.string());
  for (std::size_t i = 0; i < n; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.bin", i);
    if (!fs::exists(velodyne / name))
      throw bad(velodyne / name,
                "missing (scans are numbered "
                "000000.bin on, one per line of times.txt)");
  }
}

/// poses.txt (camera frame) at the scans' times, brought into the LiDAR frame by calib's Tr.
Trajectory lidarGroundTruth(const fs::path& dir, const ScanSource& scans) {
  const fs::path poses = dir / kitti_files::kPoses, calib = dir / kitti_files::kCalib;
  if (!fs::exists(calib))
    throw bad(calib,
              "not found; the ground truth in poses.txt is in the camera frame and "
              "calib.txt's Tr brings it into the LiDAR's");
  const Pose3 Tr = readKittiCalibTr(calib);
  Trajectory gt = readKittiPoses(poses);
  if (gt.size() != scans.size())
    throw bad(poses, std::to_string(gt.size()) + " poses for " + std::to_string(scans.size()) +
                         " scans in times.txt");
  const Pose3 Tr_inv = Tr.inverse();
  for (std::size_t i = 0; i < gt.size(); ++i) {
    gt[i].t = scans.time(i);
    gt[i].T_world_body = Tr_inv * gt[i].T_world_body * Tr;
  }
  return gt;
}

}  // namespace

Pose3 readKittiCalibTr(const fs::path& calib) {
  std::istringstream in(readFile(calib));
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("Tr:", 0) != 0) continue;
    const std::vector<double> v = numbersAfterKey(calib, line);
    if (v.size() != 12)
      throw bad(calib, "Tr: has " + std::to_string(v.size()) + " numbers, not 12 (3x4 row-major)");
    Eigen::Matrix<double, 3, 4> m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) m(r, c) = v[static_cast<std::size_t>(4 * r + c)];
    const Eigen::JacobiSVD<Mat3> svd(m.leftCols<3>(), Eigen::ComputeFullU | Eigen::ComputeFullV);
    if ((svd.singularValues().array() - 1.0).abs().maxCoeff() > 1e-3 ||
        m.leftCols<3>().determinant() < 0)
      throw bad(calib, "Tr: the 3x3 part is not a rotation");
    Pose3 T = Pose3::Identity();
    T.linear() = svd.matrixU() * svd.matrixV().transpose();  // KITTI prints ~9 digits
    T.translation() = m.col(3);
    return T;
  }
  throw bad(calib, "no 'Tr:' line (velodyne -> camera)");
}

KittiSequence readKittiSequence(const fs::path& dir, const LidarSpec& spec) {
  if (!fs::is_directory(dir)) throw bad(dir, "not a folder");
  const fs::path velodyne = dir / kitti_files::kVelodyneDir, times = dir / kitti_files::kTimes;
  if (!fs::is_directory(velodyne)) throw bad(velodyne, "not found (not a KITTI sequence folder?)");
  if (!fs::exists(times)) throw bad(times, "not found");
  KittiSequence seq;
  seq.scans = std::make_unique<KittiScanSource>(velodyne, spec, times);
  checkScanFiles(velodyne, times, seq.scans->size());
  if (fs::exists(dir / kitti_files::kPoses)) seq.ground_truth = lidarGroundTruth(dir, *seq.scans);
  return seq;
}

}  // namespace slamroute
