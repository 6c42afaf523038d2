// The evaluate config: sections load, values that cannot work are refused with the field's name,
// and the flat keys of earlier files name where they live now.
#include <gtest/gtest.h>

#include <string>

#include "slamroute/core/ConfigIO.hpp"
#include "slamroute/evaluate/Config.hpp"

namespace slamroute::evaluate {
namespace {

std::string loadError(const std::string& yaml) {
  Config c;
  try {
    config::loadYaml(YAML::Load(yaml), c, "f.yaml");
    c.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(EvaluateConfig, DefaultsAreValid) { EXPECT_NO_THROW(Config{}.validate()); }

TEST(EvaluateConfig, SectionsLoad) {
  Config c;
  config::loadYaml(
      YAML::Load("odometry: {use_wheel_odometry: false}\nloop: {enabled: false, radius_m: 4}\n"), c,
      "f.yaml");
  EXPECT_FALSE(c.odometry.use_wheel_odometry);
  EXPECT_FALSE(c.loop.enabled);
  EXPECT_EQ(c.loop.radius_m, 4.0);
}

TEST(EvaluateConfig, AMovedKeyNamesItsNewPlace) {
  EXPECT_EQ(loadError("use_odometry: false\n"),
            "f.yaml: key 'use_odometry' is now 'odometry.use_wheel_odometry'");
  EXPECT_NE(loadError("loop_closure: false\n").find("'loop.enabled'"), std::string::npos);
  EXPECT_NE(loadError("map_iterations: 3\n").find("'mapping.iterations'"), std::string::npos);
}

TEST(EvaluateConfig, EveryFlatKeyOfEarlierFilesIsMapped) {
  for (const auto& [old_key, new_key] : movedConfigKeys()) {
    const std::string err = loadError(std::string(old_key) + ": 1\n");
    EXPECT_NE(err.find(new_key), std::string::npos) << old_key << ": " << err;
  }
  EXPECT_EQ(movedConfigKeys().size(), 102u);
}

TEST(EvaluateConfig, ValuesThatCannotWorkAreRefusedByName) {
  EXPECT_EQ(loadError("input: {scan_stride: 0}\n"),
            "f.yaml: input.scan_stride must be in [1, 100] (got 0)");
  EXPECT_NE(loadError("metrics: {plot_size_px: 200000}\n").find("metrics.plot_size_px"),
            std::string::npos);
  EXPECT_NE(loadError("metrics: {assoc_max_dt_s: -1}\n").find("assoc_max_dt_s"), std::string::npos);
  EXPECT_NE(loadError("metrics: {map_accuracy_max_m: 0}\n").find("map_accuracy_max_m"),
            std::string::npos);
  EXPECT_NE(loadError("mapping: {huber_m: .nan}\n").find("mapping.huber_m"), std::string::npos);
  EXPECT_NE(loadError("mapping: {edge_weight: 0}\n").find("mapping.edge_weight"),
            std::string::npos);
  EXPECT_NE(loadError("mapping: {edge_weight: 2}\n").find("mapping.edge_weight"),
            std::string::npos);
  EXPECT_NE(
      loadError("odometry: {slack_since_fix_max_s: -1}\n").find("odometry.slack_since_fix_max_s"),
      std::string::npos);
  EXPECT_NE(loadError("loop: {max_height_gap_m: 0}\n").find("loop.max_height_gap_m"),
            std::string::npos);
  EXPECT_NE(loadError("loop: {ambiguity_along_m: [3, -1]}\n").find("ambiguity_along_m"),
            std::string::npos);
}

TEST(EvaluateConfig, AConfigBuiltInCodeNamesTheSectionOfTheBadValue) {
  EXPECT_EQ(loadError("loop: {place: {sectors: 2}}\n"),
            "f.yaml: loop.place.sectors must be in [4, 3600] (got 2)");
  Config c;
  c.loop.place.sectors = 2;
  try {
    c.validate();
    FAIL() << "sectors 2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "loop.place.sectors must be in [4, 3600] (got 2)");
  }
}

}  // namespace
}  // namespace slamroute::evaluate
