// Runs a suite: every (row, episode) in parallel worker threads with their own plugin
// instances, results written as episodes finish, resumable.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/results.h"
#include "crowdsim/suite.h"

namespace crowdsim {

class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOptions {
  std::filesystem::path out_dir;  ///< default: results/<suite name>/ under the working dir
  int jobs = 1;                   ///< worker threads
  int episodes = -1;              ///< overrides the suite's count when > 0
  bool fresh = false;             ///< discard stored episodes instead of resuming
  bool progress = true;           ///< progress line on stderr
};

struct RunSummary {
  std::vector<TableRow> rows;
  std::string table_markdown;
  int episodes_run = 0;      ///< this invocation
  int episodes_resumed = 0;  ///< found on disk
  std::filesystem::path out_dir;
};

/// Runs the suite and writes DIR/{episodes.csv, table.md, table.csv, manifest.json}.
/// Throws RunError for problems that stop the whole run (output folder, mismatched results).
RunSummary RunSuite(const Suite& suite, PluginRegistry& registry, const RunOptions& options);

}  // namespace crowdsim
