#include "run/output_folder.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>
#include <set>
#include <string>

namespace crowdsim {
namespace fs = std::filesystem;

namespace {

std::mutex g_mutex;
std::set<fs::path> g_held;  // canonical folders a holder in this process writes into

}  // namespace

std::shared_ptr<OutputFolderLock> OutputFolderLock::Acquire(const fs::path& dir, std::string* why) {
  std::error_code ec;
  const fs::path key = fs::weakly_canonical(dir, ec);
  std::lock_guard<std::mutex> guard(g_mutex);
  if (g_held.count(key)) {
    *why = "this process is already writing into '" + dir.string() +
           "' (another run or evaluate at the same time); wait until it ends, or choose another "
           "--out";
    return nullptr;
  }
  const fs::path file = dir / ".crowdsim-bench.lock";
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  // An unopenable folder is unwritable; a later write says why. Without lock support (errors other
  // than "held"), run unlocked.
  if (fd >= 0) {
    struct flock request {};
    request.l_type = F_WRLCK;
    request.l_whence = SEEK_SET;  // the whole file
    if (::fcntl(fd, F_SETLK, &request) != 0 && (errno == EACCES || errno == EAGAIN)) {
      struct flock holder {};
      holder.l_type = F_WRLCK;
      holder.l_whence = SEEK_SET;
      const bool known =
          ::fcntl(fd, F_GETLK, &holder) == 0 && holder.l_type != F_UNLCK && holder.l_pid > 0;
      ::close(fd);
      *why = "another crowdsim-bench process" +
             (known ? " (pid " + std::to_string(holder.l_pid) + ")" : std::string()) +
             " is writing into '" + dir.string() + "'; wait until it ends, or choose another --out";
      return nullptr;
    }
  }
  g_held.insert(key);
  // Released under the mutex: closing any descriptor drops the process's lock, so no new holder may
  // come first.
  return std::shared_ptr<OutputFolderLock>(new OutputFolderLock(fd), [key](OutputFolderLock* held) {
    std::lock_guard<std::mutex> release(g_mutex);
    delete held;
    g_held.erase(key);
  });
}

OutputFolderLock::~OutputFolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the record lock
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

std::shared_ptr<OutputFolderLock> ClaimOutputFolder(const fs::path& dir, const std::string& kind,
                                                    std::string* why) {
  auto lock = OutputFolderLock::Acquire(dir, why);
  if (!lock) return nullptr;
  const std::string held = OutputFolderKind(dir);
  if (!held.empty() && held != kind) {
    // Appended piece by piece: GCC 12 falsely warns (-Wrestrict) on one long sum.
    std::string text = "'";
    text += dir.string();
    text += "' holds ";
    text += held;
    text += held == "a training" ? " (training.yaml); " : " (manifest.json, episodes.csv); ";
    text += kind;
    text += " writes into a folder of its own: choose another --out";
    *why = std::move(text);
    return nullptr;
  }
  return lock;
}

}  // namespace crowdsim
