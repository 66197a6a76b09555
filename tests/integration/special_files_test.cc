// Named pipes (FIFOs) given where a file belongs: as the suite, as a world `file:` and as
// weights, each is an error naming the path, never a wait for a writer that never comes.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "crowdsim/input_file.h"
#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::Shell;

class SpecialFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    fifo_ = (dir_.path() / "pipe").string();
    ASSERT_EQ(mkfifo(fifo_.c_str(), 0600), 0);
  }
  // `validate` on `suite` under a 30 s bound: (exit code, output); 124 is a hang.
  std::pair<int, std::string> Validate(const std::string& suite) {
    const std::string exe = (testing::BinaryDir() / "bin" / "crowdsim-bench").string();
    return Shell("cd " + testing::SourceDir().string() + " && timeout 30 " + exe + " validate " +
                 suite + " 2>&1");
  }

  testing::TempDir dir_;
  std::string fifo_;
};

TEST_F(SpecialFiles, TheKindOfAFileIsToldWithoutOpeningIt) {
  EXPECT_EQ(NotARegularFile(testing::SourceDir() / "suites" / "quick.yaml"), "");
  EXPECT_EQ(NotARegularFile(fifo_).rfind("is a named pipe (FIFO)", 0), 0u);
  EXPECT_EQ(NotARegularFile(dir_.path()), "is a folder");
  EXPECT_EQ(NotARegularFile(dir_.path() / "none"), "does not exist");
  EXPECT_EQ(NotARegularFile("/dev/null"), "is a device, not a file");
}

TEST_F(SpecialFiles, APipeAsTheSuiteIsAnError) {
  const auto [rc, text] = Validate(fifo_);
  EXPECT_EQ(rc, 2) << text;
  EXPECT_NE(text.find(fifo_), std::string::npos) << text;
}

TEST_F(SpecialFiles, APipeAsAWorldFileIsAnError) {
  const auto suite =
      dir_.Write("s.yaml", "name: s\nepisodes: 2\nworld: {source: floorplan, file: " + fifo_ +
                               ", split: test}\nhumans: {count: 2, policy: orca}\nrows:\n"
                               "  - {label: linear, policy: linear}\n");
  const auto [rc, text] = Validate(suite.string());
  EXPECT_EQ(rc, 2) << text;
  EXPECT_NE(text.find(fifo_), std::string::npos) << text;
}

TEST_F(SpecialFiles, APipeAsWeightsIsAnErrorNamingWhatItIs) {
  for (const std::string policy : {"cadrl", "torchscript"}) {
    if (!std::filesystem::exists(testing::PluginDir() / ("crowdsim_" + policy + ".so"))) {
      GTEST_SKIP() << "built without libtorch: no " << policy << " plugin";
    }
    const auto suite =
        dir_.Write(policy + ".yaml",
                   "name: w\nepisodes: 2\nworld: {source: random_rect, obstacles: 1, split: test}\n"
                   "humans: {count: 2, policy: orca}\nrobot: {sensors: [person]}\nrows:\n"
                   "  - {label: l, policy: " +
                       policy + ", weights: " + fifo_ +
                       (policy == "cadrl" ? ", params: {sensors: person}" : "") + "}\n");
    const auto [rc, text] = Validate(suite.string());
    EXPECT_EQ(rc, 2) << policy << ": " << text;
    EXPECT_NE(text.find("is a named pipe (FIFO)"), std::string::npos) << policy << ": " << text;
  }
}

}  // namespace
}  // namespace crowdsim
