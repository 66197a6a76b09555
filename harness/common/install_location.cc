#include "install_location.h"

#include <boost/dll/runtime_symbol_info.hpp>
#include <system_error>

namespace crowdsim::common {
namespace fs = std::filesystem;

std::optional<fs::path> InstalledLibDir() {
  std::error_code ec;
  // Canonical, so '..' from an RPATH such as $ORIGIN/../../.. resolves as folders, not lexically.
  const fs::path lib =
      fs::weakly_canonical(fs::path(boost::dll::this_line_location().string()), ec).parent_path();
  if (fs::is_directory(lib / "crowdsim-bench" / "plugins", ec)) return lib;
  return std::nullopt;
}

}  // namespace crowdsim::common
