// What a policy sees at one step.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "crowdsim/agent_state.h"
#include "crowdsim/export.h"
#include "crowdsim/sim_config.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

class AgentIndex;
class Lookahead;

/// One person seen by a person sensor, in the sensor frame (Observation::frame).
struct CROWDSIM_SDK_API PersonObservation {
  Vec2 position = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
  double radius = 0.3;
  /// A tracking sensor's identity of this detection, kept from step to step while the tracker
  /// follows it; -1 when the sensor does not track.
  int track_id = -1;
};

/// One sensor's output: `people` (person sensors); `ranges`, `angles` (sensor frame, rad),
/// `max_range` (range sensors); else `values`, a fixed-length vector.
struct CROWDSIM_SDK_API SensorReading {
  std::string sensor;  ///< the sensor's plugin name (e.g. "lidar2d", "person")
  std::vector<PersonObservation> people;
  std::vector<double> ranges;  ///< m, max_range when nothing is hit
  std::vector<double> angles;  ///< rad, relative to the frame's x axis
  double max_range = 0.0;
  std::vector<double> values;  ///< other sensors' features, sensor frame where spatial
};

/// Everything one policy receives at one decision.
struct CROWDSIM_SDK_API Observation {
  double time = 0.0;  ///< s since the episode start
  AgentState self;    ///< own state, world frame (heading: see frame)
  /// Sensor frame: x towards the goal, or, for a non-holonomic robot, along its heading.
  Frame frame;
  double linear = 0.0;   ///< non-holonomic robot: the last step's executed linear speed, m/s
  double angular = 0.0;  ///< non-holonomic robot: the last step's executed angular speed, rad/s
  std::vector<SensorReading> readings;  ///< robot only: one per configured sensor, in order
  /// Ground-truth agents this policy may react to, its own index in `self_index` (-1 if absent).
  /// Null for the robot.
  const AgentIndex* agents = nullptr;
  int self_index = -1;
  /// One-step lookahead, given only to robot policies that declare they need it.
  const Lookahead* lookahead = nullptr;

  /// The first reading from the sensor named `name`, or null.
  const SensorReading* Reading(std::string_view name) const {
    for (const auto& r : readings) {
      if (r.sensor == name) return &r;
    }
    return nullptr;
  }
};

}  // namespace crowdsim
