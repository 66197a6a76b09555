#include "episodes_text.h"

#include <sstream>
#include <vector>

namespace crowdsim::testing {

std::string WithoutWallTime(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, out;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::string cell;
    std::istringstream ls(line);
    while (std::getline(ls, cell, ',')) f.push_back(cell);
    if (f.size() > 11) f.erase(f.begin() + 11);
    for (size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
    out += "\n";
  }
  return out;
}

}  // namespace crowdsim::testing
