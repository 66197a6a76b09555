// What a policy decides each step.
#pragma once

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"

namespace crowdsim {

/// A decision: a world-frame velocity (holonomic form) or, for a non-holonomic robot
/// (crowdsim/kinematics.h), a (linear, angular) command.
struct CROWDSIM_SDK_API Action {
  Vec2 velocity = Vec2::Zero();  ///< m/s, world frame: the velocity to hold for the next step
  bool command = false;          ///< true: linear and angular hold instead of velocity
  double linear = 0.0;           ///< m/s along the robot's heading
  double angular = 0.0;          ///< rad/s, counter-clockwise

  Action() = default;
  explicit Action(const Vec2& v) : velocity(v) {}

  static Action Command(double linear, double angular) {
    Action a;
    a.command = true;
    a.linear = linear;
    a.angular = angular;
    return a;
  }
};

}  // namespace crowdsim
