// The lidar's readings do not depend on the processor's vector units: with CROWDSIM_SIMD=off
// the scan meets its beams one at a time (the path of processors without AVX2), and a committed
// row of a learned policy that sees through the lidar reruns identically. beam_scan_test
// compares the two beam kernels scan by scan; this compares whole episodes, whose every
// decision the ranges feed. It needs the learned policies' plugins (a build with libtorch).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "committed_rows.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;

class LidarScalarPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::current_path(testing::SourceDir());  // the suites name weights from the root
    const std::string skip = testing::LearnedRowsSkipReason();
    if (!skip.empty()) GTEST_SKIP() << skip;
    // Read by the core at its first scan, which comes after this (one test per process).
    setenv("CROWDSIM_SIMD", "off", 1);
  }
  void TearDown() override { unsetenv("CROWDSIM_SIMD"); }

  testing::TempDir dir_;
  PluginRegistry registry_{{testing::PluginDir()}};
};

// CADRL++ with the lidar alone, tested among three rectangles and five humans: 45 beams a step.
TEST_F(LidarScalarPathTest, CadrlLidarRowRerunsIdentically) {
  const std::string row = "line04_cadrl_pp_lidar_rect1_nohumans";
  const testing::RowRerun r =
      testing::RerunCommittedRow(registry_, dir_.path() / row, "table1_3obs", row);
  EXPECT_EQ(std::count(r.committed.begin(), r.committed.end(), '\n'), 1 + 500);
  EXPECT_EQ(r.rerun, r.committed) << row << " of table1_3obs differs from results/table1_3obs "
                                  << "on the scalar path (CROWDSIM_SIMD=off)";
}

}  // namespace
}  // namespace crowdsim
