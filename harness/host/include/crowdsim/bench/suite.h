// A suite: the experiment description (YAML) resolved against the plugins it names.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/kinematics.h"
#include "crowdsim/params.h"
#include "crowdsim/sim_config.h"
#include "crowdsim/world_source.h"

namespace crowdsim {

/// One problem in a suite file, located exactly.
struct SuiteError {
  std::string file;
  int line = 0;          ///< 1-based; 0 = whole file
  int column = 0;        ///< 1-based
  std::string key_path;  ///< e.g. rows[1].sensors[0].beams
  std::string message;   ///< what is wrong, the offending value and the valid choices
  std::string Format() const;
};

/// A plugin chosen in the suite, with validated parameters.
struct PluginUse {
  std::string plugin;                    ///< name or .so path as written
  const LoadedPlugin* loaded = nullptr;  ///< owned by the registry
  Params params;
};

/// A per-person attribute: one value (lo == hi), or drawn uniformly from [lo, hi] per person.
struct AttributeRange {
  double lo = 0.0;
  double hi = 0.0;
};

/// `humans.groups`: people who walk together (docs/humans.md).
struct GroupsSpec {
  double share = 0.0;  ///< of the people, the share who walk in groups (rounded to whole people)
  int size_min = 2;    ///< a group's size, drawn uniformly in [size_min, size_max]
  int size_max = 3;
};

/// The humans of a row.
struct HumansSpec {
  int count = 5;      ///< humans per episode; the least of a range
  int count_max = 5;  ///< the most: `count` itself, or a training file's range [count, count_max]
  PluginUse policy;
  HumanGoalMode goal_mode = HumanGoalMode::kStay;
  std::optional<AttributeRange> radius;  ///< `radius:` (m); unset: sim.human_radius for all
  std::optional<AttributeRange> v_pref;  ///< `v_pref:` (m/s); unset: sim.human_v_pref for all
  double distracted = 0.0;           ///< `distracted:` chance that a person never sees the robot
  std::optional<GroupsSpec> groups;  ///< `groups:`; unset: everybody walks alone
  /// Whether people differ from the sim's one person (the harness then draws their attributes).
  bool Varied() const { return radius || v_pref || distracted > 0.0 || groups; }
};

/// Published values of a row (e.g. the paper's), shown beside ours; never in results or hash.
struct PublishedReference {
  std::optional<double> success;
  std::optional<double> collision;
  std::optional<double> timeout;
  std::optional<double> nav_time;
  std::optional<double> danger;
  std::string source;  ///< e.g. "CrowdSim++ Table 1, line 10"
};

/// One table row: a robot policy with its sensors in a world with humans.
struct RowSpec {
  std::string label;
  PluginUse policy;
  std::vector<PluginUse> sensors;
  RobotKinematics kinematics;  ///< `kinematics:`, else the suite's `robot.kinematics`
  PluginUse world;
  HumansSpec humans;
  std::vector<std::pair<std::string, std::string>> info;  ///< extra table columns (model, ...)
  std::optional<PublishedReference> reference;
  /// Canonical text of what decides this row's episodes: an unchanged row hash resumes, whatever
  /// other rows do.
  std::string canonical;
  std::string ConfigHash() const;
};

/// A summary line under the rows (e.g. Table 2's average): the mean of the named rows.
struct SummarySpec {
  std::string label;
  std::vector<std::string> rows;  ///< labels of the rows it averages, in suite order
  std::vector<std::pair<std::string, std::string>> info;
  std::optional<PublishedReference> reference;
};

/// Whether episodes run in worker processes, so a crashing or hanging plugin spares the run. kAuto:
/// isolated for user plugins or a timeout.
enum class IsolationMode { kAuto, kOn, kOff };

struct Suite {
  std::string name;
  std::string description;
  std::filesystem::path file;
  int episodes = 500;
  std::uint64_t seed = 0;
  SimConfig sim;
  std::vector<std::string> info_columns;  ///< order of the extra columns
  /// Social metrics named in `columns:` (table.md shows them); naming one turns its family on:
  /// episodes.csv, table.csv and manifest.json carry them (docs/metrics.md). Hashed when on.
  std::vector<std::string> metric_columns;
  unsigned social_metrics = 0;  ///< MetricFamilies (episode_columns.h) of the named metrics
  std::vector<RowSpec> rows;
  std::vector<SummarySpec> summaries;  ///< shown after the rows; not part of the config hash
  std::vector<std::string> overrides;  ///< `--set key.path=value` applied to the file, in order
  /// `isolation:` and `episode_timeout_s:` (seconds before a worker is killed, policy_timeout; 0:
  /// none). Not hashed.
  IsolationMode isolation = IsolationMode::kAuto;
  double episode_timeout_s = 0.0;
  /// Canonical text of what decides the results (not the episode count); its hash gates resume.
  std::string canonical;
  std::string ConfigHash() const;
};

struct SuiteLoadResult {
  std::optional<Suite> suite;
  std::vector<SuiteError> errors;  ///< every error found (empty when suite is set)
};

/// Reads and validates a suite, loading its plugins. `overrides` (`--set`) apply first, then sweeps
/// expand.
SuiteLoadResult LoadSuite(const std::filesystem::path& file, PluginRegistry& registry,
                          const std::vector<std::string>& overrides = {});

}  // namespace crowdsim
