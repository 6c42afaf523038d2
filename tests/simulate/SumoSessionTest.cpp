// SumoSession: open / step / close, one session per process. Each TEST starts at most one SUMO
// session (ctest runs every TEST in its own process; libsumo holds one simulation per process).
#include <gtest/gtest.h>

#include <filesystem>

#include "slamroute/simulate/SumoSession.hpp"

namespace {
using slamroute::simulate::SumoSession;
using slamroute::simulate::SumoSessionOptions;

SumoSessionOptions gridOptions() {
  SumoSessionOptions o;
  o.net = std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks/test/grid3x3.net.xml";
  o.seed = 7;
  return o;
}

TEST(SumoSession, OpensStepsAndCloses) {
  SumoSession s(gridOptions());
  EXPECT_TRUE(s.isOpen());
  EXPECT_TRUE(SumoSession::anyOpen());
  EXPECT_DOUBLE_EQ(s.time(), 0.0);
  for (int i = 0; i < 10; ++i) s.step();
  EXPECT_NEAR(s.time(), 1.0, 1e-9);  // 10 steps of 0.1 s
  s.close();
  EXPECT_FALSE(s.isOpen());
  EXPECT_FALSE(SumoSession::anyOpen());
  EXPECT_THROW(s.step(), std::runtime_error);
  s.close();  // idempotent
}

TEST(SumoSession, SecondSessionInTheSameProcessThrows) {
  SumoSession first(gridOptions());
  try {
    SumoSession second(gridOptions());
    FAIL() << "a second session opened";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("already open"), std::string::npos) << e.what();
  }
  // The first session is unaffected.
  first.step();
  EXPECT_NEAR(first.time(), 0.1, 1e-9);
}

TEST(SumoSession, MissingNetThrowsNamingTheFile) {
  SumoSessionOptions o;
  o.net = "/nonexistent/city.net.xml";
  try {
    SumoSession s(o);
    FAIL() << "opened a missing net";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/city.net.xml"), std::string::npos);
  }
  EXPECT_FALSE(SumoSession::anyOpen());
}

TEST(SumoSession, SumoErrorsBecomeRuntimeErrorsNamingTheNet) {
  SumoSession s(gridOptions());
  try {
    s.guard("query", [] { throw std::logic_error("boom"); });
    FAIL();
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("grid3x3.net.xml"), std::string::npos) << msg;
    EXPECT_NE(msg.find("boom"), std::string::npos) << msg;
  }
}

}  // namespace
