#include "slamroute/evaluate/CloudStore.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace slamroute::evaluate {
namespace {

static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "clouds are stored as packed xyz floats");

/// An unnamed file in `dir`: O_TMPFILE where the file system has it, else a named one unlinked
/// at once.
int openUnnamed(const std::filesystem::path& dir) {
  int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
  std::string tmpl = (dir / ".keyframe-clouds.XXXXXX").string();
  fd = ::mkostemp(tmpl.data(), O_CLOEXEC);
  if (fd >= 0) ::unlink(tmpl.c_str());
  return fd;
}

}  // namespace

CloudStore::CloudStore(const std::filesystem::path& dir) : dir_(dir) {
  fd_ = openUnnamed(dir);
  if (fd_ < 0)
    throw std::runtime_error(dir.string() + ": cannot make a file for the keyframe clouds (" +
                             std::strerror(errno) + ")");
}

CloudStore::~CloudStore() {
  if (fd_ >= 0) ::close(fd_);
}

int CloudStore::add(const Cloud& c) {
  Entry e;
  e.offset = end_;
  e.points = static_cast<std::uint32_t>(c.size());
  if (fd_ < 0) {
    memory_.push_back(c);
  } else {
    const char* p = reinterpret_cast<const char*>(c.data());
    std::size_t left = c.size() * sizeof(Eigen::Vector3f);
    std::uint64_t at = end_;
    while (left > 0) {
      const ssize_t n = ::pwrite(fd_, p, left, static_cast<off_t>(at));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        throw std::runtime_error(dir_.string() + ": cannot write the keyframe clouds (" +
                                 std::strerror(n < 0 ? errno : ENOSPC) + ")");
      p += n;
      at += static_cast<std::uint64_t>(n);
      left -= static_cast<std::size_t>(n);
    }
    end_ = at;
  }
  index_.push_back(e);
  return static_cast<int>(index_.size()) - 1;
}

Cloud CloudStore::get(int id) const {
  const auto k = static_cast<std::size_t>(id);
  if (id < 0 || k >= index_.size()) throw std::out_of_range("CloudStore: no cloud " + std::to_string(id));
  if (fd_ < 0) return memory_[k];
  Cloud c(index_[k].points);
  char* p = reinterpret_cast<char*>(c.data());
  std::size_t left = c.size() * sizeof(Eigen::Vector3f);
  std::uint64_t at = index_[k].offset;
  while (left > 0) {
    const ssize_t n = ::pread(fd_, p, left, static_cast<off_t>(at));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw std::runtime_error(dir_.string() + ": cannot read the keyframe clouds back (" +
                               (n < 0 ? std::strerror(errno) : "file too short") + ")");
    p += n;
    at += static_cast<std::uint64_t>(n);
    left -= static_cast<std::size_t>(n);
  }
  return c;
}

void CloudStore::release(int id) {
  const auto k = static_cast<std::size_t>(id);
  if (fd_ < 0 && id >= 0 && k < memory_.size()) Cloud().swap(memory_[k]);
}

}  // namespace slamroute::evaluate
