// per_edge.csv read back as written; files from before the along-street column; bad cells.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {
namespace {
namespace fs = std::filesystem;

fs::path tempFile(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "slamroute_per_edge_csv";
  fs::create_directories(dir);
  return dir / name;
}

TEST(PerEdgeCsv, ReadsBackWhatItWrote) {
  EdgeError a{.edge = "R0C0_R0C1",
              .poses = 120,
              .visits = 2,
              .length_m = 410.5,
              .ate_mean_m = 0.12,
              .ate_max_m = 0.31,
              .drift_pct = 0.52,
              .window_drift_pct = 0.137,
              .rot_deg_per_m = 0.004};
  EdgeError b{.edge = "-R0C1_R1C1",
              .poses = 3,
              .visits = 1,
              .length_m = 4.25,
              .ate_mean_m = 0.05,
              .ate_max_m = 0.06,
              .drift_pct = std::nan(""),
              .window_drift_pct = std::nan(""),
              .rot_deg_per_m = 0.0};
  const fs::path p = tempFile("round_trip.csv");
  writePerEdgeCsv(p, {a, b});
  const auto rows = readPerEdgeCsv(p);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].edge, "R0C0_R0C1");
  EXPECT_EQ(rows[0].poses, 120);
  EXPECT_EQ(rows[0].visits, 2);
  EXPECT_DOUBLE_EQ(rows[0].length_m, 410.5);
  EXPECT_DOUBLE_EQ(rows[0].ate_mean_m, 0.12);
  EXPECT_DOUBLE_EQ(rows[0].ate_max_m, 0.31);
  EXPECT_DOUBLE_EQ(rows[0].drift_pct, 0.52);
  EXPECT_DOUBLE_EQ(rows[0].rot_deg_per_m, 0.004);
  EXPECT_DOUBLE_EQ(rows[0].window_drift_pct, 0.137);
  EXPECT_EQ(rows[1].edge, "-R0C1_R1C1");
  EXPECT_TRUE(std::isnan(rows[1].drift_pct));  // a piece too short for a figure
  EXPECT_TRUE(std::isnan(rows[1].window_drift_pct));
}

TEST(PerEdgeCsv, AFileFromBeforeTheAlongStreetColumnHasNoAlongFigure) {
  const fs::path p = tempFile("eight_columns.csv");
  std::ofstream(p) << "sumo_edge,poses,visits,length_m,ate_mean_m,ate_max_m,drift_pct,"
                      "rot_deg_per_m\nE1,50,1,200,0.1,0.2,0.75,0.01\n";
  const auto rows = readPerEdgeCsv(p);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_DOUBLE_EQ(rows[0].drift_pct, 0.75);
  EXPECT_TRUE(std::isnan(rows[0].window_drift_pct));
}

/// What reading `rows` (under the header) throws, or "" when it reads.
std::string readError(const fs::path& p, const std::string& rows) {
  std::ofstream(p) << "sumo_edge,poses,visits,length_m,ate_mean_m,ate_max_m,drift_pct,"
                      "rot_deg_per_m,window_drift_pct\n"
                   << rows;
  try {
    readPerEdgeCsv(p);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(PerEdgeCsv, ABadCellNamesTheFileAndLine) {
  const fs::path p = tempFile("bad.csv");
  EXPECT_EQ(readError(p, "E1,50,1,200,0.1,0.2,0.75,0.01,0.3\nE2,50,1,2x0,0.1,0.2,0.75,0.01,0.3\n"),
            p.string() + ":3: bad number '2x0'");
  EXPECT_EQ(readError(p, "E1,12.5,1,200,0.1,0.2,0.75,0.01,0.3\n"),
            p.string() + ":2: bad count '12.5'");
  EXPECT_EQ(readError(p, "E1,50,1,200,0.1,0.2,0.75,0.01,0.3\n"), "");
  std::ofstream(p) << "edge,drift\nE1,0.5\n";
  EXPECT_THROW(readPerEdgeCsv(p), std::runtime_error);
}

}  // namespace
}  // namespace slamroute::evaluate
