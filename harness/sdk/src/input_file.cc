#include "crowdsim/input_file.h"

#include <system_error>

namespace crowdsim {
namespace fs = std::filesystem;

std::string NotARegularFile(const fs::path& path) {
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  switch (s.type()) {
    case fs::file_type::regular:
      return "";
    case fs::file_type::not_found:
      return "does not exist";
    case fs::file_type::directory:
      return "is a folder";
    case fs::file_type::fifo:
      return "is a named pipe (FIFO), not a file (reading it would wait for a writer)";
    case fs::file_type::block:
    case fs::file_type::character:
      return "is a device, not a file";
    case fs::file_type::socket:
      return "is a socket, not a file";
    default:
      return ec ? "cannot be read (" + ec.message() + ")" : "is not a regular file";
  }
}

}  // namespace crowdsim
