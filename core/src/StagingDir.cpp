#include "slamroute/core/StagingDir.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

#include <stdexcept>

#include "StagingSignals.hpp"

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

/// The pid in a `.NAME.KIND.PID` folder name beside `target`, or 0 when `name` is not one.
long stagingPid(const std::string& name, const fs::path& target, const std::string& kind) {
  const std::string prefix = "." + target.filename().string() + "." + kind + ".";
  if (name.rfind(prefix, 0) != 0) return 0;
  const std::string digits = name.substr(prefix.size());
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
  return std::strtol(digits.c_str(), nullptr, 10);
}

bool processGone(long pid) {
  return pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH;
}

/// Tidies up after a process that is gone (killed by SIGKILL or the OOM killer, it could not do
/// it itself): its `.NAME.tmp.PID` staging folders were never complete results and are removed;
/// an `.NAME.old.PID` folder is the previous result set aside while the new one was moved in
/// (commit() without RENAME_EXCHANGE): put back when the target is missing, else removed.
void tidyAfterDeadProcesses(const fs::path& target) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (!e.is_directory(ec)) continue;
    if (processGone(stagingPid(name, target, "tmp"))) fs::remove_all(e.path(), ec);
    if (!processGone(stagingPid(name, target, "old"))) continue;
    if (!fs::exists(target, ec))
      fs::rename(e.path(), target, ec);
    else
      fs::remove_all(e.path(), ec);
  }
}

/// Moves `from` onto `to` so that a complete `to` exists at every instant: an atomic exchange
/// (renameat2 RENAME_EXCHANGE) where the file system has it, else `to` is first renamed aside.
/// Afterwards the previous `to` (if any) is gone.
void swapInto(const fs::path& from, const fs::path& to, const fs::path& aside) {
  std::error_code ec;
  if (!fs::exists(to, ec)) {
    fs::rename(from, to, ec);
    if (ec)
      throw std::runtime_error(to.string() + ": cannot move into place (" + ec.message() + ")");
    return;
  }
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(from, ec);  // now the previous result
    return;
  }
  fs::rename(to, aside, ec);
  if (ec) throw std::runtime_error(to.string() + ": cannot replace (" + ec.message() + ")");
  fs::rename(from, to, ec);
  if (ec) {
    std::error_code back;
    fs::rename(aside, to, back);
    throw std::runtime_error(to.string() + ": cannot move into place (" + ec.message() + ")");
  }
  fs::remove_all(aside, ec);
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
  tidyAfterDeadProcesses(target_);
  tmp_ = target_.parent_path() /
         ("." + target_.filename().string() + ".tmp." + std::to_string(::getpid()));
  fs::remove_all(tmp_, ec);
  fs::create_directories(tmp_, ec);
  if (ec) throw std::runtime_error(tmp_.string() + ": cannot create folder (" + ec.message() + ")");
  detail::removeOnSignal(tmp_.string());
}

StagingDir::~StagingDir() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(tmp_, ec);
  }
  detail::unwatchOnSignal(tmp_.string());
}

void StagingDir::commit() {
  checkReplaceable(target_, marker_);
  // From here the staging folder is the new result: a signal must no longer remove it (the
  // exchange below may already have made it the target).
  detail::unwatchOnSignal(tmp_.string());
  const fs::path aside = target_.parent_path() /
                         ("." + target_.filename().string() + ".old." + std::to_string(::getpid()));
  swapInto(tmp_, target_, aside);
  committed_ = true;
}

}  // namespace slamroute
