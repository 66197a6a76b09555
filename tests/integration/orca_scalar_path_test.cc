// The ORCA tables do not depend on the processor's vector units: with CROWDSIM_SIMD=off the
// orca plugin computes its agent lines one neighbour at a time (the path of processors without
// AVX2), and the committed ORCA rows, made with the AVX2 path on hand, rerun identically.
// orca_agent_lines_test compares the two paths line by line; this compares whole episodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "committed_rows.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::TempDir;

class OrcaScalarPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Read by the plugin at its first decision, which comes after this (one test per process).
    setenv("CROWDSIM_SIMD", "off", 1);
  }
  void TearDown() override { unsetenv("CROWDSIM_SIMD"); }

  // Reruns `row` of suites/<suite>.yaml alone and compares its episodes with results/<suite>/.
  void ExpectRowReruns(const std::string& suite_name, const std::string& row, int episodes) {
    const testing::RowRerun r =
        testing::RerunCommittedRow(registry_, dir_.path() / row, suite_name, row);
    EXPECT_EQ(std::count(r.committed.begin(), r.committed.end(), '\n'), 1 + episodes);
    EXPECT_EQ(r.rerun, r.committed) << row << " of " << suite_name << " differs from results/"
                                    << suite_name << " on the scalar path (CROWDSIM_SIMD=off)";
  }

  TempDir dir_;
  PluginRegistry registry_{{testing::PluginDir()}};
};

// CrowdNav's task: the robot and five humans all ORCA, four or five neighbours a decision.
TEST_F(OrcaScalarPathTest, CrowdNavOrcaRowRerunsIdentically) {
  ExpectRowReruns("crowdnav_orca", "orca", 500);
}

// Among three rectangles: obstacle lines before the agent lines.
TEST_F(OrcaScalarPathTest, OrcaAmongThreeRectanglesRerunsIdentically) {
  ExpectRowReruns("baselines", "orca_rect3", 500);
}

}  // namespace
}  // namespace crowdsim
