// Seeded mutation fuzzing of the config loader (tests/FuzzMutate.hpp): the full default config
// as `config --dump` writes it, mutated, then loaded and validated as --config does.
#include <gtest/gtest.h>

#include "AppConfig.hpp"
#include "Commands.hpp"
#include "FuzzMutate.hpp"
#include "TestTmp.hpp"
#include "slamroute/core/ConfigIO.hpp"

namespace slamroute::cli {
namespace {

TEST(FuzzConfig, YamlConfig) {
  const std::string base = config::dumpYaml(AppConfig{});
  test::fuzzReader(base, test::testTmp() / "m.yaml", 21, 300, [](const auto& p) {
    AppConfig cfg;
    loadConfigFile(p.string(), cfg);
  });
}

}  // namespace
}  // namespace slamroute::cli
