#include "crowdsim/data_root.h"

#include <cstdlib>

#include "install_location.h"

namespace crowdsim {

std::filesystem::path DataRoot() {
  if (const char* env = std::getenv("CROWDSIM_DATA_DIR"); env && *env) return env;
  if (const auto lib = common::InstalledLibDir())
    return lib->parent_path() / "share" / "crowdsim-bench";
  return CROWDSIM_SOURCE_DIR;
}

}  // namespace crowdsim
