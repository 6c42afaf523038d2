#pragma once
// Keyframe clouds of a SLAM run, appended once and read back by number (loop-closure submaps,
// the final map). In memory, or in an unnamed temporary file in a given folder: a keyframe's
// 0.2 m cloud is ~47 kB, a 75 km drive has ~36,000 keyframes, and with the clouds on disk the
// run's resident memory does not grow by them (the page cache serves the reads; the file
// disappears with the process, even when it is killed).
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate {

class CloudStore {
 public:
  /// Clouds in memory.
  CloudStore() = default;
  /// Clouds in an unnamed file in `dir` (which must exist). Throws std::runtime_error naming the
  /// folder when no file can be made there; `what` names the clouds in error messages.
  explicit CloudStore(const std::filesystem::path& dir, std::string what = "the keyframe clouds");
  ~CloudStore();
  CloudStore(const CloudStore&) = delete;
  CloudStore& operator=(const CloudStore&) = delete;

  /// Stores a copy of `c`; returns its number (0, 1, ...). Throws std::runtime_error on a write
  /// error (e.g. the disk is full), naming the folder.
  int add(const Cloud& c);
  /// The cloud stored as number `id`, bit for bit.
  Cloud get(int id) const;
  /// The axis-aligned box around cloud `id`'s points (kept in memory: 24 bytes a cloud; an empty
  /// cloud has an empty box), so a cloud's extent is known without reading it back.
  const Eigen::AlignedBox3f& box(int id) const;
  /// Frees the memory of cloud `id` (in memory, get(id) is then empty; a no-op on disk).
  void release(int id);
  std::size_t size() const { return index_.size(); }
  bool onDisk() const { return fd_ >= 0; }
  /// Bytes written to the file so far (0 in memory).
  std::uint64_t bytesOnDisk() const { return end_; }

 private:
  struct Entry {
    std::uint64_t offset = 0;
    std::uint32_t points = 0;
    Eigen::AlignedBox3f box;  ///< empty by default
  };
  const Entry& entry(int id) const;
  std::filesystem::path dir_;
  std::string what_ = "the keyframe clouds";
  int fd_ = -1;
  std::uint64_t end_ = 0;
  std::vector<Entry> index_;
  std::vector<Cloud> memory_;  ///< used when not on disk
};

}  // namespace slamroute::evaluate
