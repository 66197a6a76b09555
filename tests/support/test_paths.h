// Where tests find the source tree, the build tree and the built plugins.
#pragma once

#include <filesystem>

namespace crowdsim::testing {

std::filesystem::path SourceDir();
std::filesystem::path BinaryDir();
std::filesystem::path PluginDir();
std::filesystem::path FixturePluginDir();  ///< deliberately broken plugins
/// ../shared next to the source tree (floor plans, references); may not exist.
std::filesystem::path SharedDir();

}  // namespace crowdsim::testing
