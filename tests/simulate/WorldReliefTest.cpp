// The road and the ground are not planes: camber, kerbs, swell and roughness (WorldRelief).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "WorldTestNet.hpp"
#include "slamroute/simulate/World.hpp"

namespace slamroute::simulate {
namespace {

double zAt(const World& w, double x, double y) {
  const auto z = w.surfaceZ(x, y, 1.0);
  EXPECT_TRUE(z.has_value()) << "no surface under (" << x << ", " << y << ")";
  return z.value_or(0.0);
}

// Grid street J0_0 -> J1_0 runs along +x on y in [-3.2, 0] (one lane, the crown at y = 0, the
// kerb at y = -3.2, the pavement beyond it); x in [8, 152].
TEST(WorldRelief, RoadFallsTwoPercentFromTheCrownToTheKerb) {
  const SumoNet net = testnet::gridNet(2, 160);
  WorldConfig flat;
  flat.road_camber_pct = 0.0;
  const World w = World::build(net, WorldConfig{}, 5), w0 = World::build(net, flat, 5);
  // the same seed gives the same relief, so the difference of the two worlds is the camber
  double sum = 0;
  int n = 0;
  for (double x = 30; x <= 130; x += 0.5) {
    const double crown = zAt(w, x, -0.05) - zAt(w0, x, -0.05);
    const double kerb = zAt(w, x, -3.15) - zAt(w0, x, -3.15);
    sum += crown - kerb;
    ++n;
  }
  EXPECT_NEAR(sum / n, 0.02 * 3.1, 0.002);
}

TEST(WorldRelief, KerbRisesAboutItsHeightAboveTheRoad) {
  const World w = World::build(testnet::gridNet(2, 160), WorldConfig{}, 5);
  for (double x = 30; x <= 130; x += 10) {
    const double step = zAt(w, x, -3.3) - zAt(w, x, -3.1);
    EXPECT_GT(step, 0.12) << "x = " << x;
    EXPECT_LT(step, 0.19) << "x = " << x;
  }
}

TEST(WorldRelief, RoadHeightVariesAlongTheLaneWithCentimetreRoughness) {
  const World w = World::build(testnet::gridNet(2, 160), WorldConfig{}, 5);
  std::vector<double> z;
  for (double x = 20; x <= 140; x += 0.25) z.push_back(zAt(w, x, -1.6));
  double mean = 0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(z.size());
  double var = 0, rough = 0;
  int n = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    var += (z[i] - mean) * (z[i] - mean);
    if (i < 8 || i + 8 >= z.size()) continue;
    double local = 0;  // 4 m moving average: the swell; what is left is the roughness
    for (std::size_t k = i - 8; k <= i + 8; ++k) local += z[k];
    local /= 17.0;
    rough += (z[i] - local) * (z[i] - local);
    ++n;
  }
  const double sd = std::sqrt(var / static_cast<double>(z.size())), rough_sd = std::sqrt(rough / n);
  EXPECT_GT(sd, 0.01);  // the swell: a few cm over metres
  EXPECT_LT(sd, 0.1);
  EXPECT_GT(rough_sd, 0.002);
  EXPECT_LT(rough_sd, 0.012);
}

TEST(WorldRelief, SameSeedSameBytesOtherSeedOtherRelief) {
  const SumoNet net = testnet::gridNet(2, 160);
  const World a = World::build(net, WorldConfig{}, 9), b = World::build(net, WorldConfig{}, 9);
  const World c = World::build(net, WorldConfig{}, 10);
  const auto& va = a.mesh().vertices;
  ASSERT_EQ(va.size(), b.mesh().vertices.size());
  EXPECT_EQ(std::memcmp(va.data(), b.mesh().vertices.data(), va.size() * sizeof(va[0])), 0);
  EXPECT_NE(zAt(a, 80, -1.6), zAt(c, 80, -1.6));
}

TEST(WorldRelief, RejectsBadReliefSettings) {
  WorldConfig c;
  c.road_camber_pct = -1;
  EXPECT_THROW(World::build(testnet::gridNet(2, 160), c, 1), std::invalid_argument);
  c = WorldConfig{};
  c.ground_cell_m = 0;
  EXPECT_THROW(World::build(testnet::gridNet(2, 160), c, 1), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::simulate
