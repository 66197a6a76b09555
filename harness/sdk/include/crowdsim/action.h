// What a policy decides each step.
#pragma once

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"

namespace crowdsim {

/// Holonomic action: the velocity to hold for the next step (world frame, m/s).
struct CROWDSIM_SDK_API Action {
  Vec2 velocity = Vec2::Zero();
};

}  // namespace crowdsim
