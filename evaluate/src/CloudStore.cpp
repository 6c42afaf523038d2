#include "slamroute/evaluate/CloudStore.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace slamroute::evaluate {
namespace {

static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float),
              "clouds are stored as packed xyz floats");

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

/// pwrite (`write`) or pread of `bytes` at `offset`, retried until all are through. Throws
/// std::runtime_error naming `dir` on an error or a short file.
void transfer(int fd, void* data, std::size_t bytes, std::uint64_t offset, bool write,
              const std::filesystem::path& dir, const std::string& what) {
  char* p = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t n = write ? ::pwrite(fd, p, bytes, static_cast<off_t>(offset))
                            : ::pread(fd, p, bytes, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = n < 0   ? std::strerror(errno)
                              : write ? std::strerror(ENOSPC)
                                      : "file too short";
      throw std::runtime_error(dir.string() + (write ? ": cannot write " : ": cannot read back ") +
                               what + " (" + why + ")");
    }
    p += n;
    offset += static_cast<std::uint64_t>(n);
    bytes -= static_cast<std::size_t>(n);
  }
}

}  // namespace

CloudStore::CloudStore(const std::filesystem::path& dir, std::string what)
    : dir_(dir), what_(std::move(what)) {
  fd_ = openUnnamed(dir);
  if (fd_ < 0)
    throw std::runtime_error(dir.string() + ": cannot make a file for " + what_ + " (" +
                             std::strerror(errno) + ")");
}

CloudStore::~CloudStore() {
  if (fd_ >= 0) ::close(fd_);
}

int CloudStore::add(const Cloud& c) {
  Entry e;
  e.offset = end_;
  e.points = static_cast<std::uint32_t>(c.size());
  for (const auto& p : c) e.box.extend(p);
  if (fd_ < 0) {
    memory_.push_back(c);
  } else {
    // pwrite does not change the cloud; transfer takes one pointer type for both directions.
    transfer(fd_, const_cast<Eigen::Vector3f*>(c.data()), c.size() * sizeof(Eigen::Vector3f), end_,
             true, dir_, what_);
    end_ += c.size() * sizeof(Eigen::Vector3f);
  }
  index_.push_back(e);
  return static_cast<int>(index_.size()) - 1;
}

const CloudStore::Entry& CloudStore::entry(int id) const {
  const auto k = static_cast<std::size_t>(id);
  if (id < 0 || k >= index_.size())
    throw std::out_of_range("CloudStore: no cloud " + std::to_string(id));
  return index_[k];
}

const Eigen::AlignedBox3f& CloudStore::box(int id) const { return entry(id).box; }

Cloud CloudStore::get(int id) const {
  const Entry& e = entry(id);
  if (fd_ < 0) return memory_[static_cast<std::size_t>(id)];
  Cloud c(e.points);
  transfer(fd_, c.data(), c.size() * sizeof(Eigen::Vector3f), e.offset, false, dir_, what_);
  return c;
}

void CloudStore::release(int id) {
  const auto k = static_cast<std::size_t>(id);
  if (fd_ < 0 && id >= 0 && k < memory_.size()) Cloud().swap(memory_[k]);
}

}  // namespace slamroute::evaluate
