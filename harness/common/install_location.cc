#include "install_location.h"

#include <boost/dll/runtime_symbol_info.hpp>
#include <system_error>

#include "crowdsim/version.h"

namespace crowdsim::common {
namespace fs = std::filesystem;

std::optional<fs::path> InstalledLibDir() {
  std::error_code ec;
  // The SDK library's folder, wherever the caller is linked (the host lives in executables and
  // the Python module). Canonical: an RPATH such as $ORIGIN/../../.. leaves '..' in the path.
  const fs::path sdk = boost::dll::symbol_location(crowdsim::Version).string();
  const fs::path lib = fs::weakly_canonical(sdk, ec).parent_path();
  if (fs::is_directory(lib / "crowdsim-bench" / "plugins", ec)) return lib;
  return std::nullopt;
}

}  // namespace crowdsim::common
