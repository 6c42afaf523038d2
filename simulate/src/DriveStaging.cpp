#include "DriveStaging.hpp"

#include <unistd.h>

#include <stdexcept>

namespace slamroute::simulate {
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

}  // namespace slamroute::simulate
