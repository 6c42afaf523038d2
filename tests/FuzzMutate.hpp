#pragma once
// Seeded mutation fuzzing of the file readers: a valid file is mutated a fixed number of times
// (byte flips, insertions, cut ranges, duplicated ranges, swapped lines, numbers replaced by NaN,
// infinity, huge or negative values, a truncated end) and each mutant is read in a child process
// with an alarm per mutant. The reader must either accept it or throw one std::exception whose
// message is one line naming the file: a crash, a hang, another exception or a multi-line
// message fails the test with the seed and the mutant's number to reproduce it.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace slamroute::test {

inline std::string mutate(std::string s, std::mt19937_64& rng) {
  static const char* const kNumbers[] = {
      "nan", "inf", "-inf", "-1", "0", "1e308", "-1e308", "1e400", "18446744073709551616",
      "1e8", "",    "-0"};
  auto pick = [&](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng() % n); };
  const int edits = 1 + static_cast<int>(rng() % 3);
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const std::size_t at = pick(s.size()), len = 1 + pick(std::min<std::size_t>(64, s.size() - at));
    switch (rng() % 7) {
      case 0:
        s[at] = static_cast<char>(rng());
        break;
      case 1:
        s.insert(at, 1, static_cast<char>(rng()));
        break;
      case 2:
        s.erase(at, len);
        break;
      case 3:
        s.insert(at, s.substr(at, len));
        break;
      case 4:
        s.resize(at);
        break;
      case 5: {  // swap two lines
        std::vector<std::string> lines;
        std::size_t from = 0;
        for (std::size_t nl; (nl = s.find('\n', from)) != std::string::npos; from = nl + 1)
          lines.push_back(s.substr(from, nl + 1 - from));
        lines.push_back(s.substr(from));
        std::swap(lines[pick(lines.size())], lines[pick(lines.size())]);
        s.clear();
        for (const auto& l : lines) s += l;
        break;
      }
      default: {  // a number replaced by an extreme one
        std::size_t d = s.find_first_of("0123456789", at);
        if (d == std::string::npos) break;
        std::size_t end = s.find_first_not_of("0123456789.eE+-", d);
        if (end == std::string::npos) end = s.size();
        s.replace(d, end - d, kNumbers[pick(std::size(kNumbers))]);
      }
    }
  }
  return s;
}

/// Outcome of reading one mutant, as the child process reports it (one byte each).
enum : char { kAccepted = 'a', kRejected = 'r', kUnnamed = 'm', kForeign = 'x' };

inline char readOne(const std::filesystem::path& path,
                    const std::function<void(const std::filesystem::path&)>& read) {
  try {
    read(path);
    return kAccepted;
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    const bool named = msg.find(path.filename().string()) != std::string::npos;
    return named && msg.find('\n') == std::string::npos ? kRejected : kUnnamed;
  } catch (...) {
    return kForeign;
  }
}

/// Writes `count` mutants of `base` to `path` in turn and runs `read(path)` on each, all in one
/// child process that reports each outcome through a pipe; an alarm of `limit_s` seconds per
/// mutant turns a hang into a signal. A signal names the mutant by the outcomes before it.
inline void fuzzReader(const std::string& base, const std::filesystem::path& path,
                       std::uint64_t seed, int count,
                       const std::function<void(const std::filesystem::path&)>& read,
                       unsigned limit_s = 10) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    std::mt19937_64 rng(seed);
    for (int i = 0; i < count; ++i) {
      std::ofstream(path, std::ios::binary | std::ios::trunc) << mutate(base, rng);
      ::alarm(limit_s);
      const char outcome = readOne(path, read);
      if (::write(fds[1], &outcome, 1) != 1) ::_exit(4);
    }
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string outcomes;
  char buf[256];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;)
    outcomes.append(buf, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  const std::string where = "seed " + std::to_string(seed) + ", mutant ";
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << where << outcomes.size() << ": killed by signal "
      << (WIFSIGNALED(status) ? WTERMSIG(status) : 0)
      << (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM ? " (hang)" : "");
  ASSERT_EQ(outcomes.size(), static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < outcomes.size(); ++i)
    ASSERT_TRUE(outcomes[i] == kAccepted || outcomes[i] == kRejected)
        << where << i
        << (outcomes[i] == kUnnamed ? ": error message is not one line naming the file"
                                    : ": not a std::exception");
  // Some mutants keep the file valid (a changed digit): the reader is really exercised both ways.
  const auto accepted = std::count(outcomes.begin(), outcomes.end(), kAccepted);
  EXPECT_GT(accepted, 0);
  EXPECT_LT(accepted, count);
}

}  // namespace slamroute::test
