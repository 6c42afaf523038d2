#pragma once
// Outputs are written atomically: to a temporary file beside the target, then renamed, so a
// failed run never leaves a half-written file and never destroys a previous good one.
#include <filesystem>
#include <fstream>
#include <string>

namespace slamroute {

/// Writes `content` to `path` atomically (temp file + rename). Throws std::runtime_error.
void writeFileAtomic(const std::filesystem::path& path, const std::string& content);

/// Stream-style atomic writer: write to stream(), then commit(). Destroyed without commit(),
/// the temporary file is removed and the target is untouched.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path path, bool binary = false);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ofstream& stream() { return out_; }
  const std::filesystem::path& tempPath() const { return tmp_; }
  void commit();

 private:
  std::filesystem::path path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Reads a whole file; throws std::runtime_error naming the file when it cannot be read.
std::string readFile(const std::filesystem::path& path);

/// Reads a whole file, transparently gunzipping when it is gzip-compressed (.gz or magic bytes).
/// Throws std::runtime_error naming the file on a missing file or a truncated/corrupt gzip.
std::string readMaybeGzip(const std::filesystem::path& path);

}  // namespace slamroute
