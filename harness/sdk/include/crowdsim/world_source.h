// World plugin interface: produces the scenario of every episode.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/scenario.h"
#include "crowdsim/sim_config.h"

namespace crowdsim {

enum class HumanGoalMode { kStay, kNewGoal };

/// One person's own attributes, drawn per episode by the harness (suite `humans: {radius,
/// v_pref, distracted}`, docs/humans.md).
struct CROWDSIM_SDK_API HumanAttributes {
  double radius = 0.3;         ///< m
  double v_pref = 1.0;         ///< m/s
  bool ignores_robot = false;  ///< distracted: never sees the robot, even a visible one
  /// Walking group, -1 alone. Members are consecutive, the first one leads: worlds place the
  /// others near it, start and goal.
  int group = -1;
};

/// What the harness asks a world for.
struct CROWDSIM_SDK_API ScenarioRequest {
  std::uint64_t seed = 0;  ///< episode seed (DeriveSeed)
  std::int64_t episode_index = 0;
  int num_humans = 5;
  HumanGoalMode goal_mode = HumanGoalMode::kStay;
  SimConfig sim;  ///< radii and speeds
  /// One per human when the people vary; empty: everybody has sim's radius and v_pref.
  std::vector<HumanAttributes> humans;
};

/// The frozen layout an episode plays among `count` (> 0): its index mod count, from 0.
inline std::int64_t FrozenLayoutIndex(const ScenarioRequest& request, std::int64_t count) {
  return ((request.episode_index % count) + count) % count;
}

/// Human i's attributes: request.humans[i], or sim's radius and v_pref when none are drawn.
CROWDSIM_SDK_API HumanAttributes HumanAttributesOf(const ScenarioRequest& request, int i);
/// The largest radius among the requested humans: the clearance of free space for any of them.
CROWDSIM_SDK_API double LargestHumanRadius(const ScenarioRequest& request);
/// Human i's group leader (the group's first member), or -1 when i walks alone or leads.
CROWDSIM_SDK_API int GroupLeaderOf(const ScenarioRequest& request, int i);
/// Copies human i's attributes (radius, v_pref, ignores_robot, group) onto `spec`.
CROWDSIM_SDK_API void ApplyHumanAttributes(const ScenarioRequest& request, int i, HumanSpec* spec);

class CROWDSIM_SDK_API WorldSource {
 public:
  virtual ~WorldSource();
  /// Stable identity used in seeds and manifests (e.g. "random_rect:obstacles=1:split=test").
  virtual std::string Identity() const = 0;
  /// Number of distinct frozen layouts (0 if generated on the fly).
  virtual int LayoutCount() const { return 0; }
  /// The scenario of one episode; the same request always gives the same scenario.
  virtual Scenario Make(const ScenarioRequest& request) const = 0;
};

}  // namespace crowdsim
