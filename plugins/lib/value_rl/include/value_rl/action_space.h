// CrowdNav's holonomic action space (build_action_space), sized as in the paper: speeds
// exponentially spaced up to v_pref times directions evenly spaced in the world frame.
#pragma once

#include <vector>

#include "crowdsim/action.h"

namespace crowdsim::value_rl {

/// speed_i = (e^((i+1)/S) - 1)/(e - 1) * v_pref, i = 0..S-1 (S = 2: 0.3775 and 1 * v_pref).
std::vector<double> ExponentialSpeeds(int speed_samples, double v_pref);

/// [stop,] then every (direction, speed) pair, direction the outer loop (CrowdNav's order);
/// direction k is at k * 2 pi / rotation_samples in the world frame.
std::vector<Action> BuildActionSpace(int speed_samples, int rotation_samples, bool stop_action,
                                     double v_pref);

}  // namespace crowdsim::value_rl
