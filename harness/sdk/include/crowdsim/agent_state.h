// Kinematic state of one agent (robot or human).
#pragma once

#include <span>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"

namespace crowdsim {

/// Full state of an agent in the world frame (CrowdNav's FullState).
struct CROWDSIM_SDK_API AgentState {
  Vec2 position = Vec2::Zero();  ///< m
  Vec2 velocity = Vec2::Zero();  ///< m/s
  Vec2 goal = Vec2::Zero();      ///< m, current goal
  double radius = 0.3;           ///< m
  double v_pref = 1.0;           ///< preferred speed, m/s
  double heading = 0.0;          ///< rad; holonomic robot: direction to its goal (no state)
  /// A person's walking group (docs/humans.md); -1 alone, and for the robot. Members of a group
  /// are consecutive in the humans' list.
  int group = -1;
};

/// The agent-centric frame of sensors and learned policies: origin at the agent, x along its
/// heading (holonomic robot: towards its goal, as CrowdNav's rotate()).
struct CROWDSIM_SDK_API Frame {
  Vec2 origin = Vec2::Zero();
  double heading = 0.0;
  double cos_h = 1.0;
  double sin_h = 0.0;

  static Frame Make(const Vec2& origin, double heading);
  /// World point to frame coordinates.
  Vec2 PointToLocal(const Vec2& p) const {
    const Vec2 d = p - origin;
    return Vec2(d.x() * cos_h + d.y() * sin_h, d.y() * cos_h - d.x() * sin_h);
  }
  /// World vector (velocity) to frame coordinates.
  Vec2 VectorToLocal(const Vec2& v) const {
    return Vec2(v.x() * cos_h + v.y() * sin_h, v.y() * cos_h - v.x() * sin_h);
  }
  /// Frame vector to world coordinates.
  Vec2 VectorToWorld(const Vec2& v) const {
    return Vec2(v.x() * cos_h - v.y() * sin_h, v.x() * sin_h + v.y() * cos_h);
  }
};

/// Heading of a holonomic robot: the direction to its goal (0 when on the goal).
CROWDSIM_SDK_API double HeadingToGoal(const AgentState& s);

/// Within this distance (m) of its goal a group member walks alone: members' goals lie apart, so
/// keeping together there would hold them off their goals (docs/humans.md).
inline constexpr double kGroupReleaseDist = 1.0;

/// Fills `out` with the positions of the other members of agents[self]'s walking group (they are
/// consecutive in `agents`); empty when it walks alone, or is within kGroupReleaseDist of its goal.
CROWDSIM_SDK_API void GroupMates(std::span<const AgentState> agents, int self,
                                 std::vector<Vec2>* out);

}  // namespace crowdsim
