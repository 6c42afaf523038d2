#include "slamroute/core/StagingDir.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

#include <stdexcept>

namespace slamroute {
namespace fs = std::filesystem;
namespace {

void checkReplaceable(const fs::path& target, const std::string& marker) {
  std::error_code ec;
  if (!fs::exists(target, ec)) return;
  if (!fs::is_directory(target, ec))
    throw std::runtime_error(target.string() + ": exists and is not a folder");
  if (fs::is_empty(target, ec) || fs::exists(target / marker, ec)) return;
  throw std::runtime_error(target.string() + ": folder exists and does not hold a previous " +
                           marker + "; refusing to overwrite it");
}

/// Removes `.NAME.tmp.PID` folders beside `target` left by a process that is gone (killed by a
/// signal or the OOM killer, it could not remove its own): they are never moved into place.
void removeStaleStaging(const fs::path& target) {
  const std::string prefix = "." + target.filename().string() + ".tmp.";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || !e.is_directory(ec)) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::strtol(digits.c_str(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH) fs::remove_all(e.path(), ec);
  }
}

}  // namespace

StagingDir::StagingDir(fs::path target, const std::string& marker)
    : target_(std::move(target)), marker_(marker) {
  if (target_.empty()) throw std::invalid_argument("output folder: empty path");
  target_ = fs::absolute(target_).lexically_normal();
  if (target_.filename().empty()) target_ = target_.parent_path();
  checkReplaceable(target_, marker_);
  std::error_code ec;
  fs::create_directories(target_.parent_path(), ec);
  if (ec)
    throw std::runtime_error(target_.parent_path().string() + ": cannot create folder (" +
                             ec.message() + ")");
  removeStaleStaging(target_);
  tmp_ = target_.parent_path() /
         ("." + target_.filename().string() + ".tmp." + std::to_string(::getpid()));
  fs::remove_all(tmp_, ec);
  fs::create_directories(tmp_, ec);
  if (ec) throw std::runtime_error(tmp_.string() + ": cannot create folder (" + ec.message() + ")");
}

StagingDir::~StagingDir() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(tmp_, ec);
  }
}

void StagingDir::commit() {
  checkReplaceable(target_, marker_);
  std::error_code ec;
  if (fs::exists(target_, ec)) fs::remove_all(target_, ec);
  if (ec) throw std::runtime_error(target_.string() + ": cannot replace (" + ec.message() + ")");
  fs::rename(tmp_, target_, ec);
  if (ec)
    throw std::runtime_error(target_.string() + ": cannot move into place (" + ec.message() + ")");
  committed_ = true;
}

}  // namespace slamroute
