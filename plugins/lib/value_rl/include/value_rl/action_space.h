// CrowdNav's action spaces (build_action_space): speeds exponentially spaced up to v_pref times
// directions evenly spaced in the world frame (holonomic, the paper's) or rotations (unicycle).
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

/// CrowdNav's unicycle actions: [stop,] then every (rotation, speed) pair, rotation the outer loop;
/// rotations linspace(-pi/4, pi/4, R) per step (R = 1: none), as commands held over `time_step`.
std::vector<Action> BuildUnicycleActionSpace(int speed_samples, int rotation_samples,
                                             bool stop_action, double v_pref, double time_step);

}  // namespace crowdsim::value_rl
