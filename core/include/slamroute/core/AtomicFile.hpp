#pragma once
// Outputs are written atomically: to a temporary file beside the target, then renamed, so a
// failed run never leaves a half-written file and never destroys a previous good one.
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

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

/// Outputs made of several files (graph.json + .geojson + .graphml + .png; route.json +
/// .rou.xml) replaced together: every file is first written in full to a hidden path beside its
/// target (staged()), then commit() renames them all in place and removes the old output's
/// companions the new one lacks. A failure while writing (full disk, bad value) leaves the old
/// set whole; destroyed without commit(), the staged files are removed.
class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  ~AtomicFileSet();
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;

  /// The path to write `target`'s new content to (same folder and extension, hidden name).
  std::filesystem::path staged(const std::filesystem::path& target);
  /// `target` belongs to the output being replaced but not to the new one: removed at commit().
  void dropAtCommit(const std::filesystem::path& target);
  void commit();

 private:
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // tmp, target
  std::vector<std::filesystem::path> dropped_;
  bool committed_ = false;
};

/// Throws std::runtime_error when `path` is a folder: an output file cannot replace one.
void requireFileTarget(const std::filesystem::path& path);

/// Reads a whole file; throws std::runtime_error naming the file when it cannot be read.
std::string readFile(const std::filesystem::path& path);

/// Reads a whole file, transparently gunzipping when it is gzip-compressed (.gz or magic bytes).
/// Throws std::runtime_error naming the file on a missing file or a truncated/corrupt gzip.
std::string readMaybeGzip(const std::filesystem::path& path);

}  // namespace slamroute
