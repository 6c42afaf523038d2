#pragma once
// Helpers shared by the core tests: temp folders and small files.
#include "TestTmp.hpp"
#include <filesystem>
#include <fstream>
#include <string>

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

inline std::string sharedNet(const std::string& which) {
  if (which == "bologna")
    return std::string(SLAMROUTE_SHARED_DIR) + "/networks/bologna_acosta/acosta_buslanes.net.xml";
  return std::string(SLAMROUTE_SHARED_DIR) + "/networks/ingolstadt21/ingolstadt21.net.xml";
}

}  // namespace slamroute::test
