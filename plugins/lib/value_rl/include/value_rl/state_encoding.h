// The robot-centric state of CrowdNav's rotate() (reference 1.6), built from the harness's
// sensor readings (already in the frame whose x axis points to the goal), plus the lidar.
// Layout of an EncodedState: [self (6)] [route (3), with +route] [lidar (L)] [human rows (n x 7)].
#pragma once

#include <span>
#include <vector>

#include "crowdsim/agent_state.h"
#include "crowdsim/observation.h"
#include "crowdsim/trainable.h"
#include "value_rl/config.h"

namespace crowdsim::value_rl {

inline constexpr int kSelfDim = 6;   ///< dg, v_pref, theta, radius, vx, vy
inline constexpr int kRouteDim = 3;  ///< route distance, waypoint x, waypoint y (frame)
inline constexpr int kHumanDim = 7;  ///< px1, py1, vx1, vy1, radius1, da, radius_sum
/// A person model seeing nobody gets one stand-in human this far behind the robot (m),
/// standing still: "nobody near" in the network's own terms.
inline constexpr double kAbsentHumanDistance = 10.0;

/// Width of the self state the network sees: the 6 values, plus the route's 3 with +route.
inline int SelfInputs(const ValueRlConfig& c) { return kSelfDim + (c.route ? kRouteDim : 0); }

/// Self part: dg, v_pref, theta (`heading`: robot heading less goal direction; else 0), radius,
/// velocity in `frame`.
void AppendSelf(const AgentState& robot, const Frame& frame, bool heading, std::vector<float>* out);

/// One human row; `person` is in the robot frame (the person sensor's output).
void AppendHuman(const PersonObservation& person, double robot_radius, std::vector<float>* out);

/// Builds the state of `robot` at `frame` from its readings. Throws std::runtime_error when
/// a reading the configuration needs is missing or has the wrong number of beams.
EncodedState EncodeState(const ValueRlConfig& config, const AgentState& robot, const Frame& frame,
                         std::span<const SensorReading> readings);

/// Number of human rows in an encoded state.
int HumanRows(const ValueRlConfig& config, const EncodedState& state);

}  // namespace crowdsim::value_rl
