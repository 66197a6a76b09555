// Runs a suite: every (row, episode) in parallel worker threads with their own plugin
// instances, or in worker processes that a crashing or hanging plugin cannot take down with the
// run (isolation), results written as episodes finish, resumable.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/bench/results.h"
#include "crowdsim/bench/suite.h"

namespace crowdsim {

class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run or merge refused before it did anything: its inputs do not fit together (a folder of
/// another configuration or shard, shards that are not one run). The CLI exits 2 for it, as for
/// a usage or validation error; 1 stays for what failed while running.
class RunRefused : public RunError {
 public:
  using RunError::RunError;
};

/// Rows that cannot run, found before any episode (the preflight of every row): one message per
/// row at fault, each naming its row; what() joins them with newlines.
class RowsRefused : public RunRefused {
 public:
  explicit RowsRefused(std::vector<std::string> errors);
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  std::vector<std::string> errors_;
};

/// The ranges a run takes for its worker count and its episode count (the CLI's --jobs and
/// --episodes, the Python package's jobs= and episodes=).
inline constexpr int kMaxJobs = 1024;
inline constexpr int kMaxEpisodes = 10'000'000;

struct RunOptions {
  std::filesystem::path out_dir;  ///< default: DefaultRunDir(suite)
  int jobs = 1;                   ///< worker threads, or worker processes when isolated
  /// Overrides the suite's `isolation` when set (e.g. off for a policy that lives in this
  /// process's Python interpreter, which a forked worker must not run).
  std::optional<IsolationMode> isolation;
  int episodes = -1;     ///< overrides the suite's count when > 0
  bool fresh = false;    ///< discard stored episodes instead of resuming
  bool progress = true;  ///< progress line on stderr
  /// Shard `shard_index` (1-based) of `shard_count`: only the (row, episode) pairs whose
  /// position in row-major order is shard_index - 1 modulo shard_count; no table is written
  /// (`merge` joins the shards). 1 of 1 is the whole suite.
  int shard_index = 1;
  int shard_count = 1;
  /// The caller already holds `out_dir` (its lock and kind checked), as merge does around
  /// the run that writes the joined tables: the run does not claim it again.
  bool out_dir_claimed = false;
  /// The run joins shards' stored episodes (merge): its manifest says `"merged": true`.
  bool merge = false;
  /// Asked between episodes (from any worker thread); true stops the run as an AbortRun
  /// would: the finished episodes are kept, RunSuite throws RunError. The Python package
  /// checks for Ctrl-C here, which reaches Python code only between calls into C++.
  std::function<bool()> stop_requested;
};

/// The shard (1-based, of `shards`) that runs episode `episode` of row `row` when every row runs
/// `episodes`: its position in row-major order modulo the shard count (RunOptions::shard_index).
/// `shards` >= 1.
int ShardOfEpisode(std::size_t row, int episode, int episodes, int shards);

/// A row's episodes that ended in policy_error (run or resumed) and the first one's message.
struct PolicyErrorNote {
  std::string row;
  int errors = 0;
  int episodes = 0;
  int first_episode = 0;
  std::string first_error;
  /// "row 'a': 20 of 20 episodes ended in policy_error; episode 0: MESSAGE"
  std::string Format() const;
  /// Its last part: "episode 0: MESSAGE".
  std::string First() const;
};

struct RunSummary {
  std::vector<TableRow> rows;
  std::string table_markdown;
  int episodes_run = 0;      ///< this invocation
  int episodes_resumed = 0;  ///< found on disk
  std::filesystem::path out_dir;
  /// Per row whose episodes (run or resumed) ended in policy_error: how many and the first
  /// one's message, for the CLI and the Python package to say; an error is otherwise only a
  /// column of the table.
  std::vector<PolicyErrorNote> policy_errors;
};

/// Joins the output folders of the shards of one suite run into `out_dir` and writes the tables
/// as a single run would: the shards must hold the same configuration (config hash, episode
/// count) and together every (row, episode) exactly once, and have been made by one commit
/// (their manifests' git_commit) unless `allow_mixed_commits`. `suite_file` empty: the
/// manifests'. The merged manifest records the shards' commit (shards_git_commit, "mixed" if
/// several) and each shard's (shard_commits). Throws RunError naming the folders at fault.
RunSummary MergeShards(const std::vector<std::filesystem::path>& shard_dirs,
                       const std::filesystem::path& out_dir,
                       const std::filesystem::path& suite_file, PluginRegistry& registry,
                       bool allow_mixed_commits = false);

/// Where a run writes without an explicit folder: runs/<suite name>/ under the working folder
/// (ignored by git). The committed reference outputs under results/ are only ever written
/// through an explicit --out, so trying a suite in the checkout never changes them.
std::filesystem::path DefaultRunDir(const Suite& suite);

/// What `validate` checks: what `run` does before any episode (builds every row's plugins once:
/// world and its files, sensors, robot and human policies, their weights; checks that each
/// robot has the sensors it needs; makes the scenario of the first episode of each frozen
/// layout of a world of the harness's own, else of episode 0), then plays the first step of
/// episode 0 of each row whose plugins are all the harness's own (in this process; `run`
/// isolates a row with yours, whose crash or hang would end validate). Returns one
/// message per failing row (naming the row and with the plugin's own message); empty when
/// every row can run.
std::vector<std::string> PreflightSuite(const Suite& suite, PluginRegistry& registry);

/// Runs the suite and writes DIR/{episodes.csv, table.md, table.csv, manifest.json}.
/// Throws RunError for problems that stop the whole run (output folder, mismatched results).
RunSummary RunSuite(const Suite& suite, PluginRegistry& registry, const RunOptions& options);

/// Writes the finished episodes a running RunSuite still holds in memory (at most the last
/// 200 ms of them) to its episodes.csv; async-signal-safe, for a handler (Ctrl-C) that ends
/// the process right after.
void FlushPendingEpisodesForSignal() noexcept;

}  // namespace crowdsim
