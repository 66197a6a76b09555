#include "suite_runs.h"

#include <stdexcept>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "temp_dir.h"

namespace crowdsim::testing {

SuiteRun RunSuiteFile(const std::filesystem::path& suite_file, const std::filesystem::path& out_dir,
                      int jobs) {
  PluginRegistry registry;
  SuiteLoadResult loaded = LoadSuite(suite_file, registry);
  if (!loaded.suite) {
    throw std::runtime_error(loaded.errors.empty() ? "no suite" : loaded.errors[0].Format());
  }
  RunOptions options;
  options.out_dir = out_dir;
  options.jobs = jobs;
  options.progress = false;
  const RunSummary summary = RunSuite(*loaded.suite, registry, options);
  return {WithoutTimingColumns(ReadText(out_dir / "episodes.csv")), summary.rows.size()};
}

std::vector<SuiteRun> RunOnOneAndTwoThreads(const std::filesystem::path& suite_file,
                                            const std::filesystem::path& out_dir) {
  return {RunSuiteFile(suite_file, out_dir / "1", 1), RunSuiteFile(suite_file, out_dir / "2", 2)};
}

}  // namespace crowdsim::testing
