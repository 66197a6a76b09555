// A planar lidar: a fan of beams from the robot, each returning the distance to the first
// rectangle (and, optionally, human disc) it meets, capped at max_range.
#pragma once

#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/sensor.h"

namespace crowdsim::lidar2d {

/// Beam angles in the sensor frame (rad): for fov < 360 deg, `beams` evenly spaced from
/// -fov/2 to +fov/2 inclusive (one beam: straight ahead); for 360 deg, k * 2pi / beams.
std::vector<double> BeamAngles(int beams, double fov_deg);

class Lidar2dSensor final : public Sensor {
 public:
  /// Throws std::invalid_argument for values the schema range cannot express (fov, range 0).
  explicit Lidar2dSensor(const Params& params);
  void Sense(const SenseInput& in, SensorReading* out) const override;

  /// Beam angles in the sensor frame (rad), as written to SensorReading::angles.
  const std::vector<double>& angles() const { return angles_; }

 private:
  std::vector<double> angles_;
  std::vector<Vec2> directions_;  // (cos, sin) of each beam angle, rotated by the heading
  /// Range noise and dropouts, drawn from the episode's noise seed, the step and the beam.
  void AddNoise(const SenseInput& in, std::vector<double>* ranges) const;

  double max_range_;
  bool see_humans_;
  double range_noise_;   // m, standard deviation; 0: exact
  double dropout_prob_;  // per beam and step
};

/// The parameters lidar2d declares (beams, fov_deg, max_range, see_humans, range_noise,
/// dropout_prob).
ParamSchema Schema();

}  // namespace crowdsim::lidar2d
