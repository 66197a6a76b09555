// Who may write into an output folder: one crowdsim-bench process at a time (two runs or
// trainings appending to one episodes.csv or training log interleave their lines), and one
// kind of output (a suite run's files beside a training's mix two unrelated results).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

namespace crowdsim {

/// An exclusive lock on an output folder while any holder of it lives: a POSIX record lock
/// (fcntl) on the file `.crowdsim-bench.lock` in it, which belongs to this process (children it
/// forks do not hold it, and the system releases it when the process ends, however it ends: a
/// crash leaves no stale lock; it works on NFS). The file itself stays (git ignores it).
class OutputFolderLock {
 public:
  /// The lock, or null when another process, or another holder in this one (two Python
  /// threads evaluating into one folder), holds it: then `*why` names the holder and the
  /// folder. A file system that cannot lock (ENOLCK, ENOSYS: NFS without a lock daemon, Lustre
  /// without flock) gives an unlocked holder: the run goes on as before locks existed.
  static std::shared_ptr<OutputFolderLock> Acquire(const std::filesystem::path& dir,
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

/// Claims the existing folder `dir` for output of `kind` ("a suite run" or "a training"): its
/// lock, once no other process holds it and the folder holds no output of the other kind.
/// Null, and in `*why` the refusal (naming the folder and the fix), otherwise.
std::shared_ptr<OutputFolderLock> ClaimOutputFolder(const std::filesystem::path& dir,
                                                    const std::string& kind, std::string* why);

}  // namespace crowdsim
