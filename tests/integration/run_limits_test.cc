// A run within the system's limits: no more worker threads than episodes, and a thread the
// system refuses is an error naming --jobs, not an abort (each case in a child process whose
// address space is limited, as a cluster job's may be).
#include <gtest/gtest.h>
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "crowdsim/bench/runner.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

// One row of straight-line robots among three ORCA people.
constexpr const char* kSuite =
    "{name: limits, episodes: 6, seed: 3, world: {source: random_rect, obstacles: 1}, "
    "humans: {count: 3, policy: orca}, rows: [{label: linear, policy: linear}]}\n";

// The process's virtual size in bytes (/proc/self/statm's first field is in pages).
long VirtualBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0;
  statm >> pages;
  return pages * sysconf(_SC_PAGESIZE);
}

// Runs the suite with `jobs` and `episodes` in a child whose address space may grow by
// `headroom` bytes (one malloc arena, so threads cost their stacks alone). The child's exit
// code: 0 run finished, 3 RunError holding `expected`, 4 another error; a signal is an abort.
int RunLimited(const std::string& suite_file, int jobs, int episodes, long headroom,
               const std::string& expected, const std::filesystem::path& out) {
  const pid_t pid = fork();
  if (pid == 0) {
    PluginRegistry registry{{testing::PluginDir()}};
    SuiteLoadResult loaded = LoadSuite(suite_file, registry);
    if (!loaded.suite) _exit(5);
    mallopt(M_ARENA_MAX, 1);
    const rlimit limit{static_cast<rlim_t>(VirtualBytes() + headroom),
                       static_cast<rlim_t>(VirtualBytes() + headroom)};
    setrlimit(RLIMIT_AS, &limit);
    RunOptions o;
    o.out_dir = out;
    o.jobs = jobs;
    o.episodes = episodes;
    o.progress = false;
    try {
      RunSuite(*loaded.suite, registry, o);
      _exit(0);
    } catch (const RunError& e) {
      _exit(std::string(e.what()).find(expected) != std::string::npos ? 3 : 4);
    } catch (...) {
      _exit(4);
    }
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(RunLimits, JobsBeyondTheEpisodesStartNoThreads) {
  testing::TempDir dir;
  const auto suite = dir.Write("suite.yaml", kSuite);
  // 600 threads would reserve 4.8 GB of stacks; 6 episodes need 6 threads.
  EXPECT_EQ(RunLimited(suite.string(), 600, 6, 256L << 20, "", dir.path() / "out"), 0);
  std::ifstream table(dir.path() / "out" / "table.md");
  EXPECT_TRUE(table.good()) << "the run wrote no table";
}

TEST(RunLimits, AThreadTheSystemRefusesIsAnErrorNamingJobs) {
  testing::TempDir dir;
  const auto suite = dir.Write("suite.yaml", kSuite);
  // 200 threads' stacks (8 MB each) do not fit in 96 MB more: the run stops, saying so.
  EXPECT_EQ(RunLimited(suite.string(), 200, 200, 96L << 20, "rerun with fewer --jobs",
                       dir.path() / "out"),
            3);
}

}  // namespace
}  // namespace crowdsim
