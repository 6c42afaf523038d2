// Reading earlier steps' JSON files: a missing file is "not run", a broken one an error.
#include <gtest/gtest.h>

#include "TestTmp.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/pipeline/JsonFile.hpp"

namespace slamroute::pipeline {
namespace {

TEST(JsonFile, MissingIsEmptyBrokenIsAnErrorNamingTheFile) {
  const auto dir = test::testTmp();
  EXPECT_TRUE(readJsonIfPresent(dir / "missing.json").empty());
  writeFileAtomic(dir / "ok.json", R"({"ate_rmse_m": 0.25})");
  EXPECT_DOUBLE_EQ(readJsonIfPresent(dir / "ok.json")["ate_rmse_m"].get<double>(), 0.25);
  writeFileAtomic(dir / "broken.json", R"({"ate_rmse_m": )");
  try {
    readJsonIfPresent(dir / "broken.json");
    FAIL() << "a broken file must be an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json: not valid JSON"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace slamroute::pipeline
