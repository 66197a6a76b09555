// The robot's observation as the Dict[str, Tensor] a TorchScript policy's forward takes: the
// layout of the Python package's observations (python/src/observation_arrays.h), as tensors.
//   robot (9,) float64: x, y, vx, vy, goal x, goal y, radius, v_pref, heading (world frame)
//   humans (H, 5) float64: x, y, vx, vy, radius of the people seen, robot frame (x to the goal),
//       padded with zero rows to H = max(`humans`, people seen)
//   humans_mask (H,) bool: true for real rows
//   lidar (beams,) float64: the first range sensor's ranges (only when there is one)
//   route (3,) float64: the route sensor's path distance and waypoint (only when asked for)
//   time () float64: s since the episode start
// The lookahead form (`output: values`) stacks one such observation per candidate action on a
// leading dimension A: robot (A, 9), humans (A, H, 5), humans_mask (A, H), lidar (A, beams),
// route (A, 3), time (A,): what the robot would observe after each action (harness lookahead).
// Includes libtorch: only the policy's .cc files include this header.
#pragma once

#include <ATen/core/Dict.h>
#include <ATen/core/Tensor.h>

#include <span>
#include <string>

#include "crowdsim/lookahead.h"
#include "crowdsim/observation.h"

namespace crowdsim::torchscript {

using ObservationDict = c10::Dict<std::string, at::Tensor>;

/// The observation `obs`, humans padded to at least `humans` rows; `route`: with the route
/// sensor's reading (an error naming the fix when the observation has none).
ObservationDict MakeObservationDict(const Observation& obs, int humans, bool route);

/// A stand-in observation for the load-time check of a module's output: robot at the origin,
/// goal 4 m ahead, v_pref 1, nobody seen, `lidar_beams` ranges of 5 m (none when 0), the route
/// straight to the goal when `route`.
ObservationDict ProbeObservationDict(int humans, int lidar_beams, bool route);

/// The observations after each lookahead outcome, stacked (humans padded to at least `humans`
/// rows; `time` is theirs: the current observation's plus one time step).
ObservationDict MakeLookaheadDict(std::span<const LookaheadOutcome> outcomes, double time,
                                  int humans, bool route);

/// The stand-in of ProbeObservationDict for `actions` candidates (the `values` load-time check).
ObservationDict ProbeLookaheadDict(int actions, int humans, int lidar_beams, bool route);

}  // namespace crowdsim::torchscript
