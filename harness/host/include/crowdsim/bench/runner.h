// Runs a suite's (row, episode) pairs in worker threads, or in worker processes that a crashing
// plugin cannot take down; results written as episodes finish, resumable.
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

/// A run or merge refused before acting: its inputs do not fit together (another configuration's
/// folder, shards of different runs). The CLI exits 2 for it, 1 for failures while running.
class RunRefused : public RunError {
 public:
  using RunError::RunError;
};

/// Rows that cannot run, found by preflight: one message per row, each naming it; what() joins them
/// with newlines.
class RowsRefused : public RunRefused {
 public:
  explicit RowsRefused(std::vector<std::string> errors);
  const std::vector<std::string>& errors() const { return errors_; }

 private:
  std::vector<std::string> errors_;
};

/// The ranges of a run's worker count and episode count (--jobs/--episodes, jobs=/episodes=).
inline constexpr int kMaxJobs = 1024;
inline constexpr int kMaxEpisodes = 10'000'000;

/// A worker process's episode is killed (policy_timeout) after this many seconds unless the suite
/// sets episode_timeout_s; a threaded run names an episode on stderr once it runs
/// kSlowEpisodeNoteS.
inline constexpr double kDefaultEpisodeTimeoutS = 600.0;
inline constexpr double kSlowEpisodeNoteS = 60.0;

struct RunOptions {
  std::filesystem::path out_dir;  ///< default: DefaultRunDir(suite)
  int jobs = 1;                   ///< worker threads, or worker processes when isolated
  /// Overrides the suite's `isolation` when set (off for a policy in this process's Python, which a
  /// forked worker must not run).
  std::optional<IsolationMode> isolation;
  int episodes = -1;   ///< overrides the suite's count when > 0
  bool fresh = false;  ///< discard stored episodes instead of resuming
  /// Writes each episode run's log (docs/episode_log.md) under out_dir/logs/.
  bool record = false;
  bool progress = true;  ///< progress line on stderr
  /// Shard `shard_index` (1-based) of `shard_count`: the pairs whose row-major position is
  /// shard_index - 1 modulo shard_count; writes no table (`merge` joins shards). 1 of 1 is the
  /// whole suite.
  int shard_index = 1;
  int shard_count = 1;
  /// The caller already holds `out_dir` (lock and kind checked, as merge does): the run does not
  /// claim it again.
  bool out_dir_claimed = false;
  /// The run joins shards' stored episodes (merge): its manifest says `"merged": true`.
  bool merge = false;
  /// Isolated runs: an episode's bound when the suite sets no episode_timeout_s.
  double default_episode_timeout_s = kDefaultEpisodeTimeoutS;
  /// Threaded runs: an episode running this long is named on stderr, and again at each doubling.
  double slow_episode_note_s = kSlowEpisodeNoteS;
  /// Asked between episodes, from any worker thread; true stops the run as AbortRun does, keeping
  /// finished episodes; RunSuite throws RunError. Python checks Ctrl-C here, as it runs only
  /// between calls into C++.
  std::function<bool()> stop_requested;
};

/// The 1-based shard that runs (`row`, `episode`) when each row runs `episodes`: row-major position
/// modulo `shards` (>= 1).
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
  /// Per row with policy_error episodes (run or resumed): their count and the first message, which
  /// the table alone does not show.
  std::vector<PolicyErrorNote> policy_errors;
};

/// Joins one suite run's shard folders into `out_dir` and writes the tables as one run would. The
/// shards must share configuration (config hash, episode count), cover every (row, episode) once,
/// and share git_commit unless `allow_mixed_commits`. `suite_file` empty: the manifests'. The
/// manifest records shards_git_commit ("mixed" if several) and shard_commits. Throws RunError
/// naming the folders at fault.
RunSummary MergeShards(const std::vector<std::filesystem::path>& shard_dirs,
                       const std::filesystem::path& out_dir,
                       const std::filesystem::path& suite_file, PluginRegistry& registry,
                       bool allow_mixed_commits = false);

/// A run's folder without --out: runs/<suite name>/ under the working folder (git-ignored), so
/// results/ changes only through an explicit --out.
std::filesystem::path DefaultRunDir(const Suite& suite);

/// What `validate` checks: run's preflight (every row's plugins and files built once, robot sensor
/// needs, the first scenario of each frozen layout of the harness's worlds, else episode 0), then
/// episode 0's first step in-process for rows of only the harness's plugins (another's crash would
/// end validate). Returns one message per failing row, naming it; empty when all can run.
std::vector<std::string> PreflightSuite(const Suite& suite, PluginRegistry& registry);

/// Runs the suite and writes DIR/{episodes.csv, table.md, table.csv, manifest.json}.
/// Throws RunError for problems that stop the whole run (output folder, mismatched results).
RunSummary RunSuite(const Suite& suite, PluginRegistry& registry, const RunOptions& options);

/// Writes a running RunSuite's pending episodes (at most the last 200 ms) to episodes.csv;
/// async-signal-safe, for a Ctrl-C handler that then exits.
void FlushPendingEpisodesForSignal() noexcept;

}  // namespace crowdsim
