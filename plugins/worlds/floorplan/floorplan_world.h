// The `floorplan` world plugin: episodes in an imported real floor plan. The robot's start
// and goal are the precomputed pairs of the chosen split (episode k uses pair k mod count);
// humans stand on the world's free points.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/world_file.h"
#include "crowdsim/world_source.h"

namespace crowdsim::floorplan {

/// Immutable after construction, so one instance serves every worker thread.
class FloorplanWorld final : public WorldSource {
 public:
  /// Reads the world file named by params "world"; throws WorldFileError / invalid_argument.
  explicit FloorplanWorld(const Params& params);
  /// The world file, wherever it was found (a suite's folder or the data root): its contents
  /// enter the config hash (PluginDescriptor::data_files).
  static std::vector<std::filesystem::path> DataFiles(const Params& params);
  std::string Identity() const override;
  int LayoutCount() const override { return 1; }
  Scenario Make(const ScenarioRequest& request) const override;

 private:
  std::string split_;
  double passage_padding_ = 0.0;  ///< m; PassableGoalClearance's padding
  std::string name_;
  std::shared_ptr<const StaticMap> map_;
  std::vector<StartGoal> pairs_;
  std::vector<Vec2> free_points_;
};

/// The plugin's parameters: world (path), split (train|test).
ParamSchema Schema();

}  // namespace crowdsim::floorplan
