// The signal handler may run at any instruction of any thread, so it uses only async-signal-safe
// system calls (openat, getdents64, unlinkat) on paths kept in fixed buffers.
#include "StagingSignals.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>

namespace slamroute::detail {
namespace {

constexpr std::size_t kSlots = 16, kPathMax = 4096;
struct Slot {
  std::atomic<bool> used{false};
  char path[kPathMax] = {};
};
std::array<Slot, kSlots> g_slots;
std::mutex g_mutex;  // registration only; never taken in the handler
constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};

struct LinuxDirent64 {
  ino64_t d_ino;
  off64_t d_off;
  unsigned short d_reclen;
  unsigned char d_type;
  char d_name[];
};

/// Removes the entry `name` of the folder `dirfd`, recursing into folders (depth-limited).
void removeEntry(int dirfd, const char* name, int depth) {
  if (::unlinkat(dirfd, name, 0) == 0 || depth > 32) return;
  const int fd = ::openat(dirfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(8) char buf[4096];
  for (long n; (n = ::syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0;) {
    for (long off = 0; off < n;) {
      const auto* d = reinterpret_cast<const LinuxDirent64*>(buf + off);
      off += d->d_reclen;
      if (std::strcmp(d->d_name, ".") == 0 || std::strcmp(d->d_name, "..") == 0) continue;
      removeEntry(fd, d->d_name, depth + 1);
    }
  }
  ::close(fd);
  ::unlinkat(dirfd, name, AT_REMOVEDIR);
}

void onSignal(int sig) {
  const int saved = errno;
  for (auto& s : g_slots)
    if (s.used.load()) {
      removeEntry(AT_FDCWD, s.path, 0);
      removeEntry(AT_FDCWD, s.path, 0);  // again: a thread may have added a file meanwhile
    }
  errno = saved;
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void installHandlers() {
  for (int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    for (int other : kSignals) sigaddset(&sa.sa_mask, other);
    ::sigaction(sig, &sa, nullptr);
  }
}

}  // namespace

void removeOnSignal(const std::string& dir) {
  if (dir.size() + 1 > kPathMax) return;
  const std::lock_guard lock(g_mutex);
  static std::once_flag once;
  std::call_once(once, installHandlers);
  for (auto& s : g_slots)
    if (!s.used.load()) {
      std::memcpy(s.path, dir.c_str(), dir.size() + 1);
      s.used.store(true);
      return;
    }
}

void unwatchOnSignal(const std::string& dir) {
  const std::lock_guard lock(g_mutex);
  for (auto& s : g_slots)
    if (s.used.load() && dir == s.path) s.used.store(false);
}

}  // namespace slamroute::detail
