// Where the installed libraries live: the SDK finds the data and the host the plugins from it.
#pragma once

#include <filesystem>
#include <optional>

namespace crowdsim::common {

/// PREFIX/lib when libcrowdsim_sdk.so is installed (PREFIX/lib/crowdsim-bench/plugins beside
/// it), else none (a build tree).
std::optional<std::filesystem::path> InstalledLibDir();

}  // namespace crowdsim::common
