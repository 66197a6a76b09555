// `crowdsim-bench list-plugins`: how a user sees the plugins of their folders.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "shell.h"
#include "temp_dir.h"
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

TEST(ListPlugins, APluginThatHidesAnotherOfItsNameSaysWhichFile) {
  // A copy of yours on CROWDSIM_PLUGIN_PATH replaces the built-in one of its name
  // (docs/plugins.md); an old copy left there must not be taken for the one you just built without
  // a word.
  const testing::TempDir dir;
  std::filesystem::copy_file(testing::PluginDir() / "crowdsim_linear.so",
                             dir.path() / "crowdsim_linear.so");
  // The harness's folder on the path too: the same file again hides nothing.
  const auto [status, out] =
      testing::Shell("CROWDSIM_PLUGIN_PATH=" + dir.path().string() + ":" +
                     testing::PluginDir().string() + " " + Exe() + " list-plugins");
  EXPECT_EQ(status, 0) << out;
  const std::string mine = "file: " + (dir.path() / "crowdsim_linear.so").string();
  const std::string hides = "hides: " + (testing::PluginDir() / "crowdsim_linear.so").string();
  ASSERT_NE(out.find(mine), std::string::npos) << out;
  EXPECT_NE(out.find(hides, out.find(mine)), std::string::npos) << out;
  EXPECT_EQ(Count(out, "hides:"), 1u) << out;
  // The command's help says what the line means.
  const auto [help_status, help] = testing::Shell(Exe() + " help list-plugins");
  EXPECT_EQ(help_status, 0) << help;
  EXPECT_NE(help.find("`hides:` the files of its name in later folders"), std::string::npos)
      << help;
}

TEST(ListPlugins, ListsTheShippedHumanModels) {
  // docs/humans.md's models: each listed by name with its description.
  const auto [status, out] = testing::Shell(Exe() + " list-plugins");
  EXPECT_EQ(status, 0) << out;
  for (const char* name : {"orca", "social_force", "hsfm", "linear"}) {
    EXPECT_NE(out.find("  " + std::string(name) + " - "), std::string::npos) << name << "\n" << out;
  }
}

TEST(ListPlugins, AnEmptyTextDefaultIsShownAsEmptyQuotes) {
  // The torchscript and floor-plan plugins' file parameters default to "" (none given).
  const auto [status, out] = testing::Shell(Exe() + " list-plugins");
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(out.find("default )"), std::string::npos) << out;
  EXPECT_NE(out.find("(string, default \"\")"), std::string::npos) << out;
}

}  // namespace
}  // namespace crowdsim
