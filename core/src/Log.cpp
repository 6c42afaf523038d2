#include "slamroute/core/Log.hpp"

#include <atomic>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <stdexcept>
#include <unistd.h>

namespace slamroute {
namespace {
std::atomic<LogLevel> g_level{LogLevel::Info};
std::mutex g_mutex;

void emit(LogLevel level, const char* tag, const std::string& msg) {
  if (level < g_level.load()) return;
  std::lock_guard<std::mutex> lock(g_mutex);
  std::cerr << tag << msg << "\n";
}
}  // namespace

void setLogLevel(LogLevel level) { g_level = level; }
LogLevel logLevel() { return g_level.load(); }

LogLevel parseLogLevel(const std::string& name) {
  if (name == "debug") return LogLevel::Debug;
  if (name == "info") return LogLevel::Info;
  if (name == "warn") return LogLevel::Warn;
  if (name == "error") return LogLevel::Error;
  if (name == "quiet") return LogLevel::Quiet;
  throw std::invalid_argument("unknown log level '" + name + "' (debug|info|warn|error|quiet)");
}

void logDebug(const std::string& msg) { emit(LogLevel::Debug, "[debug] ", msg); }
void logInfo(const std::string& msg) { emit(LogLevel::Info, "", msg); }
void logWarn(const std::string& msg) { emit(LogLevel::Warn, "warning: ", msg); }
void logError(const std::string& msg) { emit(LogLevel::Error, "error: ", msg); }

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void Progress::update(std::size_t done) {
  if (g_level.load() > LogLevel::Info) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(500) && done < total_) return;
  last_ = now;
  const double secs = std::chrono::duration<double>(now - start_).count();
  const double pct = total_ ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0;
  std::lock_guard<std::mutex> lock(g_mutex);
  const bool tty = isatty(STDERR_FILENO);
  char buf[256];
  std::snprintf(buf, sizeof(buf), "%s %5.1f%% (%zu/%zu) %.1f s", label_.c_str(), pct, done, total_,
                secs);
  if (tty) {
    std::cerr << "\r" << buf << std::flush;
  } else {
    std::cerr << buf << "\n";
  }
  printed_ = true;
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (g_level.load() > LogLevel::Info) return;
  const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::lock_guard<std::mutex> lock(g_mutex);
  const bool tty = isatty(STDERR_FILENO);
  char buf[256];
  std::snprintf(buf, sizeof(buf), "%s done (%zu) in %.1f s", label_.c_str(), total_, secs);
  std::cerr << (tty && printed_ ? "\r" : "") << buf << (tty ? "\033[K" : "") << "\n";
}

Progress::~Progress() {
  // A Progress destroyed by an exception leaves its line as it was; finish() prints the summary.
  if (!finished_ && printed_ && isatty(STDERR_FILENO)) std::cerr << "\n";
}

}  // namespace slamroute
