#pragma once
// Runs the slamroute binary in a shell and captures its output and exit code.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include "TestTmp.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace slamroute::test {

struct CliResult {
  int code = -1;
  std::string out;  ///< stdout and stderr interleaved
};

/// Runs a shell command line with stderr joined to stdout.
inline CliResult runCommand(const std::string& command) {
  const std::string cmd = command + " 2>&1";
  CliResult r;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline CliResult runCli(const std::string& args) {
  return runCommand(std::string(SLAMROUTE_BINARY) + " " + args);
}

inline std::filesystem::path cliTempDir(const std::string& name) {
  const auto dir = slamroute::test::testTmp() / ("cli_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// How often `what` occurs in `text` (overlaps counted).
inline int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

inline int countLines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

/// The command fails with one line naming `fragment`, and `dir` holds nothing but `keep` entries.
inline void expectCleanFailure(const std::string& args, const std::string& fragment,
                               const std::filesystem::path& dir, std::size_t keep) {
  const auto r = runCli(args);
  EXPECT_NE(r.code, 0) << args << "\n" << r.out;
  EXPECT_EQ(countLines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("slamroute: error: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(fragment), std::string::npos) << r.out;
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  EXPECT_EQ(n, keep) << "something was written for: " << args;
}

/// Polls `done` every 20 ms for at most `max_s` seconds (a bound against a hang, not a speed
/// figure); false when it never came true.
template <class F>
bool waitFor(F done, int max_s = 60) {
  for (int i = 0; i < max_s * 50; ++i) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

/// Gone or a zombie (whoever adopted an orphan may not reap it at once).
inline bool processDead(long pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;
  const auto close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z';
}

}  // namespace slamroute::test
