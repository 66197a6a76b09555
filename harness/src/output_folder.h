// Who may write into an output folder: one crowdsim-bench process at a time (two runs or
// trainings appending to one episodes.csv or training log interleave their lines), and one
// kind of output (a suite run's files beside a training's mix two unrelated results).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

namespace crowdsim {

/// An exclusive lock on an output folder for the lifetime of this object: flock on the file
/// `.crowdsim-bench.lock` in it, which the system releases when the process ends, however it
/// ends (a crash leaves no stale lock). The file itself stays (git ignores it).
class OutputFolderLock {
 public:
  /// The lock, or null when another process holds it: then `*why` names that process and
  /// the folder.
  static std::unique_ptr<OutputFolderLock> Acquire(const std::filesystem::path& dir,
                                                   std::string* why);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

 private:
  explicit OutputFolderLock(int fd) : fd_(fd) {}
  int fd_;
};

/// What `dir` already holds: "a training" (training.yaml or a checkpoint), "a suite run"
/// (manifest.json or episodes.csv), or "" (nothing of ours, or no folder).
std::string OutputFolderKind(const std::filesystem::path& dir);

}  // namespace crowdsim
