// Params::ResolvePath: where a relative file named by a plugin parameter (weights, a world file)
// is looked for, and what a missing one resolves to (the path an error message names).
#include "crowdsim/params.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace
}  // namespace crowdsim
