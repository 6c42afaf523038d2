// Drive under the default city's overpass with --save-scans: the scans stacked with the ground
// truth form a crisp map (every point on a world surface), the overpass is a deck above the
// street, saved scans equal regenerated ones. Writes build/test_tmp/<this
// test>/drive_map_overpass.png.
#include <gtest/gtest.h>
#include "DriveTestUtil.hpp"
#include "TestTmp.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "slamroute/core/DriveFolder.hpp"
#include "slamroute/simulate/Drive.hpp"
#include "slamroute/simulate/SimulatedScanSource.hpp"

namespace {
namespace fs = std::filesystem;
using namespace slamroute;

TEST(DriveMap, StackedScansUnderTheOverpassAreCrispAndShowTheDeck) {
  const fs::path dir = slamroute::test::testTmp() / "drive_map";
  const fs::path route = slamroute::test::testTmp() / "drive_map_route.json";
  // Avenue C2 northwards from R1 to R3, under the R2 overpass (networks/README.md).
  std::ofstream(route) << R"({"sumo_edges":["R1C2_R3C2"]})";
  const simulate::Config cfg = test::vlp16Config();
  simulate::DriveOptions o = test::testDrive("default_city/default_city.net.xml", route, dir, 11);
  o.save_scans = true;
  const simulate::DriveResult r = simulate::runDrive(o, cfg);
  ASSERT_GT(r.groundtruth.size(), 50u);

  const simulate::SimulatedScanSource sim(dir);
  const KittiScanSource saved(dir / drive_files::kScanDir, sim.spec());
  ASSERT_EQ(saved.size(), sim.size());
  ASSERT_EQ(sim.groundtruth().size(), sim.size());
  {  // saved == regenerated
    const Scan a = saved.scan(20), b = sim.scan(20);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t k = 0; k < a.points.size(); ++k) {
      ASSERT_EQ(a.points[k].x, b.points[k].x);
      ASSERT_EQ(a.points[k].z, b.points[k].z);
    }
  }

  // Every stacked point lies on a world surface (range noise 2 cm): cast the ray again from
  // where it fired.
  const Point3 crossing(430.1, 452.1, 0.0);
  std::size_t checked = 0, on_surface = 0, street = 0, deck = 0;
  for (std::size_t i = 0; i < saved.size(); i += 5) {
    const Scan s = saved.scan(i);
    ASSERT_TRUE(s.has_point_times);
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      // the sensor's pose when the point fired (the sweep is distorted by the motion)
      const Pose3 T = simulate::poseAtTime(sim.groundtruth(), i, s.t + s.points[k].dt);
      const Point3 p = T * Point3(s.points[k].x, s.points[k].y, s.points[k].z);
      if ((p - crossing).head<2>().norm() < 4.0) {
        if (std::abs(p.z()) < 0.3) ++street;
        if (p.z() > 4.5 && p.z() < 8.0) ++deck;
      }
      if (k % 37 != 0) continue;
      const Vec3 d = p - T.translation();
      const auto hit = sim.world().castRay(T.translation(), d, d.norm() + 1.0, sim.traffic()[i]);
      ++checked;
      if (hit.hit && std::abs(hit.range_m - d.norm()) < 0.1) ++on_surface;
    }
  }
  ASSERT_GT(checked, 1000u);
  EXPECT_GT(static_cast<double>(on_surface) / checked, 0.99) << on_surface << "/" << checked;
  EXPECT_GT(street, 50u);  // the street at z = 0 under the crossing
  EXPECT_GT(deck, 50u);    // the deck (6.5 m road, 1 m thick) above it

  simulate::MapPngOptions mo;
  mo.metres_per_pixel = 0.25;
  mo.stride = 2;
  const fs::path png = slamroute::test::testTmp() / "drive_map_overpass.png";
  EXPECT_GT(simulate::renderStackedScansPng(saved, sim.groundtruth(), png, mo), 100000u);
  EXPECT_GT(fs::file_size(png), 10000u);
  fs::remove_all(dir / drive_files::kScanDir);  // ~100 MB; keep the rest for a look
}

}  // namespace
