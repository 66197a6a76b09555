// A suite file run as the CLI runs it, for tests that compare runs (e.g. on 1 and 2 threads).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace crowdsim::testing {

/// What a run left: its episodes.csv without the timing columns, and the table's row count.
struct SuiteRun {
  std::string episodes;
  std::size_t rows = 0;
};

/// Loads `suite_file` (throws std::runtime_error with its first error) and runs it on `jobs`
/// threads into `out_dir`.
SuiteRun RunSuiteFile(const std::filesystem::path& suite_file, const std::filesystem::path& out_dir,
                      int jobs);

/// Runs `suite_file` on one thread and on two (into out_dir/1 and out_dir/2): what each left.
std::vector<SuiteRun> RunOnOneAndTwoThreads(const std::filesystem::path& suite_file,
                                            const std::filesystem::path& out_dir);

}  // namespace crowdsim::testing
