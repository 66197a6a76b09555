// The people detector of CrowdNav: every human's position, velocity and radius in the
// robot's frame, optionally limited to a detection range.
#pragma once

#include "crowdsim/params.h"
#include "crowdsim/sensor.h"

namespace crowdsim::person {

class PersonSensor final : public Sensor {
 public:
  explicit PersonSensor(const Params& params);
  void Sense(const SenseInput& in, SensorReading* out) const override;

 private:
  double max_range_;  // m; 0 = unlimited
};

/// The parameters person declares (max_range).
ParamSchema Schema();

}  // namespace crowdsim::person
