#pragma once
// Minimal levelled logging to stderr and a progress indicator for long work.
#include <chrono>
#include <cstddef>
#include <string>

namespace slamroute {

enum class LogLevel { Debug = 0, Info = 1, Warn = 2, Error = 3, Quiet = 4 };

void setLogLevel(LogLevel level);
LogLevel logLevel();
/// Parses "debug|info|warn|error|quiet"; throws std::invalid_argument otherwise.
LogLevel parseLogLevel(const std::string& name);

void logDebug(const std::string& msg);
void logInfo(const std::string& msg);
void logWarn(const std::string& msg);
void logError(const std::string& msg);

/// Progress on stderr, at most twice a second, only at level Info or lower. On a terminal one
/// line redrawn in place: "label [#########...............]  37.0% 370/1000  30.1/s  21s left";
/// otherwise (a log file) one line per update: "label  37.0% (370/1000) 12.3 s".
/// Thread-compatible (call update from one thread).
/// The terminal line of Progress: bar of `width` characters, share, count, rate and the time
/// left at that rate ("?" before the first step is done).
std::string progressBar(const std::string& label, std::size_t done, std::size_t total,
                        double elapsed_s, int width);
/// 42s, 3m07s, 2h05m ("?" when not finite or negative).
std::string formatDuration(double secs);

class Progress {
 public:
  Progress(std::string label, std::size_t total);
  void update(std::size_t done);
  void finish();
  ~Progress();

 private:
  std::string label_;
  std::size_t total_;
  std::chrono::steady_clock::time_point start_, last_;
  bool finished_ = false;
  bool printed_ = false;
};

}  // namespace slamroute
