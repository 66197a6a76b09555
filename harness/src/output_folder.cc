#include "output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace crowdsim {
namespace fs = std::filesystem;

std::unique_ptr<OutputFolderLock> OutputFolderLock::Acquire(const fs::path& dir, std::string* why) {
  const fs::path file = dir / ".crowdsim-bench.lock";
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    // A folder we cannot lock is one we cannot write either: the writes say why.
    return std::unique_ptr<OutputFolderLock>(new OutputFolderLock(-1));
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char pid[32] = {};
    const ssize_t n = ::pread(fd, pid, sizeof(pid) - 1, 0);
    std::string holder = n > 0 ? std::string(pid, static_cast<size_t>(n)) : "";
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    ::close(fd);
    *why = "another crowdsim-bench process" + (holder.empty() ? "" : " (pid " + holder + ")") +
           " is writing into '" + dir.string() + "'; wait until it ends, or choose another --out";
    return nullptr;
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd, pid.data(), pid.size(), 0);
  }
  return std::unique_ptr<OutputFolderLock>(new OutputFolderLock(fd));
}

OutputFolderLock::~OutputFolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

std::string OutputFolderKind(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir / "training.yaml", ec) || fs::exists(dir / "checkpoint", ec)) {
    return "a training";
  }
  if (fs::exists(dir / "manifest.json", ec) || fs::exists(dir / "episodes.csv", ec)) {
    return "a suite run";
  }
  return "";
}

}  // namespace crowdsim
