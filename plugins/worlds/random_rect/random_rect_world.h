// The `random_rect` world: frozen random rectangle rooms, one layout per episode (cycled),
// with the robot's trip and the humans drawn from the episode seed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "crowdsim/human_placement.h"
#include "crowdsim/params.h"
#include "crowdsim/world_file.h"
#include "crowdsim/world_source.h"

namespace crowdsim::random_rect {

/// How scenarios are drawn inside a layout.
struct ScenarioOptions {
  double min_start_goal_dist = 7.0;  ///< m; robot start to goal
  double human_goal_min_dist = 3.0;  ///< m; a human goal from the point before it (if room allows)
  int new_goal_count = 16;           ///< goals per human when humans get new goals
  double clearance_margin = 0.1;     ///< m; free space beyond an agent's radius at starts and goals
  double passage_padding = kDefaultPassagePadding;  ///< m; PassableGoalClearance's padding
  int max_tries = 100000;                           ///< robot start/goal draws before giving up
};

/// Parameters of the plugin (obstacles, split, file, ...).
ParamSchema Schema();

/// Scenarios in frozen random rooms; maps are built once and shared by every scenario.
class RandomRectWorld final : public WorldSource {
 public:
  /// From validated plugin parameters; reads the world set. Throws std::runtime_error with the
  /// file, what is wrong and the fix.
  explicit RandomRectWorld(const Params& params);
  /// From layouts already in memory (tests, tools); `layouts` non-empty.
  RandomRectWorld(std::vector<WorldFile> layouts, ScenarioOptions options, std::string identity);

  /// The frozen set a configuration without `file` reads (none for 0 obstacles): its
  /// contents enter the config hash (PluginDescriptor::data_files).
  static std::vector<std::filesystem::path> DataFiles(const Params& params);

  /// "random_rect:obstacles=N:split=S" (or "random_rect:file=NAME"), plus non-default options.
  std::string Identity() const override { return identity_; }
  /// Number of layouts in the set (1 for the empty room).
  int LayoutCount() const override { return static_cast<int>(maps_.size()); }
  /// Layout episode_index mod LayoutCount(); thread-safe (reads immutable state only).
  Scenario Make(const ScenarioRequest& request) const override;

 private:
  void BuildMaps(const std::vector<WorldFile>& layouts);

  ScenarioOptions options_;
  std::string identity_;
  std::vector<std::shared_ptr<const StaticMap>> maps_;  // built once, shared by all scenarios
};

}  // namespace crowdsim::random_rect
