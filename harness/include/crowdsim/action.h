// What a policy decides each step.
#pragma once

#include "crowdsim/geometry.h"

namespace crowdsim {

/// Holonomic action: the velocity to hold for the next step (world frame, m/s).
struct Action {
  Vec2 velocity = Vec2::Zero();
};

}  // namespace crowdsim
