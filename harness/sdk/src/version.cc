#include "crowdsim/version.h"

#include <fstream>
#include <string>

namespace crowdsim {

const char* Version() { return CROWDSIM_VERSION; }

std::string CpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      std::string m = colon == std::string::npos ? line : line.substr(colon + 1);
      m.erase(0, m.find_first_not_of(' '));
      std::erase(m, '"');
      std::erase(m, '\\');
      return m;
    }
  }
  return "unknown";
}

}  // namespace crowdsim
