// `crowdsim-bench list-plugins`: how a user sees the plugins of their folders.
#include <gtest/gtest.h>

#include <string>

#include "shell.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

std::size_t Count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

const std::string& Exe() {
  static const std::string exe = (testing::BinaryDir() / "bin" / "crowdsim-bench").string();
  return exe;
}

TEST(ListPlugins, APluginGivenByPathThatIsAlsoFoundIsListedOnce) {
  // docs/plugins.md: `list-plugins build/crowdsim_NAME.so` with that folder on the path.
  const std::string folder = testing::FixturePluginDir().string();
  const auto [status, out] =
      testing::Shell("CROWDSIM_PLUGIN_PATH=" + folder + " " + Exe() + " list-plugins " + folder +
                     "/crowdsim_throwing_policy.so");
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(Count(out, "file: " + folder + "/crowdsim_throwing_policy.so"), 1u) << out;
}

}  // namespace
}  // namespace crowdsim
