// `slamroute evaluate --kitti SEQ_DIR`: a short drive's saved scans laid out as a KITTI odometry
// sequence (velodyne/, times.txt, poses.txt in a camera frame, calib.txt's Tr) give the same
// result as `evaluate --drive` on the drive itself without its wheel odometry; without poses.txt
// the metrics are skipped; bad sequences fail with one line naming the file.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Trajectory.hpp"

namespace slamroute {
namespace {
namespace fs = std::filesystem;

const std::string kGrid = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/grid3x3.net.xml";

/// A velodyne -> camera transform like KITTI's (camera z forward, x right, y down) with an
/// offset, so that the ground truth must really be brought into the LiDAR frame.
Pose3 cameraFromVelodyne() {
  Pose3 T = Pose3::Identity();
  T.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  T.linear() =
      T.linear() * Eigen::AngleAxisd(0.02, Vec3(0.3, 0.5, 0.8).normalized()).toRotationMatrix();
  T.translation() = Vec3(-0.004, -0.076, -0.27);
  return T;
}

std::string row12(const Pose3& T) {
  std::string s;
  char buf[40];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      std::snprintf(buf, sizeof buf, "%.17g", T.matrix()(r, c));
      s += (s.empty() ? "" : " ") + std::string(buf);
    }
  return s;
}

/// DIR/seq: the drive's scans and times, its ground truth as camera poses and the calibration.
void writeKittiSequence(const fs::path& drive, const fs::path& seq) {
  fs::create_directories(seq / "velodyne");
  for (const auto& e : fs::directory_iterator(drive / "scans"))
    if (e.path().filename() != "times.txt")
      fs::copy_file(e.path(), seq / "velodyne" / e.path().filename());
  fs::copy_file(drive / "scans/times.txt", seq / "times.txt");
  const Pose3 Tr = cameraFromVelodyne();
  std::string poses;
  for (const auto& p : readTum(drive / "groundtruth.tum"))
    poses += row12(Tr * p.T_world_body * Tr.inverse()) + "\n";
  std::ofstream(seq / "poses.txt") << poses;
  std::ofstream(seq / "calib.txt") << "P0: 7.1e+02 0 6.0e+02 0 0 7.1e+02 1.8e+02 0 0 0 1 0\n"
                                   << "Tr: " << row12(Tr) << "\n";
}

nlohmann::json metrics(const fs::path& eval) {
  return nlohmann::json::parse(std::ifstream(eval / "metrics.json"));
}

TEST(KittiCli, ASequenceFromADriveGivesTheDrivesResult) {
  const auto dir = test::cliTempDir("kitti_sequence");
  std::ofstream(dir / "route.json") << R"(["g00_g01"])";
  const auto d = test::runCli("--seed 3 drive --net " + kGrid + " --route " +
                              (dir / "route.json").string() + " --out " + (dir / "drive").string() +
                              " --save-scans --sensor vlp16 --no-mesh --log-level warn");
  ASSERT_EQ(d.code, 0) << d.out;
  writeKittiSequence(dir / "drive", dir / "seq");
  std::ofstream(dir / "lidar_only.yaml")
      << "evaluate:\n  odometry:\n    use_wheel_odometry: false\n";
  // A few seconds of the drive.
  const double t0 = readTum(dir / "drive/groundtruth.tum").front().t;
  const std::string common = "--log-level warn --config " + (dir / "lidar_only.yaml").string() +
                             " evaluate --to " + std::to_string(t0 + 4.0) + " ";
  const auto by_drive = test::runCli(common + "--drive " + (dir / "drive").string() + " --out " +
                                     (dir / "eval_drive").string());
  ASSERT_EQ(by_drive.code, 0) << by_drive.out;
  const auto by_kitti = test::runCli(common + "--kitti " + (dir / "seq").string() +
                                     " --sensor vlp16 --out " + (dir / "eval_kitti").string());
  ASSERT_EQ(by_kitti.code, 0) << by_kitti.out;

  const auto a = metrics(dir / "eval_drive"), b = metrics(dir / "eval_kitti");
  EXPECT_EQ(b["motion_prior"], "constant velocity");
  EXPECT_EQ(a["scans"], b["scans"]);
  EXPECT_GT(b["scans"].get<int>(), 15);
  EXPECT_GT(b["evaluated_length_m"].get<double>(), 40.0);
  EXPECT_NEAR(a["ate_rmse_m"].get<double>(), b["ate_rmse_m"].get<double>(), 1e-6);
  EXPECT_NEAR(a["ate_max_m"].get<double>(), b["ate_max_m"].get<double>(), 1e-6);
  EXPECT_NEAR(a["evaluated_length_m"].get<double>(), b["evaluated_length_m"].get<double>(), 1e-6);
  // Both estimates are in the drive's world frame: Tr^-1 (Tr T Tr^-1) Tr = T.
  const Trajectory ea = readTum(dir / "eval_drive/estimate.tum"),
                   eb = readTum(dir / "eval_kitti/estimate.tum");
  ASSERT_EQ(ea.size(), eb.size());
  EXPECT_LT((ea.back().T_world_body.translation() - eb.back().T_world_body.translation()).norm(),
            1e-5);

  fs::remove(dir / "seq/poses.txt");  // no ground truth: the SLAM runs, the metrics are skipped
  const auto blind = test::runCli(common + "--kitti " + (dir / "seq").string() +
                                  " --sensor vlp16 --out " + (dir / "eval_blind").string());
  ASSERT_EQ(blind.code, 0) << blind.out;
  EXPECT_NE(blind.out.find("no ground truth: trajectory metrics skipped"), std::string::npos)
      << blind.out;
  const auto c = metrics(dir / "eval_blind");
  EXPECT_EQ(c["trajectory_metrics"], "skipped: no ground truth");
  EXPECT_FALSE(c.contains("ate_rmse_m"));
  EXPECT_EQ(c["scans"], b["scans"]);
  const Trajectory ec = readTum(dir / "eval_blind/estimate.tum");
  ASSERT_FALSE(ec.empty());
  EXPECT_TRUE(ec.front().T_world_body.isApprox(Pose3::Identity()));
}

/// A two-scan sequence with ground truth (no SLAM is run on it: every case fails first).
fs::path tinySequence(const fs::path& dir) {
  const fs::path seq = dir / "seq";
  fs::create_directories(seq / "velodyne");
  const std::string point(16, '\0');
  for (const char* f : {"000000.bin", "000001.bin"}) std::ofstream(seq / "velodyne" / f) << point;
  std::ofstream(seq / "times.txt") << "0.0\n0.1\n";
  std::ofstream(seq / "poses.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 1\n";
  std::ofstream(seq / "calib.txt") << "Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  return seq;
}

void expectOneLineError(const fs::path& dir, const std::string& fragment) {
  const auto r = test::runCli("evaluate --kitti " + (dir / "seq").string() + " --out " +
                              (dir / "eval").string());
  EXPECT_NE(r.code, 0) << r.out;
  EXPECT_EQ(test::countLines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("slamroute: error: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(fragment), std::string::npos)
      << "expected '" << fragment << "' in " << r.out;
  EXPECT_FALSE(fs::exists(dir / "eval"));
}

TEST(KittiCli, ABadSequenceFailsWithOneLineNamingTheFile) {
  const auto dir = test::cliTempDir("kitti_bad");
  const fs::path seq = tinySequence(dir);
  std::ofstream(seq / "calib.txt") << "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  expectOneLineError(dir, "calib.txt: no 'Tr:' line");
  std::ofstream(seq / "calib.txt") << "Tr: 1 0 0 0 0 1 0 0 0 0 1\n";
  expectOneLineError(dir, "calib.txt: Tr: has 11 numbers, not 12");
  std::ofstream(seq / "calib.txt") << "Tr: 2 0 0 0 0 1 0 0 0 0 1 0\n";
  expectOneLineError(dir, "calib.txt: Tr: the 3x3 part is not a rotation");
  fs::remove(seq / "calib.txt");
  expectOneLineError(dir, "calib.txt: not found");
  std::ofstream(seq / "calib.txt") << "Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  std::ofstream(seq / "poses.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n";
  expectOneLineError(dir, "poses.txt: 1 poses for 2 scans in times.txt");
  fs::remove(seq / "velodyne/000001.bin");
  expectOneLineError(dir, "velodyne: 1 scans (.bin) for 2 times in");
  std::ofstream(seq / "velodyne/000002.bin") << std::string(16, '\0');
  expectOneLineError(dir, "velodyne/000001.bin: missing");
  fs::remove(seq / "times.txt");
  expectOneLineError(dir, "times.txt: not found");
  fs::remove_all(seq / "velodyne");
  expectOneLineError(dir, "velodyne: not found (not a KITTI sequence folder?)");
  const auto both = test::runCli("evaluate --kitti " + seq.string() + " --drive " + seq.string() +
                                 " --out " + (dir / "eval").string());
  EXPECT_NE(both.code, 0) << both.out;
  const auto neither = test::runCli("evaluate --out " + (dir / "eval").string());
  EXPECT_NE(neither.code, 0);
  EXPECT_NE(neither.out.find("evaluate needs --drive DIR or --kitti SEQ_DIR"), std::string::npos)
      << neither.out;
}

}  // namespace
}  // namespace slamroute
