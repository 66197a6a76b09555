// The robot's sensor readings at one recorded step, re-sensed from the trajectory (Figure 3).
#pragma once

#include <span>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/scenario.h"

namespace crowdsim::render {

/// What the robot's sensors read at one trajectory frame.
struct SensorSnapshot {
  int step = 0;                    ///< trajectory frame index
  double time = 0.0;               ///< s
  AgentState robot;                ///< with the heading the episode senses with (goal's or body's)
  Frame frame;                     ///< the sensor frame the readings are relative to
  std::vector<AgentState> humans;  ///< the people present
  std::vector<int> human_ids;      ///< their scenario indices; empty: humans[i] is human i
  std::vector<SensorReading> readings;  ///< one per mounted sensor, in order
  /// Per reading: the person sensor's field of view in degrees (360: all around; filled from the
  /// row's parameters by the caller), and its range (m, 0: unlimited).
  std::vector<double> fov_deg;
  std::vector<double> range;
};

/// Re-senses frame `step` of a recorded episode with `sensors` (a fresh CollisionWorld of the
/// scenario's map; the episode's own sensing order and frame). Throws std::out_of_range naming
/// the valid steps when `step` is outside the trajectory.
SensorSnapshot TakeSensorSnapshot(const Scenario& scenario, const EpisodeResult& result, int step,
                                  std::span<const MountedSensor> sensors);

}  // namespace crowdsim::render
