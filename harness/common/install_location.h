// Where the installed libraries live: the SDK finds data, the host plugins, from it.
#pragma once

#include <filesystem>
#include <optional>

namespace crowdsim::common {

/// PREFIX/lib when the calling library is installed (PREFIX/lib/crowdsim-bench/plugins beside it),
/// else none (a build tree).
std::optional<std::filesystem::path> InstalledLibDir();

}  // namespace crowdsim::common
