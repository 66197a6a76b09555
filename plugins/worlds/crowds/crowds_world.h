// The `crowds` world plugin: a recorded scene (ETH/UCY, imported by `crowdsim-bench crowds`) as
// episodes. Episode k plays window k mod count of the split; its people appear and leave as
// recorded (HumanSpec::appear, leave, track: the replay policy follows them), and the robot
// crosses the scene's main flow at a point and in a direction drawn from the episode seed.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "crowd_tracks/tracks.h"
#include "crowdsim/params.h"
#include "crowdsim/world_source.h"

namespace crowdsim::crowds {

/// Immutable after construction, so one instance serves every worker thread.
class CrowdsWorld final : public WorldSource {
 public:
  /// Reads the track file named by params "file"; throws TrackFileError naming file and line.
  explicit CrowdsWorld(const Params& params);
  static std::vector<std::filesystem::path> DataFiles(const Params& params);
  std::string Identity() const override;
  int LayoutCount() const override { return static_cast<int>(windows_.size()); }
  Scenario Make(const ScenarioRequest& request) const override;

 private:
  /// The people of the window starting at `start` (s of the recording), `length` s long.
  std::vector<HumanSpec> PeopleOf(double start, double length,
                                  const ScenarioRequest& request) const;

  std::string scene_;
  std::string split_;
  std::shared_ptr<const StaticMap> map_;
  Rect box_;                     ///< the tracks' bounding box
  Vec2 axis_;                    ///< the main flow
  std::vector<double> windows_;  ///< the split's window starts, s of the recording
  /// Each recorded person's track in recording time, and its v_pref.
  std::vector<std::vector<TrackPoint>> tracks_;
  std::vector<double> v_pref_;
};

/// The plugin's parameters: file (a track file), split (train|test).
ParamSchema Schema();

}  // namespace crowdsim::crowds
