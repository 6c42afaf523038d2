#pragma once
// Scratch folders for tests. ctest runs every test in its own process, two at a time
// (-j2), so two tests of one suite may run at once: each test writes only below its own
// folder, build/test_tmp/<Suite>.<Test>/, which it clears when it first asks for it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace slamroute::test {

// build/test_tmp/<Suite>.<Test>/ (created, emptied on the first call of the test run).
inline std::filesystem::path testTmp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string leaf = info ? std::string(info->test_suite_name()) + "." + info->name()
                          : std::string("outside_a_test");
  for (char& c : leaf)
    if (c == '/') c = '_';  // parameterised tests are named Suite/Name
  const auto dir = std::filesystem::path(SLAMROUTE_TEST_TMP_ROOT) / leaf;
  static std::filesystem::path cleared;
  if (cleared != dir) {
    std::filesystem::remove_all(dir);
    cleared = dir;
  }
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace slamroute::test
