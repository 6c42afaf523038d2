#include "slamroute/core/Log.hpp"

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <stdexcept>

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
    : label_(std::move(label)),
      total_(total),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

std::string formatDuration(double secs) {
  char buf[32];
  if (!std::isfinite(secs) || secs < 0) return "?";
  const long s = std::lround(secs);
  if (s < 60)
    std::snprintf(buf, sizeof(buf), "%lds", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof(buf), "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof(buf), "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  return buf;
}

std::string progressBar(const std::string& label, std::size_t done, std::size_t total, double secs,
                        int width) {
  const double frac =
      total ? std::min(1.0, static_cast<double>(done) / static_cast<double>(total)) : 1.0;
  const int filled = static_cast<int>(frac * width);
  const double rate = secs > 0 ? static_cast<double>(done) / secs : 0.0;
  const double left = rate > 0 ? static_cast<double>(total - std::min(done, total)) / rate : NAN;
  char buf[160];
  // Three significant digits, never an exponent: "0.25/s", "25/s", "15873/s".
  std::snprintf(
      buf, sizeof(buf),
      rate >= 100 ? "] %5.1f%% %zu/%zu  %.0f/s  %s left" : "] %5.1f%% %zu/%zu  %.3g/s  %s left",
      100.0 * frac, done, total, rate, done ? formatDuration(left).c_str() : "?");
  return label + " [" + std::string(static_cast<std::size_t>(filled), '#') +
         std::string(static_cast<std::size_t>(width - filled), '.') + buf;
}

void Progress::update(std::size_t done) {
  if (g_level.load() > LogLevel::Info) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(500) && done < total_) return;
  last_ = now;
  const double secs = std::chrono::duration<double>(now - start_).count();
  std::lock_guard<std::mutex> lock(g_mutex);
  if (isatty(STDERR_FILENO)) {
    std::cerr << "\r" << progressBar(label_, done, total_, secs, 24) << "\033[K" << std::flush;
  } else {
    const double pct =
        total_ ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0;
    char buf[256];
    std::snprintf(buf, sizeof(buf), "%s %5.1f%% (%zu/%zu) %.1f s", label_.c_str(), pct, done,
                  total_, secs);
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
