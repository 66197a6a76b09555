// One process and one kind of output (run or training) per output folder: lines would interleave,
// files mix.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

namespace crowdsim {

/// An exclusive output-folder lock: a POSIX record lock (fcntl) on `.crowdsim-bench.lock`, not
/// inherited by forks, released however the process ends (no stale lock), NFS-safe.
class OutputFolderLock {
 public:
  /// The lock, or null when held elsewhere (`*why` names holder and folder). Without lock support
  /// (ENOLCK, ENOSYS): an unlocked holder.
  static std::shared_ptr<OutputFolderLock> Acquire(const std::filesystem::path& dir,
                                                   std::string* why);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

 private:
  explicit OutputFolderLock(int fd) : fd_(fd) {}
  int fd_;
};

/// What `dir` holds: "a training" (training.yaml or checkpoint), "a suite run" (manifest.json or
/// episodes.csv), or "".
std::string OutputFolderKind(const std::filesystem::path& dir);

/// Claims existing `dir` for `kind` output ("a suite run" or "a training"): its lock, or null with
/// `*why` and the fix when held or holding the other kind.
std::shared_ptr<OutputFolderLock> ClaimOutputFolder(const std::filesystem::path& dir,
                                                    const std::string& kind, std::string* why);

}  // namespace crowdsim
