#pragma once
// A result folder built in a hidden temporary folder beside its target and moved into place by
// commit(); destroyed without commit(), the temporary folder is removed. Used by drive, survey
// and evaluate so that a failed run leaves nothing half-written. commit() swaps the new folder
// in so that one complete result exists at every instant (RENAME_EXCHANGE, or the old one renamed
// aside first). SIGINT, SIGTERM and SIGHUP remove the temporary folder; one of a process killed
// otherwise is removed by the next StagingDir for the same target, which also puts back a
// previous result that was set aside when the kill came.
#include <chrono>
#include <filesystem>
#include <string>

namespace slamroute {

class StagingDir {
 public:
  /// `marker` is a file that identifies a previous result of the same kind: an existing target
  /// folder is replaced only when it is empty or holds the marker; otherwise this throws
  /// std::runtime_error (never delete a folder we did not write).
  StagingDir(std::filesystem::path target, const std::string& marker);
  ~StagingDir();
  StagingDir(const StagingDir&) = delete;
  StagingDir& operator=(const StagingDir&) = delete;

  const std::filesystem::path& path() const { return tmp_; }
  const std::filesystem::path& target() const { return target_; }
  void commit();

 private:
  std::filesystem::path target_, tmp_;
  std::string marker_;
  bool committed_ = false;
};

/// Commits `staging` and completes a recording's result: where it now lives and the wall time
/// since `wall0` (a result type with out_dir and wall_seconds).
template <class Result>
Result committedResult(StagingDir& staging, Result res,
                       std::chrono::steady_clock::time_point wall0) {
  staging.commit();
  res.out_dir = staging.target();
  res.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace slamroute
