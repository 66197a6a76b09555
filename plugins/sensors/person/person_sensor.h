// The people detector of CrowdNav: every human's position, velocity and radius in the
// robot's frame, optionally limited to a detection range, a field of view and what the robot
// can see past the map's rectangles and other people.
#pragma once

#include <cstddef>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/sensor.h"

namespace crowdsim::person {

/// What hides a person from the robot.
enum class Occlusion { kNone, kObstacles, kObstaclesAndPeople };

class PersonSensor final : public Sensor {
 public:
  explicit PersonSensor(const Params& params);
  void Sense(const SenseInput& in, SensorReading* out) const override;

 private:
  /// Whether human `i` lies within max_range and the field of view.
  bool InRangeAndView(const SenseInput& in, std::size_t i) const;
  /// Keeps the `candidates` a sight line from the robot's centre reaches (the centre or either
  /// edge of the disc), in order.
  void Unoccluded(const SenseInput& in, std::vector<std::size_t>* candidates) const;
  /// Whether another person stands on the sight line to `end` (on human `target`), `length` m.
  bool PersonInTheWay(const SenseInput& in, const Vec2& end, double length,
                      std::size_t target) const;

  double max_range_;     // m; 0 = unlimited
  double half_fov_cos_;  // cos of half the field of view; -1 = all around
  Occlusion occlusion_;
  double detection_prob_;  // per step and human in view
  double position_noise_;  // m, per axis
};

/// The parameters person declares (max_range, fov_deg, occlusion, detection_prob,
/// position_noise).
ParamSchema Schema();

}  // namespace crowdsim::person
