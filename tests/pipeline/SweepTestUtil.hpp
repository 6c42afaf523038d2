#pragma once
// A small study on the plus test net and reading what `slamroute sweep` wrote, for the sweep's
// end-to-end tests.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli/CliTestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::test {

/// The whole file; empty when it is missing.
inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// A study of one net, two planners, one seed, the SLAM on the first 30 s of each drive: 8 tasks.
inline std::filesystem::path writeSpec(const std::filesystem::path& dir) {
  writeFileAtomic(dir / "fast.yaml", "evaluate:\n  input:\n    scan_stride: 5\n    end_s: 30\n");
  writeFileAtomic(dir / "spec.yaml",
                  "nets: [" + std::string(SLAMROUTE_SOURCE_DIR) +
                      "/networks/test/plus.net.xml]\nplanners: [qlearning, random]\n"
                      "seeds: [3]\nvariants:\n  - {name: fast, config: fast.yaml}\n");
  return dir / "spec.yaml";
}

/// results.csv's rows: every metric but the run's own timings (left out of the file).
inline std::vector<std::string> csvLines(const std::filesystem::path& csv) {
  std::vector<std::string> lines;
  std::istringstream in(readText(csv));
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace slamroute::test
