// Params::ResolvePath: where a relative file named by a plugin parameter (weights, a world file)
// is looked for, and what a missing one resolves to (the path an error message names).
#include "crowdsim/params.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "crowdsim/data_root.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;

class ResolvePathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // A folder of this test's own: ctest runs the tests of this file in parallel processes.
    root_ = fs::path(::testing::TempDir()) /
            ("resolve_path_" +
             std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
             std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "suites");
    fs::create_directories(root_ / "cwd");
    old_cwd_ = fs::current_path();
    fs::current_path(root_ / "cwd");
  }
  void TearDown() override {
    fs::current_path(old_cwd_);
    fs::remove_all(root_);
  }
  static void Touch(const fs::path& p) { std::ofstream(p) << "x"; }

  fs::path root_, old_cwd_;
};

TEST_F(ResolvePathTest, SuiteFolderFirstThenWorkingFolder) {
  const Params params({}, root_ / "suites");
  Touch(root_ / "cwd" / "only_here.pt");
  EXPECT_EQ(params.ResolvePath("only_here.pt"), fs::path("only_here.pt"));
  Touch(root_ / "suites" / "only_here.pt");  // now in both: the suite's folder wins
  EXPECT_EQ(params.ResolvePath("only_here.pt"), root_ / "suites" / "only_here.pt");
  EXPECT_EQ(params.ResolvePath("/abs/file.pt"), fs::path("/abs/file.pt"));
}

TEST_F(ResolvePathTest, AMissingFileResolvesIntoTheSuiteFolder) {
  // So that "weights file '...' does not exist" names the folder the suite's paths start from.
  EXPECT_EQ(Params({}, root_ / "suites").ResolvePath("runs/a2c.pt"),
            root_ / "suites" / "runs" / "a2c.pt");
  EXPECT_EQ(Params().ResolvePath("runs/a2c.pt"), fs::path("runs/a2c.pt"));  // no suite folder
}

TEST_F(ResolvePathTest, ThenTheDataRoot) {
  // An installed suite names its shipped weights relative to the project's root
  // (results/models/...): found in the data root (the install's share folder) from anywhere.
  fs::create_directories(root_ / "data" / "results" / "models");
  Touch(root_ / "data" / "results" / "models" / "best.pt");
  const char* old = std::getenv("CROWDSIM_DATA_DIR");
  const std::string kept = old ? old : "";
  ::setenv("CROWDSIM_DATA_DIR", (root_ / "data").c_str(), 1);
  const Params params({}, root_ / "suites");
  EXPECT_EQ(params.ResolvePath("results/models/best.pt"),
            root_ / "data" / "results" / "models" / "best.pt");
  Touch(root_ / "cwd" / "best.pt");  // the working folder still comes first
  EXPECT_EQ(params.ResolvePath("best.pt"), fs::path("best.pt"));
  if (old) {
    ::setenv("CROWDSIM_DATA_DIR", kept.c_str(), 1);
  } else {
    ::unsetenv("CROWDSIM_DATA_DIR");
  }
}

TEST_F(ResolvePathTest, AMissingFileIsNamedWithEveryPlaceLookedIn) {
  // As ResolvePath looks: the suite's folder, the working folder, the data root, in that order
  // (the missing file's suite-folder path alone read as if that were the one place).
  const std::string root = DataRoot().string();
  EXPECT_EQ(Params({}, "my").MissingFile("results/models/nothere/best.pt"),
            "'results/models/nothere/best.pt' not found (looked in the suite's folder my, the "
            "working folder and " +
                root + ")");
  EXPECT_EQ(
      Params({}, ".").MissingFile("a.pt"),
      "'a.pt' not found (looked in the suite's folder (the working folder) and " + root + ")");
  // No suite folder: ResolvePath looks in the working folder only.
  EXPECT_EQ(Params().MissingFile("a.pt"), "'a.pt' not found (looked in the working folder)");
  // An absolute path is looked for where it says.
  EXPECT_EQ(Params({}, "my").MissingFile("/abs/a.pt"), "'/abs/a.pt' does not exist");
}

}  // namespace
}  // namespace crowdsim
