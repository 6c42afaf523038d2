// TUM and KITTI trajectory files.
#include "slamroute/core/Trajectory.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Coordinates.hpp"

namespace slamroute {
namespace {

std::vector<std::vector<double>> readRows(const std::filesystem::path& path) {
  std::istringstream in(readFile(path));
  std::vector<std::vector<double>> rows;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream ls(line);
    std::vector<double> row;
    std::string tok;
    while (ls >> tok) {
      try {
        std::size_t used = 0;
        row.push_back(std::stod(tok, &used));
        if (used != tok.size()) throw std::invalid_argument(tok);
      } catch (const std::exception&) {
        throw std::invalid_argument(path.string() + ":" + std::to_string(lineno) +
                                    ": not a number '" + tok + "'");
      }
      if (!std::isfinite(row.back()))
        throw std::invalid_argument(path.string() + ":" + std::to_string(lineno) +
                                    ": non-finite value");
    }
    rows.push_back(std::move(row));
    rows.back().push_back(lineno);  // remember the line number as the last entry
  }
  if (rows.empty()) throw std::invalid_argument(path.string() + ": no poses in the file");
  return rows;
}

std::string lineOf(const std::filesystem::path& path, const std::vector<double>& row) {
  return path.string() + ":" + std::to_string(static_cast<int>(row.back()));
}

/// A pose file's time must increase (association by time and distance along the path assume
/// it) and its positions be places on Earth (squared 1e300 metres are inf).
void checkPose(const std::filesystem::path& path, const std::vector<double>& row,
               const Trajectory& before, const StampedPose& p) {
  if (!before.empty() && !(p.t > before.back().t))
    throw std::invalid_argument(
        lineOf(path, row) + ": time " + std::to_string(p.t) +
        " s is not later than the pose before (poses must be in time order)");
  const Vec3 t = p.T_world_body.translation();
  if (!plausibleCoordinate(t.x()) || !plausibleCoordinate(t.y()) || !plausibleCoordinate(t.z()))
    throw std::invalid_argument(lineOf(path, row) + ": " + kCoordinateRule);
}

}  // namespace

double pathLength(const Trajectory& traj) {
  double m = 0.0;
  for (std::size_t i = 1; i < traj.size(); ++i)
    m += (traj[i].T_world_body.translation() - traj[i - 1].T_world_body.translation()).norm();
  return m;
}

Trajectory readTum(const std::filesystem::path& path) {
  Trajectory traj;
  for (const auto& r : readRows(path)) {
    if (r.size() != 9)
      throw std::invalid_argument(path.string() + ":" + std::to_string(static_cast<int>(r.back())) +
                                  ": TUM needs 8 columns (t tx ty tz qx qy qz qw)");
    Eigen::Quaterniond q(r[7], r[4], r[5], r[6]);
    if (q.norm() < 1e-9)
      throw std::invalid_argument(path.string() + ":" + std::to_string(static_cast<int>(r.back())) +
                                  ": zero quaternion");
    StampedPose p;
    p.t = r[0];
    p.T_world_body = Pose3::Identity();
    p.T_world_body.linear() = q.normalized().toRotationMatrix();
    p.T_world_body.translation() = Vec3(r[1], r[2], r[3]);
    checkPose(path, r, traj, p);
    traj.push_back(p);
  }
  return traj;
}

void writeTum(const std::filesystem::path& path, const Trajectory& traj) {
  std::ostringstream os;
  os << "# timestamp tx ty tz qx qy qz qw\n" << std::fixed;
  for (const auto& p : traj) {
    const Eigen::Quaterniond q(p.T_world_body.rotation());
    const Vec3 t = p.T_world_body.translation();
    os << std::setprecision(6) << p.t << " " << std::setprecision(6) << t.x() << " " << t.y() << " "
       << t.z() << " " << std::setprecision(9) << q.x() << " " << q.y() << " " << q.z() << " "
       << q.w() << "\n";
  }
  writeFileAtomic(path, os.str());
}

Trajectory readKittiPoses(const std::filesystem::path& path, double dt) {
  Trajectory traj;
  std::size_t i = 0;
  for (const auto& r : readRows(path)) {
    if (r.size() != 13)
      throw std::invalid_argument(path.string() + ":" + std::to_string(static_cast<int>(r.back())) +
                                  ": KITTI poses need 12 columns (3x4 row-major)");
    StampedPose p;
    p.t = static_cast<double>(i++) * dt;
    Eigen::Matrix3d R;
    R << r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10];
    // Written with a few digits, a rotation is orthonormal to ~1e-6; a zero or scaled matrix
    // is no rotation, whatever the re-orthonormalisation below would make of it.
    if (!((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-2) ||
        !(R.determinant() > 0))
      throw std::invalid_argument(lineOf(path, r) + ": the 3x3 part is not a rotation matrix");
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d Ro = svd.matrixU() * svd.matrixV().transpose();  // re-orthonormalise
    p.T_world_body = Pose3::Identity();
    p.T_world_body.linear() = Ro;
    p.T_world_body.translation() = Vec3(r[3], r[7], r[11]);
    checkPose(path, r, traj, p);
    traj.push_back(p);
  }
  return traj;
}

void writeKittiPoses(const std::filesystem::path& path, const Trajectory& traj) {
  std::ostringstream os;
  os << std::setprecision(9);
  for (const auto& p : traj) {
    const Eigen::Matrix<double, 3, 4> m = p.T_world_body.matrix().topRows<3>();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) os << m(r, c) << ((r == 2 && c == 3) ? "\n" : " ");
  }
  writeFileAtomic(path, os.str());
}

Trajectory readTrajectory(const std::filesystem::path& path) {
  const auto rows = readRows(path);
  const std::size_t cols = rows.front().size() - 1;
  if (cols == 8) return readTum(path);
  if (cols == 12) return readKittiPoses(path);
  throw std::invalid_argument(path.string() +
                              ": neither TUM (8 columns) nor KITTI (12 columns), found " +
                              std::to_string(cols));
}

}  // namespace slamroute
