#include "crowdsim/bench/spec_file_kind.h"

#include <fstream>
#include <string>

#include "crowdsim/input_file.h"

namespace crowdsim {

SpecFileKind KindOfSpecFile(const std::filesystem::path& file) {
  if (!NotARegularFile(file).empty()) return SpecFileKind::kUnknown;  // a pipe would block
  std::ifstream f(file);
  std::string line;
  for (bool first = true; std::getline(f, line); first = false) {
    // A UTF-8 byte order mark is no part of a key.
    if (first && line.starts_with("\xef\xbb\xbf")) line.erase(0, 3);
    if (line.starts_with("training:") || line.starts_with("policy:")) {
      return SpecFileKind::kTraining;
    }
    if (line.starts_with("rows:")) return SpecFileKind::kSuite;
    if (line.starts_with("format: crowdsim-world-set/")) return SpecFileKind::kWorldSet;
    if (line.starts_with("format: crowdsim-world/")) return SpecFileKind::kWorld;
  }
  return SpecFileKind::kUnknown;
}

}  // namespace crowdsim
