// One episode's initial conditions, produced by a world plugin.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

/// A human's start and its goals, visited in order (one goal: it stays there, CrowdNav).
struct CROWDSIM_SDK_API HumanSpec {
  Vec2 start = Vec2::Zero();
  std::vector<Vec2> goals;  ///< at least one
  double radius = 0.3;
  double v_pref = 1.0;
  bool ignores_robot = false;  ///< a distracted person: the robot is never in its view
  int group = -1;              ///< walking group, -1 alone; a group's members are consecutive
};

/// Everything needed to replay an episode exactly (with the policies).
struct CROWDSIM_SDK_API Scenario {
  std::shared_ptr<const StaticMap> map;
  Vec2 robot_start = Vec2::Zero();
  Vec2 robot_goal = Vec2::Zero();
  /// rad; a non-holonomic robot's start heading. Unset: facing its goal (CrowdNav's pi/2).
  std::optional<double> robot_heading;
  std::vector<HumanSpec> humans;
  std::uint64_t seed = 0;  ///< the episode seed it is made from
  std::string layout;      ///< layout identity (e.g. "rect3_test_017")
};

}  // namespace crowdsim
