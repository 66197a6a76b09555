#include "test_paths.h"

namespace crowdsim::testing {

std::filesystem::path SourceDir() { return CROWDSIM_TEST_SOURCE_DIR; }
std::filesystem::path BinaryDir() { return CROWDSIM_TEST_BINARY_DIR; }
std::filesystem::path PluginDir() { return BinaryDir() / "plugins"; }
std::filesystem::path FixturePluginDir() { return BinaryDir() / "tests" / "fixture_plugins"; }
std::filesystem::path SharedDir() { return SourceDir().parent_path() / "shared"; }

}  // namespace crowdsim::testing
