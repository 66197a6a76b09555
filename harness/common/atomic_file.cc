#include "atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace crowdsim::common {
namespace fs = std::filesystem;

int WriteAll(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return 0;
}

int CreateBeside(const fs::path& path, std::string* temp) {
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::string hidden = ".";  // built piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + s
  hidden += path.filename().string();
  hidden += ".XXXXXX";
  *temp = (folder / hidden).string();
  const int fd = ::mkstemp(temp->data());
  if (fd < 0) {
    throw std::runtime_error("cannot create a file in " + folder.string() + " to write " +
                             path.string() + ": " + std::strerror(errno));
  }
  // mkstemp makes it 0600; a result file is the user's as any other (0666 less the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  return fd;
}

void WriteFileAtomically(const fs::path& path, const std::string& text) {
  std::string name;
  const int fd = CreateBeside(path, &name);
  int error = WriteAll(fd, text.data(), text.size());
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(name.c_str());
    throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(error) +
                             " (the previous file, if any, is unchanged)");
  }
  if (::rename(name.c_str(), path.c_str()) != 0) {
    error = errno;
    ::unlink(name.c_str());
    throw std::runtime_error("cannot replace " + path.string() + ": " + std::strerror(error));
  }
}

void CopyFileAtomically(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  std::ostringstream bytes;
  if (!(in && bytes << in.rdbuf())) {
    throw std::runtime_error("cannot read " + from.string() + ": " + std::strerror(errno));
  }
  WriteFileAtomically(to, bytes.str());
}

}  // namespace crowdsim::common
