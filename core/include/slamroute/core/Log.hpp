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

/// Progress on stderr: "label  37% (370/1000) 12.3 s". Prints at most a few times per second,
/// only at level Info or lower. Thread-compatible (call update from one thread).
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
