#include "install_location.h"

#include <boost/dll/runtime_symbol_info.hpp>
#include <system_error>

namespace crowdsim::common {
namespace fs = std::filesystem;

std::optional<fs::path> InstalledLibDir() {
  std::error_code ec;
  // Canonical: a library found through an RPATH such as $ORIGIN/../../.. (the Python module's)
  // has '..' in its path, which parent_path() would strip lexically, not as folders.
  const fs::path lib =
      fs::weakly_canonical(fs::path(boost::dll::this_line_location().string()), ec).parent_path();
  if (fs::is_directory(lib / "crowdsim-bench" / "plugins", ec)) return lib;
  return std::nullopt;
}

}  // namespace crowdsim::common
