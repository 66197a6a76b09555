// The ORCA tables do not depend on the processor's vector units: with CROWDSIM_SIMD=off the
// orca plugin computes its agent lines one neighbour at a time (the path of processors without
// AVX2), and the committed ORCA rows, made with the AVX2 path on hand, rerun identically.
// orca_agent_lines_test compares the two paths line by line; this compares whole episodes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/runner.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;
using testing::ReadText;
using testing::TempDir;

// The header line and the lines of `row` of an episodes.csv text.
std::string LinesOfRow(const std::string& csv, const std::string& row) {
  std::istringstream in(csv);
  std::string line, out;
  std::getline(in, line);
  out = line + "\n";
  while (std::getline(in, line)) {
    if (line.rfind(row + ",", 0) == 0) out += line + "\n";
  }
  return out;
}

class OrcaScalarPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Read by the plugin at its first decision, which comes after this (one test per process).
    setenv("CROWDSIM_SIMD", "off", 1);
    fs::current_path(testing::SourceDir());  // the suites name world files from the root
  }
  void TearDown() override { unsetenv("CROWDSIM_SIMD"); }

  // Reruns `row` of suites/<suite>.yaml alone and compares its episodes with results/<suite>/.
  void ExpectRowReruns(const std::string& suite_name, const std::string& row, int episodes) {
    const SuiteLoadResult loaded =
        LoadSuite(testing::SourceDir() / "suites" / (suite_name + ".yaml"), registry_);
    ASSERT_TRUE(loaded.suite) << suite_name;
    Suite suite = *loaded.suite;
    std::erase_if(suite.rows, [&](const RowSpec& r) { return r.label != row; });
    suite.summaries.clear();
    ASSERT_EQ(suite.rows.size(), 1u) << "no row " << row << " in " << suite_name;
    RunOptions o;
    o.out_dir = dir_.path() / row;
    o.jobs = 2;
    o.progress = false;
    RunSuite(suite, registry_, o);
    const std::string ours = WithoutTimingColumns(ReadText(o.out_dir / "episodes.csv"));
    const std::string committed =
        LinesOfRow(WithoutTimingColumns(
                       ReadText(testing::SourceDir() / "results" / suite_name / "episodes.csv")),
                   row);
    EXPECT_EQ(std::count(committed.begin(), committed.end(), '\n'), 1 + episodes);
    EXPECT_EQ(ours, committed) << row << " of " << suite_name << " differs from results/"
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
