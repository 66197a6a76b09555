// The committed tables of learned policies rerun identically on this processor. OpenBLAS picks
// its kernels by processor, and kernels that round differently flip a decision between two
// nearly equal actions now and then (on AMD Zen 4, whose AVX-512 kernels differ from the
// Haswell kernels the tables were made with: episode 417 of Table 1's line 13, episodes 302
// and 475 of line 4 with 3 obstacles). The harness pins the Haswell kernels before it loads a
// plugin (harness/host/loader/blas_kernel.h); this test reruns those rows from their suites and
// compares every episode with results/. It needs the learned policies' plugins (a build with
// libtorch) and must not link libtorch itself: OpenBLAS would be loaded before the pin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "committed_rows.h"
#include "loader/blas_kernel.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

class CommittedLearnedRowsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // The suites name weights and world files relative to the repository root.
    fs::current_path(testing::SourceDir());
    const std::string skip = testing::LearnedRowsSkipReason();
    if (!skip.empty()) GTEST_SKIP() << skip;
  }

  // Reruns `row` of suites/<suite>.yaml alone and compares its episodes with results/<suite>/.
  void ExpectRowReruns(const std::string& suite_name, const std::string& row) {
    const testing::RowRerun r =
        testing::RerunCommittedRow(registry_, dir_.path() / row, suite_name, row);
    EXPECT_EQ(std::count(r.committed.begin(), r.committed.end(), '\n'), 1 + 500);
    EXPECT_EQ(r.rerun, r.committed) << row << " of " << suite_name << " differs from results/"
                                    << suite_name << " with OPENBLAS_CORETYPE=" << BlasCoreType();
  }

  TempDir dir_;
  PluginRegistry registry_{{testing::PluginDir()}};
};

TEST_F(CommittedLearnedRowsTest, SarlRowOfTable1RerunsIdentically) {
  ExpectRowReruns("table1", "line13_sarl_pp_lidar_person_rect0");
}

TEST_F(CommittedLearnedRowsTest, CadrlRowOfTable1With3ObstaclesRerunsIdentically) {
  ExpectRowReruns("table1_3obs", "line04_cadrl_pp_lidar_rect1_nohumans");
}

// A PPO row: a TorchScript module, whose tanh and softmax run in ATen's own SIMD kernels (its
// AVX2 and AVX-512 kernels give the same episodes; docs/reproducibility.md).
TEST_F(CommittedLearnedRowsTest, PpoRowRerunsIdentically) {
  if (!fs::exists(testing::PluginDir() / "crowdsim_torchscript.so")) {
    GTEST_SKIP() << "no torchscript plugin in this build";
  }
  ExpectRowReruns("ppo", "ppo_s1");
}

// An OPENBLAS_CORETYPE set before the harness runs (a user's, or an environment that avoids a
// kernel known to fail on its processor) is left as it is.
TEST(PinBlasKernel, LeavesAChoiceMadeOutsideAlone) {
  const char* before = std::getenv("OPENBLAS_CORETYPE");
  const std::string saved = before != nullptr ? before : "";
  setenv("OPENBLAS_CORETYPE", "Sandybridge", 1);
  PinBlasKernel();
  EXPECT_EQ(BlasCoreType(), "Sandybridge");
  if (before != nullptr) {
    setenv("OPENBLAS_CORETYPE", saved.c_str(), 1);
  } else {
    unsetenv("OPENBLAS_CORETYPE");
  }
}

}  // namespace
}  // namespace crowdsim
