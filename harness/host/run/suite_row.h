// One suite row as a run owns it: its name in messages, world, preflight and episodes. The runner
// asks it, not the suite.
#pragma once

#include <filesystem>
#include <memory>
#include <set>
#include <string>

#include "crowdsim/bench/results.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "run/worker_process.h"

namespace crowdsim {

class SuiteRow {
 public:
  SuiteRow(const Suite& suite, size_t index) : suite_(suite), index_(index) {}

  const RowSpec& spec() const { return suite_.rows[index_]; }
  /// "row 'orca' (rows[1])": how preflight errors name the row.
  std::string Place() const;
  /// "row 'orca', episode 3": how run errors name an episode.
  std::string Where(int episode) const;

  /// Builds the row's world and plugins once (the plugins in a worker process when `mode` isolates
  /// the row), checks sensor needs and the scenarios of episode 0 and each frozen layout among the
  /// first `episodes`, and plays episode 0's first step in-process when not isolated. `checked`:
  /// (world, crowd) pairs passed. Throws RunError naming the row.
  /// A threaded row's plugins taking `slow_note_s` to make are named on stderr.
  void Preflight(PluginRegistry& registry, int episodes, IsolationMode mode,
                 std::set<std::string>* checked, double slow_note_s = kSlowEpisodeNoteS);
  /// Run writes each episode's log into `dir`/<row number>_<label>/ (empty: none).
  void RecordTo(const std::filesystem::path& dir) { record_dir_ = dir; }

  /// The world Preflight built; null before.
  const std::shared_ptr<WorldSource>& world() const { return world_; }

  /// Episode `episode` as the CLI runs it, with its line for episodes.csv.
  EpisodeLine Run(RowInstance& instance, int episode) const;
  /// The line of an episode whose worker dies or is killed: no result, its own status.
  EpisodeLine Lost(int episode, const WorkerLoss& loss) const;

 private:
  void CheckEveryLayout(int episodes, std::set<std::string>* checked) const;
  std::unique_ptr<RowInstance> MakePlugins(PluginRegistry& registry) const;
  void MakePluginsInWorker(PluginRegistry& registry) const;
  void CheckFirstStep(RowInstance& instance, const Scenario& episode0) const;
  std::string Suspects() const;
  void WriteLog(const Episode& played, int episode) const;

  const Suite& suite_;
  size_t index_;
  std::shared_ptr<WorldSource> world_;
  std::filesystem::path record_dir_;
};

}  // namespace crowdsim
