// A suite of your plugin alone, rebuilt between two runs into one folder: no row is unchanged,
// so run refuses the folder (docs/plugins.md, "Rebuilding"), and says which file changed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;

TEST(RebuiltPlugin, ARefusedRerunNamesThePluginFileThatChanged) {
  const testing::TempDir dir;
  fs::create_directories(dir.path() / "mine");
  const fs::path plugin = dir.path() / "mine" / "crowdsim_linear.so";
  fs::copy_file(testing::PluginDir() / "crowdsim_linear.so", plugin);
  const fs::path file = dir.Write("suite.yaml", R"(name: mine
episodes: 2
seed: 1
isolation: off
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 2, policy: orca}
rows:
  - {policy: )" + plugin.string() + "}\n");
  RunOptions options;
  options.out_dir = dir.path() / "out";
  options.progress = false;
  auto run = [&] {
    PluginRegistry registry({testing::PluginDir()});
    const SuiteLoadResult loaded = LoadSuite(file, registry);
    ASSERT_TRUE(loaded.suite);
    RunSuite(*loaded.suite, registry, options);
  };
  run();
  std::ofstream(plugin, std::ios::app) << "rebuilt";  // other bytes: another build
  try {
    run();
    FAIL() << "a rerun of a rebuilt plugin's only row was not refused";
  } catch (const RunRefused& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no row is unchanged"), std::string::npos) << message;
    EXPECT_NE(message.find("plugin files rebuilt since those results: " + plugin.string()),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("--fresh"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace crowdsim
