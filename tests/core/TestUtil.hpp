#pragma once
// Helpers shared by the core tests: temp folders and small files.
#include <filesystem>
#include <fstream>
#include <string>
#include "TestTmp.hpp"

namespace slamroute::test {

inline std::filesystem::path tempDir(const std::string& name) {
  const auto dir = slamroute::test::testTmp() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void writeText(const std::filesystem::path& p, const std::string& s) {
  std::ofstream(p, std::ios::binary) << s;
}

}  // namespace slamroute::test
